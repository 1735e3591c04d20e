#include "hilight/pipeline/seeder.hpp"

#include "hilight/pipeline/fit.hpp"

#include <cmath>
#include <tbb/parallel_for.h>

namespace hilight {

namespace {

struct Cell {
  Vec3 centre;
  float size;
};

std::vector<Cell> coarse_cells(const Bounds& b, int along_longest) {
  Vec3 extent = b.extent();
  float size = std::max(extent.x, std::max(extent.y, extent.z)) / float(std::max(1, along_longest));
  glm::ivec3 n;
  for (int k = 0; k < 3; ++k) n[k] = std::max(1, int(std::ceil(extent[k] / size - 1e-4f)));
  std::vector<Cell> cells;
  // Centre the (possibly larger) grid on the bounds.
  Vec3 origin = b.center() - 0.5f * size * Vec3(n);
  for (int z = 0; z < n.z; ++z)
    for (int y = 0; y < n.y; ++y)
      for (int x = 0; x < n.x; ++x) cells.push_back({origin + size * (Vec3(float(x), float(y), float(z)) + 0.5f), size});
  return cells;
}

/// Cells whose centre is a valid place for a light: in the bounds, out of
/// solid geometry, not touching a surface.
std::vector<Cell> free_cells(const std::vector<Cell>& cells, const RayScene& rays) {
  const Bounds b = rays.scene().light_bounds();
  std::vector<char> ok(cells.size());
  const float clearance = 1e-3f * rays.scene().diagonal();
  tbb::parallel_for(size_t(0), cells.size(), [&](size_t i) {
    const Vec3& p = cells[i].centre;
    ok[i] = b.contains(p) && !rays.inside_solid(p) && !rays.closest_point(p, std::max(clearance, 0.05f * cells[i].size)).valid();
  });
  std::vector<Cell> out;
  for (size_t i = 0; i < cells.size(); ++i)
    if (ok[i]) out.push_back(cells[i]);
  return out;
}

} // namespace

SeedResult seed_lights(ResponseModel& model, const RayScene& rays, const Lighting& spots, const SeedSettings& settings) {
  const SampleSet& samples = model.samples();
  const size_t m = samples.size();
  const double target_norm = samples.target_norm();
  std::vector<Rgb> spot_phi = spots.empty() ? std::vector<Rgb>{} : model.responses(spots);

  SeedResult result;
  // The spots are part of the answer even if no cell is free for a point light.
  result.lights = spots;
  result.phi = spot_phi;
  std::vector<Cell> cells = free_cells(coarse_cells(rays.scene().light_bounds(), settings.coarse_cells), rays);
  for (int level = 0; level < settings.iterations && !cells.empty(); ++level) {
    Lighting lights;
    for (const auto& c : cells) lights.push_back(Light::point(c.centre, Rgb(1.f)));
    result.lights_tried += lights.size();
    std::vector<Rgb> phi = model.responses(lights);
    phi.insert(phi.end(), spot_phi.begin(), spot_phi.end());
    const size_t n_points = lights.size();
    std::vector<Rgb> l = fit_intensities(phi, n_points + spots.size(), samples);

    // Eq. 6: drop point lights contributing less than ε_w of ‖Ψ‖, then re-solve.
    std::vector<size_t> keep;
    for (size_t j = 0; j < n_points; ++j)
      if (contribution(phi, j, l[j], samples) >= settings.weak_threshold * target_norm) keep.push_back(j);
    if (keep.empty()) {  // nothing is strong alone: keep the strongest rather than nothing
      size_t best = 0;
      double best_c = -1;
      for (size_t j = 0; j < n_points; ++j)
        if (double c = contribution(phi, j, l[j], samples); c > best_c) best_c = c, best = j;
      if (best_c > 0) keep.push_back(best);
    }
    std::vector<Rgb> kept_phi;
    kept_phi.reserve((keep.size() + spots.size()) * m);
    result.lights.clear();
    for (size_t j : keep) {
      kept_phi.insert(kept_phi.end(), phi.begin() + std::ptrdiff_t(j * m), phi.begin() + std::ptrdiff_t((j + 1) * m));
      result.lights.push_back(lights[j]);
    }
    kept_phi.insert(kept_phi.end(), spot_phi.begin(), spot_phi.end());
    for (const auto& s : spots) result.lights.push_back(s);
    std::vector<Rgb> kept_l = fit_intensities(kept_phi, result.lights.size(), samples);
    for (size_t j = 0; j < result.lights.size(); ++j) result.lights[j].intensity = kept_l[j];
    result.phi = std::move(kept_phi);
    result.dbar = normalized_difference(combine(result.phi, kept_l, m), samples);

    if (level + 1 < settings.iterations) {
      std::vector<Cell> children;
      for (size_t j : keep) {
        const Cell& c = cells[j];
        for (int k = 0; k < 8; ++k) {
          Vec3 offset((k & 1 ? 0.25f : -0.25f), (k & 2 ? 0.25f : -0.25f), (k & 4 ? 0.25f : -0.25f));
          children.push_back({c.centre + offset * c.size, 0.5f * c.size});
        }
      }
      cells = free_cells(children, rays);
    }
  }
  result.spot_count = spots.size();
  return result;
}

} // namespace hilight
