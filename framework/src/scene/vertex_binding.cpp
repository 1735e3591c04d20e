#include "hilight/vertex_binding.hpp"

#include "hilight/point_grid.hpp"

#include <algorithm>
#include <cmath>
#include <tbb/parallel_for.h>
#include <unordered_map>

namespace hilight {

namespace {

/// Vertices on a uniform hash grid whose cells are the match tolerance wide.
class VertexGrid {
public:
  VertexGrid(const Scene& scene, float cell) : m_scene(scene), m_grid(cell) {
    for (uint32_t v = 0; v < scene.positions.size(); ++v) m_grid.add(scene.positions[v], v);
  }

  /// Vertices within `tolerance` of p, nearest first, then in vertex order.
  std::vector<uint32_t> near(const Vec3& p, float tolerance) const {
    std::vector<std::pair<float, uint32_t>> found;
    m_grid.for_each_near(p, [&](uint32_t v) {
      const float d = glm::length(m_scene.positions[v] - p);
      if (d <= tolerance) found.emplace_back(d, v);
    });
    std::sort(found.begin(), found.end());
    // Vertices at the same place (split at a crease) count as equally near.
    std::vector<uint32_t> out;
    for (const auto& [d, v] : found)
      if (d <= found.front().first + 0.5f * tolerance) out.push_back(v);
    std::sort(out.begin(), out.end());
    return out;
  }

private:
  const Scene& m_scene;
  PointGrid m_grid;
};

/// The file starts with the scene's vertices in order (a render; a refined
/// render appends its new vertices after them).
bool starts_in_order(const Scene& scene, const std::vector<Vec3>& positions, float tolerance) {
  if (positions.size() < scene.positions.size()) return false;
  for (size_t i = 0; i < scene.positions.size(); ++i)
    if (!(glm::length(positions[i] - scene.positions[i]) <= tolerance)) return false;
  return true;
}

} // namespace

std::vector<int32_t> match_vertices(const Scene& scene, const std::vector<Vec3>& positions, const std::vector<Vec3>& normals) {
  const size_t n = positions.size();
  const float tolerance = std::max(kVertexMatchTolerance * scene.diagonal(), 1e-30f);
  std::vector<int32_t> vertex(n, -1);
  // A target written by `render` (or kept in vertex order by another tool):
  // point i is vertex i. This also settles split vertices without normals.
  // A refined render's vertices after those are new points on the surface
  // (matched below: none is on a scene vertex but by coincidence).
  size_t first = 0;
  if (starts_in_order(scene, positions, tolerance)) {
    for (; first < scene.positions.size(); ++first) vertex[first] = int32_t(first);
    if (first == n) return vertex;
  }
  VertexGrid grid(scene, tolerance);
  std::vector<std::vector<uint32_t>> candidates(n);
  tbb::parallel_for(first, n, [&](size_t i) { candidates[i] = grid.near(positions[i], tolerance); });
  // Without a normal, points at one place take that place's vertices in
  // turn, in file order (the k-th point gets the k-th vertex).
  std::unordered_map<uint32_t, size_t> taken;  // first candidate -> points bound so far
  for (size_t i = first; i < n; ++i) {
    const auto& c = candidates[i];
    if (c.empty()) continue;
    const Vec3 normal = normals.empty() ? Vec3(0.f) : normals[i];
    if (glm::dot(normal, normal) > 0.f) {
      uint32_t best = c.front();
      float agreement = -2.f;
      for (uint32_t v : c) {
        float a = glm::dot(glm::normalize(normal), scene.normals[v]);
        if (a > agreement + 1e-6f) agreement = a, best = v;
      }
      // A point of another surface that only passes through a vertex here (a
      // refined render's vertex on a table leg's edge, where the table top
      // has a corner) is not that vertex: it binds to its own surface.
      if (agreement >= 0.99f) vertex[i] = int32_t(best);
    } else {
      vertex[i] = int32_t(c[taken[c.front()]++ % c.size()]);
    }
  }
  return vertex;
}

} // namespace hilight
