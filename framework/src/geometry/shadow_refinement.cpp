#include "hilight/shadow_refinement.hpp"

#include <algorithm>
#include <cstring>
#include <unordered_map>
#include <unordered_set>

namespace hilight {

namespace {

float luminance(const Rgb& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

uint64_t edge_key(uint32_t a, uint32_t b) { return a < b ? (uint64_t(a) << 32) | b : (uint64_t(b) << 32) | a; }

struct Flagged {
  uint32_t triangle;
  float contrast;
};

/// Triangles across which the light changes by more than `contrast` of the
/// brightest vertex (and whose longest edge may still be split), most
/// contrasted first.
std::vector<Flagged> fast_changing(const Scene& scene, const std::vector<Rgb>& light, float contrast, float min_edge) {
  double mean = 0;
  for (const auto& c : light) mean += luminance(c) / double(std::max<size_t>(1, light.size()));
  std::vector<Flagged> out;
  for (uint32_t t = 0; t < scene.triangles.size(); ++t) {
    const auto& tri = scene.triangles[t];
    float lo = luminance(light[tri[0]]), hi = lo;
    for (int k = 1; k < 3; ++k) lo = std::min(lo, luminance(light[tri[k]])), hi = std::max(hi, luminance(light[tri[k]]));
    if (!(hi > 1e-3f * float(mean)) || hi - lo <= contrast * hi) continue;
    float longest = 0.f;
    for (int k = 0; k < 3; ++k) longest = std::max(longest, glm::length(scene.positions[tri[k]] - scene.positions[tri[(k + 1) % 3]]));
    if (longest < 2.f * min_edge) continue;
    out.push_back({t, (hi - lo) / hi});
  }
  std::sort(out.begin(), out.end(), [](const Flagged& a, const Flagged& b) { return a.contrast > b.contrast; });
  return out;
}

/// Per vertex, the first vertex at the same position: edges are matched by
/// where they are, so copies of a vertex (split at creases, materials or
/// texture seams) split their shared edges together and no crack opens.
std::vector<uint32_t> welded(const Scene& scene) {
  std::unordered_map<uint64_t, uint32_t> first;
  std::vector<uint32_t> out(scene.positions.size());
  for (uint32_t v = 0; v < out.size(); ++v) {
    const Vec3& p = scene.positions[v];
    uint32_t bits[3];
    std::memcpy(bits, &p, sizeof bits);
    const uint64_t key = (uint64_t(bits[0]) * 0x9E3779B97F4A7C15ull) ^ (uint64_t(bits[1]) << 21) ^ (uint64_t(bits[2]) * 0xC2B2AE3D27D4EB4Full);
    auto [it, inserted] = first.emplace(key, v);
    // A hash collision between different positions must not weld them.
    out[v] = inserted || scene.positions[it->second] == p ? it->second : v;
  }
  return out;
}

/// The scene with every edge whose (welded) ends are in `split` cut at its
/// midpoint; every triangle touching a split edge is cut conformingly (1, 2
/// or 3 split edges: 2, 3 or 4 triangles). Each copy of a split edge gets its
/// own midpoint vertex (its own normal), all at the same position.
Scene split_edges(const Scene& scene, const std::vector<uint32_t>& weld, const std::unordered_set<uint64_t>& split) {
  Scene out = scene;
  out.triangles.clear();
  out.triangle_material.clear();
  std::unordered_map<uint64_t, uint32_t> midpoint;  // by vertex-index pair
  auto mid = [&](uint32_t a, uint32_t b) -> int64_t {
    if (!split.count(edge_key(weld[a], weld[b]))) return -1;
    auto [it, inserted] = midpoint.emplace(edge_key(a, b), uint32_t(out.positions.size()));
    if (inserted) {
      // From the welded ends, in a fixed order: every copy lands on the same bits.
      const uint32_t lo = std::min(weld[a], weld[b]), hi = std::max(weld[a], weld[b]);
      out.positions.push_back(0.5f * (scene.positions[lo] + scene.positions[hi]));
      Vec3 n = scene.normals[a] + scene.normals[b];
      out.normals.push_back(glm::length(n) > 0.f ? glm::normalize(n) : scene.normals[a]);
    }
    return int64_t(it->second);
  };
  for (size_t t = 0; t < scene.triangles.size(); ++t) {
    const auto& tri = scene.triangles[t];
    const uint32_t material = scene.triangle_material[t];
    auto emit = [&](uint32_t a, uint32_t b, uint32_t c) {
      out.triangles.push_back({a, b, c});
      out.triangle_material.push_back(material);
    };
    const int64_t m[3] = {mid(tri[0], tri[1]), mid(tri[1], tri[2]), mid(tri[2], tri[0])};
    const int count = int(m[0] >= 0) + int(m[1] >= 0) + int(m[2] >= 0);
    if (count == 0) {
      emit(tri[0], tri[1], tri[2]);
    } else if (count == 3) {
      const uint32_t ab = uint32_t(m[0]), bc = uint32_t(m[1]), ca = uint32_t(m[2]);
      emit(tri[0], ab, ca);
      emit(ab, tri[1], bc);
      emit(ca, bc, tri[2]);
      emit(ab, bc, ca);
    } else {
      // Rotate so that edge k (from corner k to k+1) is split, keeping the winding.
      int k = 0;
      if (count == 1) k = m[0] >= 0 ? 0 : (m[1] >= 0 ? 1 : 2);
      else k = m[0] < 0 ? 1 : (m[1] < 0 ? 2 : 0);  // two split: start after the unsplit edge
      const uint32_t a = tri[k], b = tri[(k + 1) % 3], c = tri[(k + 2) % 3];
      const uint32_t ab = uint32_t(m[k]);
      if (count == 1) {
        emit(a, ab, c);
        emit(ab, b, c);
      } else {
        const uint32_t bc = uint32_t(m[(k + 1) % 3]);
        emit(ab, b, bc);
        emit(a, ab, bc);
        emit(a, bc, c);
      }
    }
  }
  return out;
}

} // namespace

ShadowRefinementResult refine_shadow_edges(std::shared_ptr<const Scene> scene, const VertexLight& direct_light,
                                           const ShadowRefinementSettings& settings) {
  ShadowRefinementResult result;
  const size_t budget = settings.vertex_budget ? settings.vertex_budget : 4 * scene->positions.size();
  const float min_edge = settings.min_edge > 0.f ? settings.min_edge
                                                 : (scene->max_edge > 0.f ? scene->max_edge / 16.f : scene->diagonal() / 1000.f);
  for (int pass = 0; pass < settings.passes && scene->positions.size() < budget; ++pass) {
    const std::vector<Rgb> light = direct_light(scene);
    const std::vector<Flagged> flagged = fast_changing(*scene, light, settings.contrast, min_edge);
    const std::vector<uint32_t> weld = welded(*scene);
    std::unordered_set<uint64_t> split;
    for (const Flagged& f : flagged) {
      const auto& tri = scene->triangles[f.triangle];
      size_t added = 0;
      for (int k = 0; k < 3; ++k) added += !split.count(edge_key(weld[tri[k]], weld[tri[(k + 1) % 3]]));
      // (Copies of an edge at a crease each get a vertex: the budget counts positions.)
      if (scene->positions.size() + split.size() + added > budget) break;
      for (int k = 0; k < 3; ++k) split.insert(edge_key(weld[tri[k]], weld[tri[(k + 1) % 3]]));
    }
    if (split.empty()) break;
    const size_t before = scene->positions.size();
    scene = std::make_shared<const Scene>(split_edges(*scene, weld, split));
    result.split_edges += scene->positions.size() - before;
    result.passes = pass + 1;
  }
  result.scene = std::move(scene);
  return result;
}

} // namespace hilight
