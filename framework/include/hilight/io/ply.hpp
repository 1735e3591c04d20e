#pragma once
/// PLY: the illuminated-scene / target format.
/// Written as binary little-endian, vertex `float x y z nx ny nz red green blue`
/// (linear, unclamped) plus `face` with `list uchar int vertex_indices`.
#include "hilight/math.hpp"

#include <filesystem>
#include <vector>

namespace hilight {

struct Scene;

void write_illuminated_ply(const std::filesystem::path& path, const Scene& scene, const std::vector<Rgb>& radiance);

} // namespace hilight
