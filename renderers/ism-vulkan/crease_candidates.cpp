#include "crease_candidates.hpp"

#include <algorithm>
#include <cmath>
#include <tbb/parallel_for.h>
#include <unordered_map>

namespace hilight::ism {

namespace {

/// Squared distance from p to triangle (a, b, c) (Ericson, Real-Time Collision Detection, 5.1.5).
float distance2_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  Vec3 q;
  if (d1 <= 0 && d2 <= 0) q = a;
  else {
    const Vec3 bp = p - b;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    const Vec3 cp = p - c;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    const float vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    if (d3 >= 0 && d4 <= d3) q = b;
    else if (d6 >= 0 && d5 <= d6) q = c;
    else if (vc <= 0 && d1 >= 0 && d3 <= 0) q = a + ab * (d1 / (d1 - d3));
    else if (vb <= 0 && d2 >= 0 && d6 <= 0) q = a + ac * (d2 / (d2 - d6));
    else if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) q = b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    else {
      const float denom = 1.f / (va + vb + vc);
      q = a + ab * (vb * denom) + ac * (vc * denom);
    }
  }
  const Vec3 d = p - q;
  return glm::dot(d, d);
}

} // namespace

std::vector<uint32_t> crease_candidates(const Scene& scene, const SurfacePoints& points, float reach) {
  // A hash grid of triangle bounding boxes; cells as large as a typical triangle.
  const float cell = std::max(scene.max_edge > 0 ? scene.max_edge : scene.diagonal() / 40.f, 4.f * reach);
  auto cell_of = [&](const Vec3& p) { return glm::ivec3(glm::floor((p - scene.bounds.lo) / cell)); };
  auto key = [](const glm::ivec3& c) { return (uint64_t(uint32_t(c.x)) * 73856093u) ^ (uint64_t(uint32_t(c.y)) * 19349663u) ^
                                              (uint64_t(uint32_t(c.z)) * 83492791u); };
  std::unordered_map<uint64_t, std::vector<uint32_t>> grid;
  for (uint32_t t = 0; t < scene.triangles.size(); ++t) {
    const auto& tri = scene.triangles[t];
    Vec3 lo = glm::min(glm::min(scene.positions[tri[0]], scene.positions[tri[1]]), scene.positions[tri[2]]) - Vec3(reach);
    Vec3 hi = glm::max(glm::max(scene.positions[tri[0]], scene.positions[tri[1]]), scene.positions[tri[2]]) + Vec3(reach);
    const glm::ivec3 a = cell_of(lo), b = cell_of(hi);
    for (int x = a.x; x <= b.x; ++x)
      for (int y = a.y; y <= b.y; ++y)
        for (int z = a.z; z <= b.z; ++z) grid[key({x, y, z})].push_back(t);
  }
  std::vector<uint32_t> out(points.size() * kCreaseCandidates, ~0u);
  tbb::parallel_for(size_t(0), points.size(), [&](size_t i) {
    const Vec3& p = points.positions[i];
    const Vec3& n = points.normals[i];
    auto found = grid.find(key(cell_of(p)));
    if (found == grid.end()) return;
    std::vector<std::pair<float, uint32_t>> near;
    for (uint32_t t : found->second) {
      const auto& tri = scene.triangles[t];
      const Vec3 &a = scene.positions[tri[0]], &b = scene.positions[tri[1]], &c = scene.positions[tri[2]];
      // Its own plane (or a coplanar neighbour) cannot shadow the point.
      const Vec3 fn = scene.face_normal(t);
      if (std::abs(glm::dot(fn, n)) > 0.999f && std::abs(glm::dot(fn, p - a)) <= reach) continue;
      const float d2 = distance2_to_triangle(p, a, b, c);
      if (d2 <= reach * reach) near.emplace_back(d2, t);  // p looks in one cell only: no duplicates
    }
    const size_t keep = std::min<size_t>(near.size(), kCreaseCandidates);
    std::partial_sort(near.begin(), near.begin() + keep, near.end());
    for (size_t k = 0; k < keep; ++k) out[i * kCreaseCandidates + k] = near[k].second;
  });
  return out;
}

} // namespace hilight::ism
