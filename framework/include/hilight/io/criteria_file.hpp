#pragma once
/// Illuminance criteria files (`hilight target workplane` writes them,
/// `hilight solve --target C.json` reads them): JSON, documented in
/// docs/solve.md ("Illuminance criteria"):
///   {"illuminance_criteria": 1, "length_unit": "m", "grids": [
///     {"name": "workplane", "kind": "workplane", "lux": 500, "u0": 0.6,
///      "spacing": 1.2, "points": [[x, y, z], ...], "normals": [[0, 1, 0], ...]}]}
/// Normals may be left out: up.
#include "hilight/illuminance_criteria.hpp"

#include <filesystem>

namespace hilight {

/// InputError naming the file and the field for anything wrong.
IlluminanceCriteria read_criteria(const std::filesystem::path& path);
IlluminanceCriteria parse_criteria(const std::string& text, const std::string& source);
/// Written atomically.
void write_criteria(const std::filesystem::path& path, const IlluminanceCriteria& criteria);

} // namespace hilight
