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
std::string lights_to_json(const Lighting& lights);
void write_lights_json(const std::filesystem::path& path, const Lighting& lights);

} // namespace hilight
