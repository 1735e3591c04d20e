#pragma once
/// A lights file by its extension: a hilight lights JSON (intensities in
/// `units`: W/sr, or candela when photometric), or a glTF (.gltf/.glb) whose
/// KHR_lights_punctual lights are read (always candela, io/gltf.hpp).
/// Returned in hilight's units (W/sr).
#include "hilight/lighting.hpp"
#include "hilight/scene.hpp"
#include "hilight/units.hpp"

#include <filesystem>

namespace hilight {

/// With `frame`, the file's world positions are moved into that scene's
/// frame in double precision (scene_origin.hpp).
Lighting read_lights_file(const std::filesystem::path& path, Units units = Units::Radiometric, const SceneFrame* frame = nullptr);

/// Writes `lights` (hilight's units) as a lights JSON in `units`.
void write_lights_file(const std::filesystem::path& path, const Lighting& lights, Units units = Units::Radiometric,
                       const std::string& length_unit = "m");
/// The same for lights in `frame`'s scene: written in the world's
/// coordinates and the scene file's unit, moved out in double precision.
void write_lights_file(const std::filesystem::path& path, const Lighting& lights, Units units, const SceneFrame& frame);

} // namespace hilight
