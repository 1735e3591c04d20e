#include "hilight/solve/seeder.hpp"

#include "hilight/solve/fit.hpp"

#include <algorithm>
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

/// Cells whose centre is a valid place for a light (LightSpace: free, the
/// designer's rules; on the ceiling mount if that is the rule), not touching
/// a surface; cells whose places coincide are kept once.
std::vector<Cell> free_cells(const std::vector<Cell>& cells, const LightSpace& space) {
  const RayScene& rays = space.rays();
  std::vector<char> ok(cells.size());
  std::vector<Vec3> placed(cells.size());
  const float clearance = 1e-3f * rays.scene().diagonal();
  tbb::parallel_for(size_t(0), cells.size(), [&](size_t i) {
    const auto p = space.place(cells[i].centre);
    ok[i] = p && space.admissible(*p) &&
            !rays.closest_point(*p, space.clearance(std::max(clearance, 0.05f * cells[i].size))).valid();
    if (p) placed[i] = *p;
  });
  std::vector<Cell> out;
  for (size_t i = 0; i < cells.size(); ++i) {
    if (!ok[i]) continue;
    bool duplicate = false;
    for (const auto& c : out) duplicate |= glm::length(c.centre - placed[i]) < clearance;
    if (!duplicate) out.push_back({placed[i], cells[i].size});
  }
  return out;
}

/// NNLS over point lights `lights` (responses `phi`) plus the spots, eq. 6
/// deletion, re-solve: the surviving point lights, then the spots. `kept`
/// gets the indices of the surviving point lights.
SeedResult fit_and_delete(const Lighting& lights, std::vector<Rgb> phi, const Lighting& spots, const std::vector<Rgb>& spot_phi,
                          const SampleSet& samples, double weak_threshold, std::vector<size_t>& keep) {
  const size_t m = samples.size(), n_points = lights.size();
  const double target_norm = samples.target_norm();
  phi.insert(phi.end(), spot_phi.begin(), spot_phi.end());
  std::vector<Rgb> l = fit_intensities(phi, n_points + spots.size(), samples);
  keep.clear();
  for (size_t j = 0; j < n_points; ++j)
    if (contribution(phi, j, l[j], samples) >= weak_threshold * target_norm) keep.push_back(j);
  if (keep.empty()) {  // nothing is strong alone: keep the strongest rather than nothing
    size_t best = 0;
    double best_c = -1;
    for (size_t j = 0; j < n_points; ++j)
      if (double c = contribution(phi, j, l[j], samples); c > best_c) best_c = c, best = j;
    if (best_c > 0) keep.push_back(best);
  }
  SeedResult result;
  result.phi.reserve((keep.size() + spots.size()) * m);
  for (size_t j : keep) {
    result.phi.insert(result.phi.end(), phi.begin() + std::ptrdiff_t(j * m), phi.begin() + std::ptrdiff_t((j + 1) * m));
    result.lights.push_back(lights[j]);
  }
  result.phi.insert(result.phi.end(), spot_phi.begin(), spot_phi.end());
  for (const auto& s : spots) result.lights.push_back(s);
  std::vector<Rgb> kept_l = fit_intensities(result.phi, result.lights.size(), samples);
  for (size_t j = 0; j < result.lights.size(); ++j) result.lights[j].intensity = kept_l[j];
  result.dbar = normalized_difference(combine(result.phi, kept_l, m), samples);
  return result;
}

/// Beyond the paper: a room the scene-wide grid barely reaches (a small
/// closed room of a large building) gets cells of its own, at a density set
/// by its own size (half the coarse count along its longest axis).
void add_region_cells(std::vector<Cell>& cells, const LightSpace& space, int coarse) {
  constexpr size_t kEnoughCells = 4;
  const Regions& regions = space.regions();
  std::vector<size_t> in_region(regions.list().size(), 0);
  for (const auto& c : cells)
    if (int r = regions.at(c.centre); r >= 0) ++in_region[size_t(r)];
  for (const Region& r : regions.list()) {
    if (in_region[size_t(r.id)] >= kEnoughCells) continue;
    Bounds box;
    box.lo = glm::max(r.box.lo, space.bounds().lo);
    box.hi = glm::min(r.box.hi, space.bounds().hi);
    if (!(box.lo.x < box.hi.x && box.lo.y < box.hi.y && box.lo.z < box.hi.z)) continue;
    for (const auto& c : free_cells(coarse_cells(box, std::max(2, coarse / 2)), space))
      if (regions.at(c.centre) == r.id) cells.push_back(c);
  }
}

} // namespace

Lighting residual_candidates(const std::vector<Rgb>& lit, const SampleSet& samples, const LightSpace& space, float cell_size,
                             size_t count) {
  const RayScene& rays = space.rays();
  const size_t m = samples.size();
  std::vector<std::pair<double, size_t>> order;
  for (size_t i = 0; i < m; ++i) {
    const Rgb missing = glm::max(samples.target[i] - lit[i], Rgb(0.f));
    const double score = double(samples.weight[i]) * glm::dot(DVec3(missing), DVec3(missing));
    if (score > 0) order.emplace_back(-score, i);
  }
  std::sort(order.begin(), order.end());
  std::vector<Vec3> chosen;
  Lighting out;
  const float clearance = 1e-3f * rays.scene().diagonal();
  for (const auto& [score, i] : order) {
    if (chosen.size() >= count) break;
    const Vec3& p = samples.points.positions[i];
    bool apart = true;
    for (const auto& q : chosen) apart &= glm::length(q - p) > 0.5f * cell_size;
    if (!apart) continue;
    chosen.push_back(p);
    for (float d : {0.1f, 0.25f, 0.5f, 1.0f}) {
      const auto c = space.place(p + samples.points.normals[i] * (d * cell_size));
      if (c && space.admissible(*c) && !rays.closest_point(*c, space.clearance(std::max(clearance, 0.5f * d * cell_size))).valid())
        out.push_back(Light::point(*c, Rgb(1.f)));
    }
  }
  return out;
}

std::vector<Vec3> free_grid_points(const LightSpace& space, int along_longest) {
  std::vector<Vec3> out;
  for (const auto& c : free_cells(coarse_cells(space.bounds(), along_longest), space)) out.push_back(c.centre);
  return out;
}

std::vector<Vec3> free_places_in_every_room(const LightSpace& space, int along_longest) {
  std::vector<Cell> cells = free_cells(coarse_cells(space.bounds(), along_longest), space);
  add_region_cells(cells, space, along_longest);
  std::vector<Vec3> out;
  for (const auto& c : cells) out.push_back(c.centre);
  return out;
}

SeedResult seed_lights(ResponseModel& model, const LightSpace& space, const Lighting& spots, const SeedSettings& settings) {
  const SampleSet& samples = model.samples();
  const size_t m = samples.size();
  std::vector<Rgb> spot_phi = spots.empty() ? std::vector<Rgb>{} : model.responses(spots);

  SeedResult result;
  // The spots are part of the answer even if no cell is free for a point light.
  result.lights = spots;
  result.phi = spot_phi;
  std::vector<Cell> cells = free_cells(coarse_cells(space.bounds(), settings.coarse_cells), space);
  float cell_size = cells.empty() ? 0.f : cells.front().size;
  add_region_cells(cells, space, settings.coarse_cells);
  for (int level = 0; level < settings.iterations && !cells.empty(); ++level) {
    Lighting lights;
    for (const auto& c : cells) lights.push_back(Light::point(c.centre, Rgb(1.f)));
    result.lights_tried += lights.size();
    std::vector<Rgb> phi = model.responses(lights);
    std::vector<size_t> keep;
    const size_t tried = result.lights_tried;
    result = fit_and_delete(lights, std::move(phi), spots, spot_phi, samples, settings.weak_threshold, keep);
    result.lights_tried = tried;
    cell_size = cells.front().size;

    if (level + 1 < settings.iterations) {
      std::vector<Cell> children;
      for (size_t j : keep) {
        const Cell& c = cells[j];
        for (int k = 0; k < 8; ++k) {
          Vec3 offset((k & 1 ? 0.25f : -0.25f), (k & 2 ? 0.25f : -0.25f), (k & 4 ? 0.25f : -0.25f));
          children.push_back({c.centre + offset * c.size, 0.5f * c.size});
        }
      }
      cells = free_cells(children, space);
    }
  }
  // Beyond the paper: where the target is still unexplained (a lamp between
  // cell centres, a hot spot no cell centre can paint), add candidates that
  // face those samples and solve again, while D̄ improves.
  const size_t n_spots = spots.size();
  for (int round = 0; round < settings.residual_rounds && result.dbar > settings.residual_dbar && cell_size > 0.f; ++round) {
    std::vector<Rgb> intensities;
    for (const auto& l : result.lights) intensities.push_back(l.intensity);
    Lighting candidates = residual_candidates(combine(result.phi, intensities, m), samples, space, cell_size, settings.residual_candidates);
    if (candidates.empty()) break;
    result.lights_tried += candidates.size();
    Lighting lights(result.lights.begin(), result.lights.end() - std::ptrdiff_t(n_spots));
    std::vector<Rgb> phi(result.phi.begin(), result.phi.end() - std::ptrdiff_t(n_spots * m));
    std::vector<Rgb> candidate_phi = model.responses(candidates);
    lights.insert(lights.end(), candidates.begin(), candidates.end());
    phi.insert(phi.end(), candidate_phi.begin(), candidate_phi.end());
    std::vector<size_t> keep;
    SeedResult next = fit_and_delete(lights, std::move(phi), spots, spot_phi, samples, settings.weak_threshold, keep);
    if (!(next.dbar < 0.95 * result.dbar)) break;
    next.lights_tried = result.lights_tried;
    result = std::move(next);
  }
  result.spot_count = spots.size();
  return result;
}

} // namespace hilight
