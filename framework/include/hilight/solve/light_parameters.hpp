#pragma once
/// Lights as flat parameter vectors for the simplex, scaled so one unit is a
/// sensible step in every coordinate: positions in scene diagonals, spot
/// directions as two angles (radians), cutoff and soft edge in radians.
#include "hilight/lighting.hpp"

#include <vector>

namespace hilight {

/// Appends `light`'s geometry (position; for spots also direction, cutoff, soft edge).
void append_geometry(const Light& light, float scale, std::vector<double>& params, std::vector<double>& steps);
/// Reads geometry back from params[offset...]; returns the new offset.
size_t read_geometry(Light& light, float scale, const std::vector<double>& params, size_t offset);

} // namespace hilight
