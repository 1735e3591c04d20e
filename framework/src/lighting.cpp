#include "hilight/lighting.hpp"

#include <algorithm>
#include <cmath>

namespace hilight {

float spot_factor(const Light& light, const Vec3& to_point) {
  if (light.type != LightType::Spot) return 1.f;
  const float c = glm::dot(light.direction, to_point);
  const float cos_cutoff = std::cos(float(light.cutoff_deg * kPi / 180.0));
  if (c < cos_cutoff) return 0.f;
  if (light.falloff_deg <= 0.f) return 1.f;
  const float cos_inner = std::cos(float((light.cutoff_deg - light.falloff_deg) * kPi / 180.0));
  if (c >= cos_inner) return 1.f;
  const float t = (c - cos_cutoff) / (cos_inner - cos_cutoff);
  return t * t * (3.f - 2.f * t);
}

const char* to_string(LightType type) { return type == LightType::Spot ? "spot" : "point"; }

} // namespace hilight
