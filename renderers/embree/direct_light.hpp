#pragma once
/// Direct irradiance from one light at one surface point: inverse-square,
/// two-sided cosine |n·ω| (docs/rendering-model.md), spot cone, shadow ray.
#include "hilight/ray_scene.hpp"
#include "hilight/lighting.hpp"
#include "visibility_memo.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <vector>

namespace hilight::embree {

/// An area or line source ready to integrate (direct_light.cpp): its outline
/// (a rectangle's 4 corners, a disk as a 48-gon of the disk's area), the
/// centres of its equal parts (the visibility samples), and its profile.
struct AreaSource {
  LightType type = LightType::Rectangle;
  AreaFrame frame;
  std::vector<Vec3> outline;
  float area = 1.f;              ///< of the true shape (a line: its length)
  std::vector<Vec3> samples;
  const Light* profiled = nullptr;  ///< with a profile (the Light outlives the batch)
  LuminaireFrame profile_frame;
  float lambert_part = 1.f;  ///< the profile's value along the normal: the cosine part integrated exactly
};

/// Visibility samples per area source (line: half as many): 16 shadow rays
/// per point where the source is partly hidden; unhidden, the result is exact.
constexpr int kAreaSamples = 16;

/// Irradiance on the side `side_normal` points to, from an area or line
/// source at unit intensity: the exact form factor of the part of the source
/// in front of that side (Lambertian), times the fraction of it the shadow
/// rays to its parts see; a profile's difference from the cosine summed over
/// the parts (docs/rendering-model.md "Area and line sources").
float area_irradiance_on_side(const RayScene& es, const ShadingPoint& at, const Vec3& n, const Vec3& side_normal,
                              const AreaSource& area, uint64_t& rays);

/// A light with its cone precomputed as cosines, so the hot loop has no trig.
struct PreparedLight {
  Vec3 position;
  bool spot = false;
  Vec3 direction{0.f};
  SpotCone cone;
  Rgb intensity{1.f};
  const Light* luminaire = nullptr;  ///< with a profile (the Light outlives the batch)
  LuminaireFrame frame;
  std::shared_ptr<const AreaSource> area;  ///< area and line sources

  explicit PreparedLight(const Light& light);
  /// An area or line source: integrated over its extent by the functions
  /// below. What treats a light as a point at `position` with `angular()`
  /// (hot patches) sees only its far field here, and may skip it.
  bool extended() const { return area != nullptr; }
  /// Angular factor toward unit direction `to_point` (from the light):
  /// smoothstep in the cosine between the cone's edge and its full-intensity
  /// core; a luminaire's candela there over its peak (bilinear in its grid).
  /// An area or line source's, seen from afar (cos θ on its front side).
  float angular(const Vec3& to_point) const {
    if (area) return area->profiled ? luminaire_factor(*area->profiled, frame, to_point) : std::max(0.f, glm::dot(direction, to_point));
    if (luminaire) return luminaire_factor(*luminaire, frame, to_point);
    return spot ? cone.factor(glm::dot(direction, to_point)) : 1.f;
  }
};

/// A shadow ray: from `origin` along unit `dir` up to `tfar`.
struct ShadowRay {
  Vec3 origin{0.f}, dir{0.f};
  float tfar = 0.f;
};

/// What unit_direct_irradiance_on_side gives a point-like light (not
/// extended) before its shadow ray: the unshadowed irradiance in `value`, and
/// the shadow ray that decides it in `ray`. False when no ray is needed (the
/// light is behind that side, or outside its cone): the irradiance is 0.
inline bool unshadowed_point_irradiance_on_side(const RayScene& es, const ShadingPoint& at, const Vec3& n,
                                                const Vec3& side_normal, const PreparedLight& light, float& value,
                                                ShadowRay& ray) {
  const Vec3& p = at.position;
  Vec3 d = light.position - p;
  float dist2 = glm::dot(d, d);
  float eps = es.epsilon();
  if (dist2 <= eps * eps) return false;
  float dist = std::sqrt(dist2);
  Vec3 w = d / dist;
  if (glm::dot(side_normal, w) <= 0.f) return false;
  float cos_n = std::abs(glm::dot(n, w));
  if (cos_n == 0.f) return false;
  float angular = light.angular(-w);
  if (angular == 0.f) return false;
  value = cos_n * angular / dist2;
  ray = ShadowRay{at.ray_start(w, side_normal, eps), w, dist - 2.f * eps};
  return true;
}

/// Irradiance on one side of a surface at `at` — the side `side_normal`
/// points to — from `light` at unit intensity: |n·ω| · S / d² · V, zero for a
/// light behind that side or in the point's own wedge (in_own_wedge). The
/// shadow ray starts as `at` says (ShadingPoint::ray_start). Counts the
/// shadow ray it casts in `rays`. With `memo` (a point-like light's place,
/// visibility_memo.hpp), V is read there where an earlier light at the same
/// place asked it, else asked and kept there.
inline float unit_direct_irradiance_on_side(const RayScene& es, const ShadingPoint& at, const Vec3& n,
                                            const Vec3& side_normal, const PreparedLight& light, uint64_t& rays,
                                            std::atomic<uint8_t>* memo = nullptr) {
  if (light.area) return area_irradiance_on_side(es, at, n, side_normal, *light.area, rays);
  float value = 0.f;
  ShadowRay ray;
  if (!unshadowed_point_irradiance_on_side(es, at, n, side_normal, light, value, ray)) return 0.f;
  uint8_t answer = memo ? memo->load(std::memory_order_relaxed) : uint8_t(VisibilityMemo::kUnknown);
  if (answer == VisibilityMemo::kUnknown) {
    ++rays;
    // Through the smooth surface its own fan stands for. After the ray: most
    // rays that could lie in a wedge are blocked anyway (a solid's far side),
    // and the test looks the fan up.
    const bool hidden = es.occluded(ray.origin, ray.dir, ray.tfar) || in_own_wedge(es, at, n, ray.dir);
    answer = hidden ? VisibilityMemo::kHidden : VisibilityMemo::kSeen;
    if (memo) memo->store(answer, std::memory_order_relaxed);
  }
  return answer == VisibilityMemo::kSeen ? value : 0.f;
}

/// Irradiance at a point summed over both sides (a light lies on one of
/// them): the two-sided value of docs/rendering-model.md. `side_normal` (the
/// shading normal for surface points, the geometric normal for a pixel's hit)
/// tells the sides apart.
/// `memo`: as unit_direct_irradiance_on_side's.
inline float unit_direct_irradiance(const RayScene& es, const ShadingPoint& at, const Vec3& n, const Vec3& side_normal,
                                    const PreparedLight& light, uint64_t& rays, std::atomic<uint8_t>* memo = nullptr) {
  if (light.area)  // an extended source can light both sides
    return area_irradiance_on_side(es, at, n, side_normal, *light.area, rays) +
           area_irradiance_on_side(es, at, n, -side_normal, *light.area, rays);
  Vec3 side = glm::dot(side_normal, light.position - at.position) >= 0.f ? side_normal : -side_normal;
  return unit_direct_irradiance_on_side(es, at, n, side, light, rays, memo);
}

} // namespace hilight::embree
