#pragma once
/// Every bounce after the first, for ism-vulkan (docs/ism-vulkan.md, "Every
/// bounce"). A fixed set of bounce points, area-uniform over the scene, each
/// side of each one gathering over a small paraboloid map of its hemisphere
/// into which every bounce point was splatted (bounce_splat.comp: a texel
/// keeps the nearest). Their texels define one linear operator on the
/// irradiance per (bounce point, side),
///   (T F)(r) = Σ_texels w_t ρ(hit_t) F(hit_t),
/// w_t the texel's share of the cosine-weighted hemisphere (Σ w_t = 1), so
/// a closed room passes its flux on as ρ^k: no light is made or lost however
/// coarse the maps. From the direct light e₀ at the bounce points,
/// d_k = T^k e₀ is the light bounced k times; a shaded point gathers
/// f = d₁ + … + d_{B−1} through its own maps the same way (bounces 2..B; the
/// first stays the VPLs'). Linear in the lights, light-independent maps
/// (made once per scene and once per point set).
#include "hilight/scene.hpp"
#include "hilight/surface_points.hpp"

#include <cstdint>
#include <vector>

namespace hilight::ism {

/// `count` area-uniform samples of the scene's surface (seeded): positions,
/// face normals, albedo.
SurfacePoints sample_bounce_points(const Scene& scene, uint32_t count, uint64_t seed);
/// The scene's surface area (one side).
double surface_area(const Scene& scene);

/// Each texel's share of the cosine-weighted hemisphere on a size × size
/// paraboloid map (common.glsl's paraboloid_texel); they sum to 1.
std::vector<float> paraboloid_cosine_weights(uint32_t size);

/// A gathering operator's rows: per receiver side, the (bounce point side,
/// weight) pairs its map saw, weights from paraboloid_cosine_weights.
struct GatherRows {
  std::vector<uint32_t> start{0};  ///< row r's entries are [start[r], start[r + 1])
  std::vector<uint32_t> hit;       ///< 2 × bounce point + the side of it seen
  std::vector<float> weight;

  size_t rows() const { return start.size() - 1; }
  /// Appends the rows of `count` maps (size² packed texels each, as
  /// bounce_splat.comp writes them: `nearest` from its pass 0, `drawn` from
  /// its pass 1). A texel reads its drawn point; an empty one takes that of
  /// its nearest neighbour up to two texels away (too few points landed
  /// there); one with none that close is open sky.
  void append(const uint32_t* nearest, const uint32_t* drawn, size_t count, uint32_t size, const std::vector<float>& weights);
};

/// The series of bounces over the bounce points, and the shaded points' gather of it.
class BounceSeries {
public:
  /// `transport`: T's rows, one per (bounce point, side); `albedo`: ρ per
  /// bounce point; `bounces`: the total count (≥ 2) or kAllBounces.
  BounceSeries(GatherRows transport, std::vector<Rgb> albedo, int bounces);

  /// f = d₁ + … + d_{B−1} per light, 2 RGB values a bounce point (light-
  /// major), from e₀: 2 irradiance values a bounce point per light.
  /// "All" stops as embree's MultiBounce does (docs/rendering-model.md).
  std::vector<Rgb> bounced(const std::vector<float>& direct, size_t lights) const;

  /// Adds to out[j · stride + first + i] the radiance ρ_i/π · Σ_sides (rows
  /// 2i, 2i+1 of `points`) Σ w ρ(hit) f_j(hit) for each point of the chunk.
  void gather(const GatherRows& points, const std::vector<Rgb>& point_albedo, size_t first, const std::vector<Rgb>& f,
              size_t lights, Rgb* out, size_t stride) const;

  size_t sides() const { return 2 * m_albedo.size(); }
  static constexpr int kMaxSteps = 1000;  ///< "all" ends by then (the stopping rule: hilight/bounce_series.hpp)

private:
  GatherRows m_transport;
  std::vector<Rgb> m_albedo;
  int m_bounces;
};

} // namespace hilight::ism
