#pragma once
/// The target PLY the painter writes: binary little-endian vertex element
/// `float x y z nx ny nz red green blue weight` (linear colours), no faces —
/// exactly what `hilight solve --target` reads (docs/solve.md).
#include "hilight/math.hpp"
#include "hilight/scene.hpp"

#include <filesystem>
#include <vector>

namespace hilight::painter {

struct TargetPoints {
  std::vector<Vec3> positions, normals;
  std::vector<Rgb> values;
  std::vector<float> weights;
};

/// Written through write_atomically: the file appears whole or not at all.
/// Positions are local to the scene; `frame` puts them back in the file's
/// coordinates (doubles when it moved or scaled them: scene_origin.hpp).
void write_target_ply(const std::filesystem::path& path, const TargetPoints& points, const SceneFrame& frame = {});

} // namespace hilight::painter
