#include "hilight/lighting.hpp"

#include <cmath>


namespace hilight {

const char* to_string(LightType type) { return type == LightType::Spot ? "spot" : "point"; }

SpotCone SpotCone::of(const Light& light) {
  SpotCone cone;
  cone.cos_cutoff = std::cos(float(light.cutoff_deg * kPi / 180.0));
  cone.cos_inner = light.falloff_deg > 0.f ? std::cos(float((light.cutoff_deg - light.falloff_deg) * kPi / 180.0)) : cone.cos_cutoff;
  return cone;
}

} // namespace hilight
