#include "hilight/lighting.hpp"

#include <algorithm>
#include <cmath>


namespace hilight {

const char* to_string(LightType type) {
  return type == LightType::Spot ? "spot" : type == LightType::Luminaire ? "luminaire" : "point";
}

LuminaireFrame LuminaireFrame::of(const Light& light) {
  LuminaireFrame f;
  f.nadir = glm::normalize(light.direction);
  const Vec3 reference = std::abs(f.nadir.x) > 0.9f ? Vec3(0.f, 0.f, 1.f) : Vec3(1.f, 0.f, 0.f);
  Vec3 c0 = glm::normalize(reference - glm::dot(reference, f.nadir) * f.nadir);
  Vec3 c90 = glm::cross(c0, f.nadir);
  const float spin = float(light.spin_deg * kPi / 180.0);
  f.c0 = std::cos(spin) * c0 + std::sin(spin) * c90;
  f.c90 = glm::cross(f.c0, f.nadir);
  return f;
}

void LuminaireFrame::angles(const Vec3& to_point, double& c_deg, double& gamma_deg) const {
  const double down = glm::dot(to_point, nadir), x = glm::dot(to_point, c0), y = glm::dot(to_point, c90);
  gamma_deg = std::acos(std::clamp(down, -1.0, 1.0)) * 180.0 / kPi;
  c_deg = std::atan2(y, x) * 180.0 / kPi;
  if (c_deg < 0) c_deg += 360.0;
}

float luminaire_factor(const Light& light, const LuminaireFrame& frame, const Vec3& to_point) {
  if (!light.profile) return 0.f;
  const double peak = light.profile->peak();
  if (!(peak > 0)) return 0.f;
  double c, gamma;
  frame.angles(to_point, c, gamma);
  return float(light.profile->intensity(c, gamma) / peak);
}

SpotCone SpotCone::of(const Light& light) {
  SpotCone cone;
  cone.cos_cutoff = std::cos(float(light.cutoff_deg * kPi / 180.0));
  cone.cos_inner = light.falloff_deg > 0.f ? std::cos(float((light.cutoff_deg - light.falloff_deg) * kPi / 180.0)) : cone.cos_cutoff;
  return cone;
}

} // namespace hilight
