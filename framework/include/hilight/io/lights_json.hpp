#pragma once
/// The lights file: {"length_unit":"m","intensity_unit":"W/sr","lights":[{"type":"point","position":[x,y,z],"intensity":[r,g,b]},
/// {"type":"spot","position":[..],"direction":[..],"cutoff_deg":c,"falloff_deg":f,"intensity":[..]}]}
/// "intensity_unit" ("W/sr" or "cd") says what every "intensity" is in; a
/// file without it leaves that to the reader (io/lights_file.hpp).
#include "hilight/lighting.hpp"
#include "hilight/scene.hpp"

#include <filesystem>
#include <string>

namespace hilight {

/// Reads and validates; InputError names the file, the light index and the problem.
/// With `frame`, the file's world positions (and sizes, in its unit) are moved
/// into that scene's frame in double precision (scene_origin.hpp); without,
/// they are taken as they are.
/// Intensities are returned as the file has them; `intensity_unit` (when
/// given) gets the unit the file states, "W/sr" or "cd", or "" when it
/// states none (any other value is an InputError).
Lighting read_lights_json(const std::filesystem::path& path, const SceneFrame* frame = nullptr, std::string* intensity_unit = nullptr);
Lighting parse_lights_json(const std::string& text, const std::string& source_name, const SceneFrame* frame = nullptr,
                           std::string* intensity_unit = nullptr);
/// `length_unit`: the unit positions are in (the scene file's), stated in the
/// file. With `frame`, `lights` are in that scene's frame and are written in
/// the world's, moved out in double precision. `intensity_unit`: what the
/// intensities of `lights` are in ("W/sr", hilight's own, or "cd"), stated
/// in the file.
std::string lights_to_json(const Lighting& lights, const std::string& length_unit = "m", const SceneFrame* frame = nullptr,
                           const std::string& intensity_unit = "W/sr");
void write_lights_json(const std::filesystem::path& path, const Lighting& lights, const std::string& length_unit = "m",
                       const SceneFrame* frame = nullptr, const std::string& intensity_unit = "W/sr");

} // namespace hilight
