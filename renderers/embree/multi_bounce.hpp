#pragma once
/// Every diffuse bounce after the first (docs/rendering-model.md, "Every
/// bounce"). The scene's vertices gather too, each side of each vertex over
/// its own hemisphere (`transport_samples` rays a vertex, half a side), and
/// their hits define one linear operator T on irradiance per (vertex, side):
///   (T F)(v, s) = (2/N) Σ_hits ρ(y) F(y, the side of y seen),
/// F interpolated across the hit triangle. From the direct light e₀ at the
/// vertices, d_k = T^k e₀ is the light bounced k times, and a point's
/// gather reads f = d₁ + … + d_{B−1} at its hits: B bounces in all (the
/// first, from e₀ at the hits, stays as first_bounce.hpp computes it).
/// Linear in the lights, deterministic, no light is created: each step
/// multiplies by the albedo, so a closed room's flux is passed on as ρ^k.
/// "All" iterates until the steps shrink geometrically or fall under a
/// negligible share of the sum, and adds the geometric rest (the rule every
/// renderer shares: hilight/bounce_series.hpp).
#include "first_bounce.hpp"
#include "hilight/bounce_series.hpp"
#include "hilight/bounces.hpp"

#include <vector>

namespace hilight::embree {

class MultiBounce {
public:
  /// `bounces`: the total count (≥ 2), or kAllBounces; `vertex_shading`:
  /// where each scene vertex is shaded (shading_point).
  /// `progress`: advanced by one per vertex gathered.
  /// `rest_share`: when "all" may add the geometric rest (BounceSeriesSum).
  MultiBounce(const RayScene& es, const std::vector<ShadingPoint>& vertex_shading, int samples, uint64_t seed, int bounces,
              double rest_share = BounceSeriesSum::kRestShare, ProgressStage* progress = nullptr);

  /// The (vertex, side) entries whose direct light the operator reads
  /// (as BounceGather::vertex_sides_read).
  const std::vector<uint32_t>& vertex_sides_read() const { return m_gather.vertex_sides_read(); }
  uint64_t rays_cast() const { return m_gather.rays_cast(); }

  /// f for each light: `direct` holds e₀ per light (2 values a vertex, light-
  /// major, as EmbreeRenderer::vertex_direct_irradiance lays them out); the
  /// result holds 2 RGB values a vertex for each light, entry-major: the
  /// lights' values at (vertex v, side s) from [(2v + s) · light_count]
  /// (BounceGather::field_irradiance reads them so).
  /// `progress`: advanced by one per step (expected_steps() of them, about).
  std::vector<Rgb> bounced_field(const std::vector<float>& direct, size_t light_count, ProgressStage* progress = nullptr) const;
  /// About how many steps bounced_field takes (for progress; "all" usually
  /// ends within this many by the geometric rest).
  int expected_steps() const { return m_bounces == kAllBounces ? 8 : m_bounces - 1; }

  static constexpr int kMaxSteps = 200;  ///< "all" ends by then (the stopping rule: hilight/bounce_series.hpp)

private:
  const RayScene& m_es;
  BounceGather m_gather;  ///< over the scene's vertices
  int m_bounces;
  double m_rest_share;
};

} // namespace hilight::embree
