#include "core/plan_readout.hpp"

#include "hilight/illuminance_criteria.hpp"

#include <array>

namespace hilight::painter {

std::optional<double> lux_below(const RayScene& rays, const std::vector<Rgb>& radiance, const std::vector<Rgb>& albedo,
                                const Vec3& p) {
  const Scene& scene = rays.scene();
  if (radiance.size() != scene.positions.size() || albedo.size() != scene.positions.size()) return std::nullopt;
  const Hit hit = rays.intersect(p, Vec3(0.f, -1.f, 0.f));
  if (!hit.valid()) return std::nullopt;
  const Vec3 at = rays.hit_position(hit);
  uint32_t nearest = scene.triangles[hit.triangle][0];
  for (uint32_t v : scene.triangles[hit.triangle])
    if (glm::length(scene.positions[v] - at) < glm::length(scene.positions[nearest] - at)) nearest = v;
  const Rgb& rho = albedo[nearest];
  Rgb irradiance_over_pi(0.f);
  for (int c = 0; c < 3; ++c) {
    if (!(rho[c] > 0.f)) return std::nullopt;  // a black surface tells nothing of the light on it
    irradiance_over_pi[c] = radiance[nearest][c] / rho[c];
  }
  const std::array<Rgb, 1> one{irradiance_over_pi};
  return lux_from_radiance(one)[0];
}

} // namespace hilight::painter
