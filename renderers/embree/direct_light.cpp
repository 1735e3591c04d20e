#include "direct_light.hpp"

namespace hilight::embree {

PreparedLight::PreparedLight(const Light& light) : position(light.position), intensity(light.intensity) {
  if (light.type == LightType::Spot) {
    spot = true;
    direction = glm::normalize(light.direction);
    cos_cutoff = std::cos(float(light.cutoff_deg * kPi / 180.0));
    cos_inner = light.falloff_deg > 0.f ? std::cos(float((light.cutoff_deg - light.falloff_deg) * kPi / 180.0)) : cos_cutoff;
  }
}

} // namespace hilight::embree
