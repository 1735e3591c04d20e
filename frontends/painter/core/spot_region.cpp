#include "core/spot_region.hpp"

#include "core/region.hpp"
#include "hilight/error.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace hilight::painter {

double max_angle_deg(const Vec3& eye, const Vec3& direction, const std::vector<Vec3>& region) {
  const DVec3 axis = glm::normalize(DVec3(direction));
  double largest = 0;
  for (const Vec3& p : region) {
    const DVec3 to_point = DVec3(p) - DVec3(eye);
    const double length = glm::length(to_point);
    if (!(length > 0.0)) continue;  // the eye itself: inside any cone
    const double c = std::clamp(glm::dot(axis, to_point / length), -1.0, 1.0);
    largest = std::max(largest, std::acos(c) * 180.0 / kPi);
  }
  return largest;
}

Light spot_for_region(const Vec3& eye, const Vec3& direction, const std::vector<Vec3>& region,
                      const SpotRegionSettings& settings) {
  const std::string what = "spot region";
  if (region.empty()) throw InputError(what, "the region is empty");
  if (!(glm::length(direction) > 0.f) || !is_finite(direction)) throw InputError(what, "the view direction is zero");
  const double alpha = max_angle_deg(eye, direction, region);
  const float falloff = std::max(settings.falloff_deg, 0.f);
  const double cutoff = alpha + double(falloff) + double(kSpotCoverMarginDeg);
  if (!(cutoff < 90.0))
    throw InputError(what, "the region spans " + std::to_string(int(std::round(alpha))) +
                               "° from the view direction: a spotlight covers less than 90° (look at the region)");
  return Light::spot(eye, direction, float(cutoff), settings.intensity, falloff);
}

Light spot_for_region_in_scene(const LightSpace& space, const Vec3& eye, const Vec3& direction,
                               const std::vector<Vec3>& region, const SpotRegionSettings& settings) {
  const std::string what = "spot region";
  if (region.empty()) throw InputError(what, "the region is empty");
  if (!(glm::length(direction) > 0.f) || !is_finite(direction)) throw InputError(what, "the view direction is zero");
  const RayScene& rays = space.rays();
  const Scene& scene = rays.scene();
  // Rays from far-off origins overflow the ray tracer's float arithmetic.
  if (!is_finite(eye) ||
      !(glm::length(DVec3(eye) - DVec3(scene.bounds.center())) <= 1e6 * std::max(double(scene.diagonal()), 1e-30)))
    throw InputError(what, "the eye is more than 1e6 scene diagonals from the scene");
  const Vec3 axis = glm::normalize(direction);
  const Vec3 target = centroid(region);
  // Stop before the region's own plane: the apex must stay in front of it.
  const float limit = glm::dot(target - eye, axis);
  const float step = 0.01f * scene.diagonal();
  // Where a light for the view point `p` stands (LightSpace::place: on the
  // ceiling mount under a ceiling rule), if the designer's rules admit it
  // and it sees the region's centroid (on a surface: the ray stops short).
  auto apex_for = [&](const Vec3& p) -> std::optional<Vec3> {
    const std::optional<Vec3> at = space.place(p);
    if (!at || !space.admissible(*at)) return std::nullopt;
    const Vec3 to_target = target - *at;
    const float distance = glm::length(to_target);
    if (!(distance > 0.f) || rays.occluded(*at, to_target / distance, distance * 0.999f)) return std::nullopt;
    return at;
  };
  float t = 0.f;
  for (int guard = 0; guard < 10000 && t < limit; ++guard) {
    const Vec3 p = eye + t * axis;
    if (const std::optional<Vec3> apex = apex_for(p)) {
      if (*apex == p) return spot_for_region(p, axis, region, settings);
      // Moved to the ceiling: the view's direction no longer aims at the
      // region, the direction to its centroid does (if a cone covers it).
      const Vec3 aim = glm::normalize(target - *apex);
      if (max_angle_deg(*apex, aim, region) + double(std::max(settings.falloff_deg, 0.f)) + double(kSpotCoverMarginDeg) < 90.0)
        return spot_for_region(*apex, aim, region, settings);
    }
    // Past the next surface along the view, or one step on in free space.
    Hit hit = rays.intersect(p, axis, limit - t);
    t = hit.valid() && hit.t < step ? t + hit.t + step : t + step;
  }
  throw InputError(what, space.rules().any() ? "no place the placement rules (" + space.rules().describe() +
                                                   ") allow for a spotlight between the camera and the region (move the camera)"
                                             : "no place for a spotlight between the camera and the region (move the camera)");
}

} // namespace hilight::painter
