#pragma once
/// Direct irradiance from one light at one surface point: inverse-square,
/// two-sided cosine |n·ω| (docs/rendering-model.md), spot cone, shadow ray.
#include "hilight/ray_scene.hpp"
#include "hilight/lighting.hpp"

#include <algorithm>
#include <cmath>

namespace hilight::embree {

/// A light with its cone precomputed as cosines, so the hot loop has no trig.
struct PreparedLight {
  Vec3 position;
  bool spot = false;
  Vec3 direction{0.f};
  SpotCone cone;
  Rgb intensity{1.f};
  const Light* luminaire = nullptr;  ///< with a profile (the Light outlives the batch)
  LuminaireFrame frame;

  explicit PreparedLight(const Light& light);
  /// Angular factor toward unit direction `to_point` (from the light):
  /// smoothstep in the cosine between the cone's edge and its full-intensity
  /// core; a luminaire's candela there over its peak (bilinear in its grid).
  float angular(const Vec3& to_point) const {
    if (luminaire) return luminaire_factor(*luminaire, frame, to_point);
    return spot ? cone.factor(glm::dot(direction, to_point)) : 1.f;
  }
};

/// Irradiance on one side of a surface at `at` — the side `side_normal`
/// points to — from `light` at unit intensity: |n·ω| · S / d² · V, zero for a
/// light behind that side. The shadow ray starts as `at` says (ShadingPoint::
/// ray_start). Counts the shadow ray it casts in `rays`.
inline float unit_direct_irradiance_on_side(const RayScene& es, const ShadingPoint& at, const Vec3& n,
                                            const Vec3& side_normal, const PreparedLight& light, uint64_t& rays) {
  const Vec3& p = at.position;
  Vec3 d = light.position - p;
  float dist2 = glm::dot(d, d);
  float eps = es.epsilon();
  if (dist2 <= eps * eps) return 0.f;
  float dist = std::sqrt(dist2);
  Vec3 w = d / dist;
  if (glm::dot(side_normal, w) <= 0.f) return 0.f;
  float cos_n = std::abs(glm::dot(n, w));
  if (cos_n == 0.f) return 0.f;
  float angular = light.angular(-w);
  if (angular == 0.f) return 0.f;
  ++rays;
  if (es.occluded(at.ray_start(w, side_normal, eps), w, dist - 2.f * eps)) return 0.f;
  return cos_n * angular / dist2;
}

/// Irradiance at a point summed over both sides (a light lies on one of
/// them): the two-sided value of docs/rendering-model.md. `side_normal` (the
/// shading normal for surface points, the geometric normal for a pixel's hit)
/// tells the sides apart.
inline float unit_direct_irradiance(const RayScene& es, const ShadingPoint& at, const Vec3& n, const Vec3& side_normal,
                                    const PreparedLight& light, uint64_t& rays) {
  Vec3 side = glm::dot(side_normal, light.position - at.position) >= 0.f ? side_normal : -side_normal;
  return unit_direct_irradiance_on_side(es, at, n, side, light, rays);
}

} // namespace hilight::embree
