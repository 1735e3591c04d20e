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

Lighting luminaire_as_spots(const Light& light) {
  if (light.type != LightType::Luminaire || !light.profile || !(light.profile->peak() > 0)) return {light};
  constexpr int kBands = 18;  // every 5° to 90°, each way
  const double peak = light.profile->peak();
  const LuminaireFrame frame = LuminaireFrame::of(light);
  // The C-averaged shape at γ = 0, 5, ..., 180 (as the renderers see it).
  std::vector<double> shape(2 * kBands + 1);
  for (int j = 0; j <= 2 * kBands; ++j) {
    double sum = 0;
    for (int c = 0; c < 72; ++c) sum += light.profile->intensity(5.0 * c, 5.0 * j);
    shape[size_t(j)] = sum / 72.0 / peak;
  }
  Lighting out;
  const Photometry& p = *light.profile;
  const double gamma_max = p.type == Photometry::Type::C ? p.vertical.back() : 180.0;
  if (p.type == Photometry::Type::C && p.vertical.front() <= 0.0 && gamma_max <= 90.0) {
    // A downlight: dark beyond its last measured γ, sharply (a smooth band
    // there would light the walls above the lamp). Steps between samples
    // inside, then one hard-edged spot carrying the value at γ_max.
    auto at = [&](double gamma) {
      double sum = 0;
      for (int c = 0; c < 72; ++c) sum += p.intensity(5.0 * c, std::min(gamma, gamma_max - 1e-6));
      return sum / 72.0 / peak;
    };
    const int bands = int(std::floor(gamma_max / 5.0 + 1e-9));
    for (int k = 1; k <= bands; ++k)
      if (const double step = at(5.0 * (k - 1)) - at(5.0 * k); step != 0.0)
        out.push_back(Light::spot(light.position, frame.nadir, 5.f * float(k), light.intensity * float(step), 5.f));
    // Between the last sample and γ_max (when γ_max is not on the 5° grid).
    if (const double rest = at(5.0 * bands) - at(gamma_max); rest != 0.0 && gamma_max > 5.0 * bands)
      out.push_back(Light::spot(light.position, frame.nadir, float(gamma_max), light.intensity * float(rest),
                                float(gamma_max - 5.0 * bands)));
    if (const double edge = at(gamma_max); edge != 0.0)
      out.push_back(Light::spot(light.position, frame.nadir, float(gamma_max), light.intensity * float(edge), 0.25f));
    return out;
  }
  if (shape[size_t(kBands)] != 0.0) out.push_back(Light::point(light.position, light.intensity * float(shape[size_t(kBands)])));
  for (int k = 1; k <= kBands; ++k) {
    // Downward: the step between γ = 5(k−1) and 5k; upward: between 180 − 5(k−1) and 180 − 5k.
    const double down = shape[size_t(k - 1)] - shape[size_t(k)];
    const double up = shape[size_t(2 * kBands - k + 1)] - shape[size_t(2 * kBands - k)];
    const float cutoff = 5.f * float(k), falloff = 5.f;
    if (down != 0.0) out.push_back(Light::spot(light.position, frame.nadir, cutoff, light.intensity * float(down), falloff));
    if (up != 0.0) out.push_back(Light::spot(light.position, -frame.nadir, cutoff, light.intensity * float(up), falloff));
  }
  return out;
}

} // namespace hilight
