#pragma once
/// The lights file: {"lights":[{"type":"point","position":[x,y,z],"intensity":[r,g,b]},
/// {"type":"spot","position":[..],"direction":[..],"cutoff_deg":c,"falloff_deg":f,"intensity":[..]}]}
#include "hilight/lighting.hpp"
#include "hilight/scene.hpp"

#include <filesystem>
#include <string>

namespace hilight {

/// Reads and validates; InputError names the file, the light index and the problem.
/// With `frame`, the file's world positions (and sizes, in its unit) are moved
/// into that scene's frame in double precision (scene_origin.hpp); without,
/// they are taken as they are.
Lighting read_lights_json(const std::filesystem::path& path, const SceneFrame* frame = nullptr);
Lighting parse_lights_json(const std::string& text, const std::string& source_name, const SceneFrame* frame = nullptr);
/// `length_unit`: the unit positions are in (the scene file's), stated in the
/// file. With `frame`, `lights` are in that scene's frame and are written in
/// the world's, moved out in double precision.
std::string lights_to_json(const Lighting& lights, const std::string& length_unit = "m", const SceneFrame* frame = nullptr);
void write_lights_json(const std::filesystem::path& path, const Lighting& lights, const std::string& length_unit = "m",
                       const SceneFrame* frame = nullptr);

} // namespace hilight
