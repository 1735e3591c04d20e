#include "scene_buffers.hpp"

#include "hilight/error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <unordered_map>

namespace hilight::ism {

/// For each triangle, the triangle across each of its edges (~0u: none; on
/// an edge shared by more than two, the first other one). Edges are matched
/// by position, not vertex index: the faces of a box have vertices of their
/// own, and a ray grazing a box's edge must find the face across it.
std::vector<uint32_t> edge_neighbours(const Scene& scene) {
  struct PositionHash {
    size_t operator()(const Vec3& p) const {
      return std::hash<float>()(p.x) ^ (std::hash<float>()(p.y) * 31) ^ (std::hash<float>()(p.z) * 131);
    }
  };
  std::unordered_map<Vec3, uint32_t, PositionHash> canonical;
  std::vector<uint32_t> id(scene.positions.size());
  for (size_t v = 0; v < scene.positions.size(); ++v) id[v] = canonical.try_emplace(scene.positions[v], uint32_t(v)).first->second;
  std::unordered_map<uint64_t, std::array<uint32_t, 2>> edges;
  auto key = [&](uint32_t a, uint32_t b) {
    a = id[a];
    b = id[b];
    return a < b ? (uint64_t(a) << 32 | b) : (uint64_t(b) << 32 | a);
  };
  for (uint32_t t = 0; t < scene.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      auto [it, fresh] = edges.try_emplace(key(scene.triangles[t][k], scene.triangles[t][(k + 1) % 3]), std::array<uint32_t, 2>{t, ~0u});
      if (!fresh && it->second[1] == ~0u) it->second[1] = t;
    }
  std::vector<uint32_t> out(3 * scene.triangles.size(), ~0u);
  for (uint32_t t = 0; t < scene.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const auto& pair = edges.at(key(scene.triangles[t][k], scene.triangles[t][(k + 1) % 3]));
      out[3 * t + k] = pair[0] == t ? pair[1] : pair[0];
    }
  return out;
}

SceneBuffers::SceneBuffers(VulkanContext& ctx, const Scene& s, uint32_t pool_size, uint64_t seed) {
  const size_t triangles = s.triangles.size();
  if (triangles == 0) throw InputError(s.source, "the scene has no triangles");
  if (triangles > (size_t(1) << 30) / 3) throw InputError(s.source, "too many triangles for the ism-vulkan renderer");
  const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  vertices = Buffer(ctx, s.positions.size() * 3 * sizeof(float), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, true, "the scene's vertices");
  indices = Buffer(ctx, triangles * 3 * sizeof(uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT, true, "the scene's triangles");
  std::memcpy(vertices.data<float>(), s.positions.data(), s.positions.size() * 3 * sizeof(float));
  std::memcpy(indices.data<uint32_t>(), s.triangles.data(), triangles * 3 * sizeof(uint32_t));
  neighbours = Buffer(ctx, triangles * 3 * sizeof(uint32_t), storage, true, "the triangles' neighbours");
  const std::vector<uint32_t> across = edge_neighbours(s);
  std::memcpy(neighbours.data<uint32_t>(), across.data(), across.size() * sizeof(uint32_t));
  identity_ids = Buffer(ctx, triangles * sizeof(uint32_t), storage, true, "the scene's triangle ids");
  for (uint32_t t = 0; t < triangles; ++t) identity_ids.data<uint32_t>()[t] = t;
  corners = Buffer(ctx, triangles * 9 * sizeof(float), storage, true, "the scene's triangle corners");
  triangle_albedo = Buffer(ctx, triangles * 4 * sizeof(float), storage, true, "the scene's albedo");
  float* corner = corners.data<float>();
  float* albedo = triangle_albedo.data<float>();
  std::vector<double> cumulative_area(triangles);
  double area = 0;
  for (size_t t = 0; t < triangles; ++t) {
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) corner[t * 9 + k * 3 + a] = s.positions[s.triangles[t][k]][a];
    Rgb rho = s.triangle_albedo(t);
    for (int a = 0; a < 3; ++a) albedo[t * 4 + a] = rho[a];
    albedo[t * 4 + 3] = 0.f;
    const Vec3 &p0 = s.positions[s.triangles[t][0]], &p1 = s.positions[s.triangles[t][1]], &p2 = s.positions[s.triangles[t][2]];
    area += 0.5 * double(glm::length(glm::cross(p1 - p0, p2 - p0)));
    cumulative_area[t] = area;
  }
  if (!(area > 0)) throw InputError(s.source, "the scene's triangles have no area");
  // The ISMs' point samples: uniform over the surface area, in random order
  // (each VPL splats a run of them, i.e. its own random subset).
  pool = Buffer(ctx, size_t(pool_size) * 4 * sizeof(float), storage, true, "the ISM point samples");
  float* sample = pool.data<float>();
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + 17);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (uint32_t k = 0; k < pool_size; ++k) {
    size_t t = size_t(std::lower_bound(cumulative_area.begin(), cumulative_area.end(), uniform(rng) * area) - cumulative_area.begin());
    t = std::min(t, triangles - 1);
    float r1 = float(std::sqrt(uniform(rng))), r2 = float(uniform(rng));
    const Vec3 &p0 = s.positions[s.triangles[t][0]], &p1 = s.positions[s.triangles[t][1]], &p2 = s.positions[s.triangles[t][2]];
    Vec3 q = (1.f - r1) * p0 + r1 * (1.f - r2) * p1 + r1 * r2 * p2;
    sample[4 * k] = q.x;
    sample[4 * k + 1] = q.y;
    sample[4 * k + 2] = q.z;
    sample[4 * k + 3] = 1.f;
  }
}

} // namespace hilight::ism
