#pragma once
/// The lights file: {"lights":[{"type":"point","position":[x,y,z],"intensity":[r,g,b]},
/// {"type":"spot","position":[..],"direction":[..],"cutoff_deg":c,"falloff_deg":f,"intensity":[..]}]}
#include "hilight/lighting.hpp"

#include <filesystem>
#include <string>

namespace hilight {

/// Reads and validates; InputError names the file, the light index and the problem.
Lighting read_lights_json(const std::filesystem::path& path);
Lighting parse_lights_json(const std::string& text, const std::string& source_name);
/// `length_unit`: the unit positions are in (the scene file's), stated in the file.
std::string lights_to_json(const Lighting& lights, const std::string& length_unit = "m");
void write_lights_json(const std::filesystem::path& path, const Lighting& lights, const std::string& length_unit = "m");

} // namespace hilight
