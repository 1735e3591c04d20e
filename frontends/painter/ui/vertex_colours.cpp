#include "ui/vertex_colours.hpp"

#include <algorithm>
#include <cmath>

namespace hilight::painter::ui {

float luminance(const Rgb& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

float auto_exposure(const std::vector<Rgb>& values, const std::vector<float>& weights) {
  std::vector<float> lum;
  lum.reserve(values.size());
  for (size_t i = 0; i < values.size(); ++i)
    if (weights.empty() || weights[i] > 0.f) lum.push_back(luminance(values[i]));
  if (lum.empty()) return 0.f;
  size_t k = std::min(lum.size() - 1, size_t(0.99 * double(lum.size())));
  std::nth_element(lum.begin(), lum.begin() + std::ptrdiff_t(k), lum.end());
  return lum[k] > 0.f && std::isfinite(lum[k]) ? 0.9f / lum[k] : 0.f;
}

std::vector<VertexColour> result_colours(const std::vector<Rgb>& radiance, float exposure) {
  std::vector<VertexColour> out(radiance.size());
  for (size_t i = 0; i < radiance.size(); ++i) out[i].rgb = glm::clamp(radiance[i] * exposure, 0.f, 1.f);
  return out;
}

std::vector<VertexColour> target_colours(const std::vector<Rgb>& psi, const std::vector<float>& weight,
                                         const std::vector<Rgb>& backdrop, float exposure) {
  std::vector<VertexColour> out(psi.size());
  for (size_t i = 0; i < psi.size(); ++i) {
    if (weight[i] > 0.f) out[i].rgb = glm::clamp(psi[i] * exposure, 0.f, 1.f);
    else out[i] = {backdrop[i], 1.f};
  }
  return out;
}

Rgb heat_colour(float t) {
  t = std::clamp(t, 0.f, 1.f);
  if (t < 1.f / 3.f) return Rgb(0.f, 0.f, 3.f * t);                     // black -> blue
  if (t < 2.f / 3.f) { float s = 3.f * t - 1.f; return Rgb(s, 0.f, 1.f - s); }  // blue -> red
  return Rgb(1.f, 3.f * t - 2.f, 0.f);                                  // red -> yellow
}

std::vector<VertexColour> difference_colours(const std::vector<Rgb>& psi, const std::vector<float>& weight,
                                             const std::vector<Rgb>& radiance, const std::vector<Rgb>& backdrop,
                                             float exposure) {
  std::vector<VertexColour> out(psi.size());
  for (size_t i = 0; i < psi.size(); ++i) {
    if (weight[i] > 0.f) out[i].rgb = heat_colour(std::abs(luminance(psi[i]) - luminance(radiance[i])) * exposure);
    else out[i] = {backdrop[i], 1.f};
  }
  return out;
}

} // namespace hilight::painter::ui
