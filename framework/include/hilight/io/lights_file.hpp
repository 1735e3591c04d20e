#pragma once
/// A lights file by its extension: a hilight lights JSON, or a glTF
/// (.gltf/.glb) whose KHR_lights_punctual lights are read (always candela,
/// io/gltf.hpp). Returned in hilight's units (W/sr).
///
/// A lights JSON's intensities are in the unit it states ("intensity_unit":
/// "W/sr" or "cd"), whatever `units` says: the file knows what it holds.
/// `units` (--units) is the unit of a file that states none (files written
/// before the field: W/sr, or candela when photometric), and of what is
/// written, which always states it.
#include "hilight/lighting.hpp"
#include "hilight/scene.hpp"
#include "hilight/units.hpp"

#include <filesystem>

namespace hilight {

/// With `frame`, the file's world positions are moved into that scene's
/// frame in double precision (scene_origin.hpp).
Lighting read_lights_file(const std::filesystem::path& path, Units units = Units::Radiometric, const SceneFrame* frame = nullptr);

/// Writes `lights` (hilight's units) as a lights JSON in `units`, stated in it.
void write_lights_file(const std::filesystem::path& path, const Lighting& lights, Units units = Units::Radiometric,
                       const std::string& length_unit = "m");
/// The same for lights in `frame`'s scene: written in the world's
/// coordinates and the scene file's unit, moved out in double precision.
void write_lights_file(const std::filesystem::path& path, const Lighting& lights, Units units, const SceneFrame& frame);

} // namespace hilight
