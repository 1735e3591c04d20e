#include "hilight/pipeline/spot_proposals.hpp"

#include "hilight/pipeline/fit.hpp"
#include "hilight/pipeline/light_parameters.hpp"
#include "hilight/pipeline/seeder.hpp"
#include "hilight/pipeline/simplex.hpp"

#include <algorithm>
#include <cmath>
#include <tbb/parallel_for.h>

namespace hilight {

namespace {

float luminance(const Rgb& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

constexpr float kDegrees = 180.f / 3.14159265f;
/// The soft edge a proposal starts with (the refinement finds the real one).
constexpr float kStartFalloffDeg = 3.f;
/// Apexes tried: grid cells along the light space's longest axis.
constexpr int kApexCells = 12;

/// D̄ of the base lights plus one unit spot (its responses `spot_phi`, m
/// values), intensities by NNLS.
double dbar_with(const std::vector<Rgb>& base_phi, size_t base_count, std::span<const Rgb> spot_phi, const SampleSet& samples) {
  std::vector<Rgb> with = base_phi;
  with.insert(with.end(), spot_phi.begin(), spot_phi.end());
  const std::vector<Rgb> intensities = fit_intensities(with, base_count + 1, samples);
  return normalized_difference(combine(with, intensities, samples.size()), samples);
}

} // namespace

std::vector<size_t> underlit_pool(const std::vector<Rgb>& lit, const SampleSet& samples, float link) {
  const size_t m = samples.size();
  size_t worst = m;
  float worst_missing = 0.f;
  for (size_t i = 0; i < m; ++i) {
    const float missing = samples.weight[i] * luminance(glm::max(samples.target[i] - lit[i], Rgb(0.f)));
    if (missing > worst_missing) worst_missing = missing, worst = i;
  }
  if (worst == m) return {};
  const float floor = luminance(samples.target[worst]) / 10.f;
  const auto& pos = samples.points.positions;
  std::vector<char> in(m, 0);
  std::vector<size_t> pool{worst};
  in[worst] = 1;
  // Breadth-first over bright samples, linked by distance.
  for (size_t head = 0; head < pool.size(); ++head)
    for (size_t i = 0; i < m; ++i)
      if (!in[i] && luminance(samples.target[i]) >= floor && glm::length(pos[i] - pos[pool[head]]) <= link) {
        in[i] = 1;
        pool.push_back(i);
      }
  return pool;
}

namespace {

/// Unit spots for `pool` from each apex that sees its centroid: aimed at
/// it, cutoffs covering 50% to all of the pool's angular radius.
std::vector<Light> aimed_spots(const std::vector<Vec3>& apexes, const std::vector<size_t>& pool, const Vec3& centroid,
                               const SampleSet& samples, const LightSpace& space) {
  const auto& pos = samples.points.positions;
  const RayScene& rays = space.rays();
  std::vector<Light> spots;
  for (const Vec3& apex : apexes) {
    const Vec3 to = centroid - apex;
    const float distance = glm::length(to);
    if (!(distance > 0.f) || !space.admissible(apex) || rays.occluded(apex, to / distance, distance * 0.999f)) continue;
    const Vec3 axis = to / distance;
    float widest = 0.f;
    for (size_t i : pool) {
      const Vec3 d = pos[i] - apex;
      const float len = glm::length(d);
      if (len > 0.f && !rays.occluded(apex, d / len, len * 0.999f))
        widest = std::max(widest, std::acos(std::clamp(glm::dot(axis, d / len), -1.f, 1.f)) * kDegrees);
    }
    // The pool's far edge may be a neighbour's light: narrower cones too.
    if (widest < 85.f)
      for (float share : {0.5f, 0.65f, 0.8f, 0.9f, 1.f})
        spots.push_back(Light::spot(apex, axis, std::clamp(share * widest + kStartFalloffDeg, 2.f, 80.f), Rgb(1.f), kStartFalloffDeg));
  }
  return spots;
}

/// The spot (direct light, NNLS beside the base lights) that explains the samples best.
std::optional<Light> best_spot(const std::vector<Light>& spots, const SampleSet& samples, Renderer& renderer,
                               const std::vector<Rgb>& base_phi, size_t base_count) {
  if (spots.empty()) return std::nullopt;
  const size_t m = samples.size();
  const std::vector<Rgb> phi = renderer.unit_responses(samples.points, spots, Transport::DirectOnly);
  std::vector<double> dbar(spots.size());
  tbb::parallel_for(size_t(0), spots.size(), [&](size_t s) {
    dbar[s] = dbar_with(base_phi, base_count, std::span<const Rgb>(phi).subspan(s * m, m), samples);
  });
  return spots[size_t(std::min_element(dbar.begin(), dbar.end()) - dbar.begin())];
}

} // namespace

std::optional<Light> spot_for_pool(const std::vector<size_t>& pool, const SampleSet& samples, const LightSpace& space,
                                   Renderer& renderer, const std::vector<Rgb>& base_phi, size_t base_count) {
  if (pool.size() < 3) return std::nullopt;
  DVec3 sum(0.0);
  double weight = 0.0;
  for (size_t i : pool) {
    const double w = luminance(samples.target[i]);
    sum += w * DVec3(samples.points.positions[i]), weight += w;
  }
  if (!(weight > 0)) return std::nullopt;
  const Vec3 centroid = Vec3(sum / weight);
  auto spot = best_spot(aimed_spots(free_grid_points(space, kApexCells), pool, centroid, samples, space), samples, renderer,
                        base_phi, base_count);
  // Coarse to fine (as the seeding): apexes around the best, closer each level.
  const Vec3 extent = space.bounds().extent();
  float step = 0.5f * std::max({extent.x, extent.y, extent.z}) / float(kApexCells);
  for (int level = 0; spot && level < 3; ++level, step *= 0.5f) {
    std::vector<Vec3> apexes;
    for (int k = 0; k < 27; ++k) apexes.push_back(spot->position + step * Vec3(float(k % 3 - 1), float(k / 3 % 3 - 1), float(k / 9 - 1)));
    if (auto finer = best_spot(aimed_spots(apexes, pool, centroid, samples, space), samples, renderer, base_phi, base_count)) spot = finer;
  }
  if (spot) spot = refine_spot(*spot, samples, space, renderer, base_phi, base_count);
  return spot;
}

Light refine_spot(const Light& start, const SampleSet& samples, const LightSpace& space, Renderer& renderer,
                  const std::vector<Rgb>& base_phi, size_t base_count) {
  const float scale = space.rays().scene().diagonal();
  auto spot_of = [&](const std::vector<double>& x) {
    Light l = start;
    read_geometry(l, scale, x, 0);
    return l;
  };
  auto objective = [&](const std::vector<double>& x) {
    const Light l = spot_of(x);
    if (!space.admissible(l.position)) return 1e30;
    return dbar_with(base_phi, base_count, renderer.unit_responses(samples.points, std::span<const Light>(&l, 1), Transport::DirectOnly),
                     samples);
  };
  std::vector<double> x, steps;
  append_geometry(start, scale, x, steps);
  for (auto& s : steps) s *= 0.5;  // the screening put it close
  SimplexSettings settings;
  settings.max_evaluations = 300;
  // Restarted once: a fresh simplex escapes a collapsed one.
  for (int restart = 0; restart < 2; ++restart) x = nelder_mead(objective, x, steps, settings).x;
  return spot_of(x);
}

} // namespace hilight
