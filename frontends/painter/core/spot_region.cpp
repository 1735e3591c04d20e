#include "core/spot_region.hpp"

#include "hilight/error.hpp"

#include <algorithm>
#include <cmath>

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

} // namespace hilight::painter
