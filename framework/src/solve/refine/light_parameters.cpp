#include "hilight/solve/light_parameters.hpp"

#include <algorithm>
#include <cmath>

namespace hilight {

void append_geometry(const Light& light, float scale, std::vector<double>& params, std::vector<double>& steps) {
  for (int k = 0; k < 3; ++k) {
    params.push_back(light.position[k] / scale);
    steps.push_back(0.03);  // 3% of the diagonal
  }
  if (light.type == LightType::Spot) {
    Vec3 d = glm::normalize(light.direction);
    params.push_back(std::acos(std::clamp(double(d.y), -1.0, 1.0)));  // polar angle from +Y
    params.push_back(std::atan2(double(d.z), double(d.x)));            // azimuth
    params.push_back(light.cutoff_deg * kPi / 180.0);
    params.push_back(light.falloff_deg * kPi / 180.0);  // the soft edge: found with the cone
    steps.insert(steps.end(), {0.1, 0.1, 0.05, 0.02});
  }
}

size_t read_geometry(Light& light, float scale, const std::vector<double>& p, size_t o) {
  light.position = Vec3(float(p[o] * scale), float(p[o + 1] * scale), float(p[o + 2] * scale));
  o += 3;
  if (light.type == LightType::Spot) {
    double polar = p[o], azimuth = p[o + 1];
    light.direction = glm::normalize(Vec3(float(std::sin(polar) * std::cos(azimuth)), float(std::cos(polar)),
                                          float(std::sin(polar) * std::sin(azimuth))));
    light.cutoff_deg = float(std::clamp(p[o + 2] * 180.0 / kPi, 1.0, 89.0));
    light.falloff_deg = float(std::clamp(p[o + 3] * 180.0 / kPi, 0.0, double(light.cutoff_deg)));
    o += 4;
  }
  return o;
}

} // namespace hilight
