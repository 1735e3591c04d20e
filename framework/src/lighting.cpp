#include "hilight/lighting.hpp"

#include <algorithm>
#include <cmath>

namespace hilight {

float spot_factor(const Light& light, const Vec3& to_point) {
  if (light.type != LightType::Spot) return 1.f;
  float cos_angle = glm::dot(light.direction, to_point);
  float angle = std::acos(std::clamp(cos_angle, -1.f, 1.f)) * float(180.0 / kPi);
  if (angle > light.cutoff_deg) return 0.f;
  if (light.falloff_deg <= 0.f) return 1.f;
  float t = std::clamp((light.cutoff_deg - angle) / light.falloff_deg, 0.f, 1.f);
  return t * t * (3.f - 2.f * t);
}

const char* to_string(LightType type) { return type == LightType::Spot ? "spot" : "point"; }

} // namespace hilight
