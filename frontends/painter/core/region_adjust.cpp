#include "core/region_adjust.hpp"

#include "core/vertex_points.hpp"
#include "hilight/error.hpp"

namespace hilight::painter {

namespace {
double brightness(const Rgb& c) { return (double(c.r) + double(c.g) + double(c.b)) / 3.0; }
} // namespace

RegionAdjustResult adjust_region(Document& document, Renderer& renderer, const std::vector<uint32_t>& region,
                                 const RegionAdjustSettings& settings) {
  const std::string what = "adjust region";
  if (region.empty()) throw InputError(what, "the region holds no vertices");
  const Lighting lights = document.state().lights;  // a copy: the edit below changes them
  if (lights.empty()) throw InputError(what, "there are no lights to adjust (solve first)");
  const size_t n = region.size();
  SurfacePoints points = points_of_vertices(document.scene(), region);
  // φ is per unit light: scale by each light's own intensity.
  std::vector<Rgb> phi = renderer.unit_responses(points, lights);
  std::vector<double> light_sum(lights.size(), 0.0);
  double total = 0;
  for (size_t j = 0; j < lights.size(); ++j) {
    for (size_t i = 0; i < n; ++i) light_sum[j] += brightness(lights[j].intensity * phi[j * n + i]);
    total += light_sum[j];
  }
  if (!(total > 0.0)) throw InputError(what, "no light reaches the region");

  RegionAdjustResult result;
  for (size_t j = 0; j < lights.size(); ++j) {
    result.shares.push_back(light_sum[j] / total);
    if (result.shares.back() >= settings.min_share) result.changed_lights.push_back(j);
  }
  document.apply(what, [&](PaintState& s) {
    for (size_t i = 0; i < n; ++i) {
      const uint32_t v = region[i];
      Rgb current(0.f), change(0.f);
      for (size_t j = 0; j < lights.size(); ++j) current += lights[j].intensity * phi[j * n + i];
      for (size_t j : result.changed_lights) change += (settings.multiplier - Rgb(1.f)) * lights[j].intensity * phi[j * n + i];
      const Rgb base = s.weight[v] > 0.f ? s.psi[v] : current;
      s.psi[v] = glm::max(base + change, Rgb(0.f));
      s.weight[v] = std::max(s.weight[v], 1.f);
    }
    for (size_t j : result.changed_lights) s.lights[j].intensity *= settings.multiplier;
  });
  return result;
}

} // namespace hilight::painter
