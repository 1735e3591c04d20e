#pragma once
/// The first diffuse bounce by gathering: every point casts N rays over both
/// hemispheres (two-sided surfaces; N/2 cosine-weighted on each side, from
/// Hammersley points rotated per point, the rotation seeded by the point's
/// position and normal). The hits are kept, so each light
/// then costs N shadow rays per point and no further intersection tests:
///   E_ind(x) = ∫_{S²} L(y(ω)) |cos θ| dω  ≈  (2/N) Σ_k albedo(y_k) · E_dir(y_k)
/// (each hemisphere's estimate is π/(N/2) Σ L, and L(y) = albedo(y)/π · E_dir(y)).
/// Unbiased for any N; the error falls as N grows (tests show it).
#include "direct_light.hpp"
#include "hilight/ray_scene.hpp"
#include "hilight/surface_points.hpp"

#include <vector>

namespace hilight::embree {

class BounceGather {
public:
  BounceGather(const RayScene& es, const SurfacePoints& points, int samples, uint64_t seed);

  int samples() const { return m_samples; }
  uint64_t rays_cast() const { return m_rays; }

  /// Indirect irradiance (RGB, per unit light intensity) at point i.
  Rgb unit_indirect_irradiance(size_t i, const PreparedLight& light, uint64_t& rays) const;
  /// The same with the direct irradiance at each hit interpolated from
  /// `vertex_direct` (one value per scene vertex) instead of shadow rays.
  Rgb interpolated_indirect_irradiance(size_t i, const float* vertex_direct) const;

private:
  const RayScene& m_es;
  int m_samples;
  uint64_t m_rays = 0;
  std::vector<Hit> m_hits;  ///< point-major, m * samples
};

} // namespace hilight::embree
