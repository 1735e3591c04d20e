#include "hilight/voxel_labels.hpp"

#include <algorithm>

namespace hilight {

std::vector<VoxelPart> label_parts(const glm::ivec3& dims, const std::function<bool(size_t)>& in, std::vector<int>& labels,
                                   int unlabelled, int first_label) {
  const auto index = [&](const glm::ivec3& v) { return (size_t(v.z) * dims.y + size_t(v.y)) * dims.x + size_t(v.x); };
  static const glm::ivec3 kFaces[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
  std::vector<VoxelPart> parts;
  std::vector<size_t> stack;
  for (size_t start = 0; start < labels.size(); ++start) {
    if (labels[start] != unlabelled || !in(start)) continue;
    const int label = first_label + int(parts.size());
    VoxelPart part{0, start};
    labels[start] = label;
    stack.push_back(start);
    while (!stack.empty()) {
      const size_t i = stack.back();
      stack.pop_back();
      ++part.voxels;
      const glm::ivec3 v(int(i % size_t(dims.x)), int(i / size_t(dims.x) % size_t(dims.y)), int(i / (size_t(dims.x) * dims.y)));
      for (const auto& f : kFaces) {
        const glm::ivec3 q = v + f;
        if (q.x < 0 || q.y < 0 || q.z < 0 || q.x >= dims.x || q.y >= dims.y || q.z >= dims.z) continue;
        if (const size_t j = index(q); labels[j] == unlabelled && in(j)) labels[j] = label, stack.push_back(j);
      }
    }
    parts.push_back(part);
  }
  return parts;
}

int label_near(const std::vector<int>& labels, const glm::ivec3& dims, const Bounds& box, float voxel, const Vec3& p, int none) {
  if (labels.empty() || !box.contains(p)) return none;
  const auto index = [&](const glm::ivec3& v) { return (size_t(v.z) * dims.y + size_t(v.y)) * dims.x + size_t(v.x); };
  glm::ivec3 v;
  for (int k = 0; k < 3; ++k) v[k] = std::clamp(int((p[k] - box.lo[k]) / voxel), 0, dims[k] - 1);
  if (const int label = labels[index(v)]; label != none) return label;
  int best = none;
  float best_d = 1e30f;
  for (int dz = -2; dz <= 2; ++dz)
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx) {
        const glm::ivec3 q = v + glm::ivec3(dx, dy, dz);
        if (q.x < 0 || q.y < 0 || q.z < 0 || q.x >= dims.x || q.y >= dims.y || q.z >= dims.z) continue;
        const int label = labels[index(q)];
        const float d = glm::length(box.lo + (Vec3(q) + 0.5f) * voxel - p);
        if (label != none && d < best_d) best_d = d, best = label;
      }
  return best;
}

} // namespace hilight
