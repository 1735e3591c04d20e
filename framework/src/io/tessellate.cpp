#include "hilight/io/tessellate.hpp"

#include <unordered_map>

namespace hilight {

namespace {

struct Refiner {
  Scene& scene;
  float max_edge_sq;
  std::unordered_map<uint64_t, uint32_t> midpoints;  // (min,max) vertex pair -> midpoint vertex
  std::vector<std::array<uint32_t, 3>> out_tris;
  std::vector<uint32_t> out_mat;

  uint32_t midpoint(uint32_t a, uint32_t b) {
    uint64_t key = (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
    auto [it, inserted] = midpoints.try_emplace(key, uint32_t(scene.positions.size()));
    if (inserted) {
      // Copy before push_back: the references would dangle on reallocation.
      Vec3 p = 0.5f * (scene.positions[a] + scene.positions[b]);
      Vec3 n = scene.normals[a] + scene.normals[b];
      float len = glm::length(n);
      scene.positions.push_back(p);
      scene.normals.push_back(len > 1e-12f ? n / len : scene.normals[a]);
    }
    return it->second;
  }

  float edge_sq(uint32_t a, uint32_t b) const {
    Vec3 d = scene.positions[a] - scene.positions[b];
    return glm::dot(d, d);
  }

  // Depth-first: split the longest edge (first of equals, for determinism).
  // "Equal" and "not longer than the limit" hold within kTie: lengths that
  // are equal or on the limit in exact arithmetic (a square's sides, a wall
  // of 16 limits) round differently once the scene is turned or scaled, and
  // must still be cut the same way (issue 19).
  static constexpr float kTie = 1e-5f;  // of a squared length
  void refine(std::array<uint32_t, 3> t, uint32_t material) {
    float e[3] = {edge_sq(t[0], t[1]), edge_sq(t[1], t[2]), edge_sq(t[2], t[0])};
    int k = 0;
    if (e[1] > e[k] * (1.f + kTie)) k = 1;
    if (e[2] > e[k] * (1.f + kTie)) k = 2;
    if (e[k] <= max_edge_sq * (1.f + kTie)) {
      out_tris.push_back(t);
      out_mat.push_back(material);
      return;
    }
    uint32_t a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
    uint32_t m = midpoint(a, b);
    refine({a, m, c}, material);  // winding preserved in both halves
    refine({m, b, c}, material);
  }
};

} // namespace

void tessellate(Scene& scene, float max_edge) {
  if (!(max_edge > 0.f)) return;
  Refiner r{scene, max_edge * max_edge, {}, {}, {}};
  r.out_tris.reserve(scene.triangles.size());
  for (size_t t = 0; t < scene.triangles.size(); ++t) r.refine(scene.triangles[t], scene.triangle_material[t]);
  scene.triangles = std::move(r.out_tris);
  scene.triangle_material = std::move(r.out_mat);
}

} // namespace hilight
