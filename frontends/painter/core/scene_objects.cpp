#include "core/scene_objects.hpp"

#include <cmath>
#include <numeric>
#include <unordered_map>

namespace hilight::painter {

namespace {

/// Union-find over triangles.
class DisjointSets {
public:
  explicit DisjointSets(size_t n) : m_parent(n) { std::iota(m_parent.begin(), m_parent.end(), uint32_t(0)); }
  uint32_t find(uint32_t x) {
    while (m_parent[x] != x) x = m_parent[x] = m_parent[m_parent[x]];
    return x;
  }
  void unite(uint32_t a, uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) m_parent[std::max(a, b)] = std::min(a, b);
  }

private:
  std::vector<uint32_t> m_parent;
};

struct CellKey {
  int64_t x, y, z;
  uint32_t material;
  bool operator==(const CellKey&) const = default;
};
struct CellHash {
  size_t operator()(const CellKey& k) const {
    return size_t(k.x * 73856093) ^ size_t(k.y * 19349663) ^ size_t(k.z * 83492791) ^ size_t(k.material * 2654435761u);
  }
};

} // namespace

SceneObjects::SceneObjects(const Scene& scene) {
  const size_t nt = scene.triangles.size();
  DisjointSets sets(nt);
  // Weld vertices by position (to a millionth of the diagonal), per material.
  const double cell = std::max(1e-6 * double(scene.diagonal()), 1e-12);
  std::unordered_map<CellKey, uint32_t, CellHash> first_triangle;
  first_triangle.reserve(nt * 3);
  for (uint32_t t = 0; t < nt; ++t)
    for (uint32_t v : scene.triangles[t]) {
      const Vec3& p = scene.positions[v];
      CellKey key{int64_t(std::llround(p.x / cell)), int64_t(std::llround(p.y / cell)), int64_t(std::llround(p.z / cell)),
                  scene.triangle_material[t]};
      auto [it, inserted] = first_triangle.emplace(key, t);
      if (!inserted) sets.unite(it->second, t);
    }

  m_triangle_object.assign(nt, 0);
  std::unordered_map<uint32_t, uint32_t> object_of_root;
  for (uint32_t t = 0; t < nt; ++t) {
    auto [it, inserted] = object_of_root.emplace(sets.find(t), uint32_t(object_of_root.size()));
    if (inserted) {
      m_bounds.emplace_back();
      m_names.push_back(scene.materials[scene.triangle_material[t]].name);
    }
    m_triangle_object[t] = it->second;
    for (uint32_t v : scene.triangles[t]) m_bounds[it->second].extend(scene.positions[v]);
  }
  for (const Bounds& b : m_bounds) m_centres.push_back(b.center());

  m_vertex_object.assign(scene.positions.size(), 0);
  std::vector<bool> seen(scene.positions.size(), false);
  for (uint32_t t = 0; t < nt; ++t)
    for (uint32_t v : scene.triangles[t])
      if (!seen[v]) {
        seen[v] = true;
        m_vertex_object[v] = m_triangle_object[t];
      }
}

std::vector<uint32_t> SceneObjects::triangles(uint32_t object) const {
  std::vector<uint32_t> result;
  for (uint32_t t = 0; t < m_triangle_object.size(); ++t)
    if (m_triangle_object[t] == object) result.push_back(t);
  return result;
}

} // namespace hilight::painter
