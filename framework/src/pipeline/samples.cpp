#include "hilight/pipeline/samples.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace hilight {

void SampleSet::add(const Target& from, uint32_t i) {
  points.positions.push_back(from.points.positions[i]);
  points.normals.push_back(from.points.normals[i]);
  points.albedo.push_back(from.points.albedo[i]);
  binding.push_back(from.binding[i]);
  target.push_back(from.value[i]);
  weight.push_back(from.weight[i]);
  target_index.push_back(i);
}

double SampleSet::target_norm() const {
  double sum = 0;
  for (size_t i = 0; i < target.size(); ++i) sum += weight[i] * glm::dot(DVec3(target[i]), DVec3(target[i]));
  return std::sqrt(sum);
}

namespace {

float luminance(const Rgb& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

/// Uniform hash grid over points, for neighbourhood means.
struct PointGrid {
  float cell;
  std::unordered_map<uint64_t, std::vector<uint32_t>> cells;
  static uint64_t key(int x, int y, int z) {
    return (uint64_t(uint32_t(x) & 0x1FFFFF) << 42) | (uint64_t(uint32_t(y) & 0x1FFFFF) << 21) | uint64_t(uint32_t(z) & 0x1FFFFF);
  }
  glm::ivec3 coord(const Vec3& p) const { return glm::ivec3(glm::floor(p / cell)); }
};

} // namespace

std::vector<double> sample_importance(const Target& target, float radius, const SamplerSettings& settings) {
  const size_t n = target.size();
  PointGrid grid{std::max(radius, 1e-6f), {}};
  for (uint32_t i = 0; i < n; ++i) {
    glm::ivec3 c = grid.coord(target.points.positions[i]);
    grid.cells[PointGrid::key(c.x, c.y, c.z)].push_back(i);
  }
  double mean_lum = 0;
  for (const auto& v : target.value) mean_lum += luminance(v);
  mean_lum = std::max(1e-12, mean_lum / double(n));
  std::vector<double> importance(n);
  const float r2 = radius * radius;
  for (uint32_t i = 0; i < n; ++i) {
    const Vec3& p = target.points.positions[i];
    glm::ivec3 c = grid.coord(p);
    double sum = 0;
    int count = 0;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          auto it = grid.cells.find(PointGrid::key(c.x + dx, c.y + dy, c.z + dz));
          if (it == grid.cells.end()) continue;
          for (uint32_t j : it->second) {
            Vec3 d = target.points.positions[j] - p;
            if (glm::dot(d, d) <= r2) {
              sum += luminance(target.value[j]);
              ++count;
            }
          }
        }
    double local = count ? sum / count : luminance(target.value[i]);
    double lum = luminance(target.value[i]);
    // Contrast relative to the scene's mean, so dark regions' edges count too.
    double contrast = std::min(1.0, std::abs(lum - local) / (0.25 * mean_lum + 0.5 * local));
    double shadow = lum < local ? std::min(1.0, (local - lum) / (local + 1e-12)) : 0.0;
    importance[i] = target.weight[i] * (1.0 + settings.contrast_gain * contrast + settings.shadow_gain * shadow);
  }
  return importance;
}

SampleSet all_samples(const Target& target) {
  SampleSet s;
  s.points = target.points;
  s.binding = target.binding;
  s.target = target.value;
  s.weight = target.weight;
  s.target_index.resize(target.size());
  std::iota(s.target_index.begin(), s.target_index.end(), 0u);
  return s;
}

SampleSet draw_samples(const Target& target, float radius, const SamplerSettings& settings) {
  const size_t n = target.size();
  if (settings.count >= n) return all_samples(target);
  std::vector<double> importance = sample_importance(target, radius, settings);
  // Cap each point's share so that no point can be drawn twice.
  double total = std::accumulate(importance.begin(), importance.end(), 0.0);
  for (int pass = 0; pass < 8; ++pass) {
    double cap = total / double(settings.count);
    double capped = 0;
    for (auto& v : importance) capped += std::min(v, cap);
    for (auto& v : importance) v = std::min(v, cap);
    total = capped;
  }
  const double step = total / double(settings.count);
  // Golden-ratio offset from the seed: deterministic, different per seed.
  double offset = std::fmod(0.5 + 0.6180339887498949 * double(settings.seed), 1.0) * step;
  SampleSet s;
  double cumulative = 0;
  double next = offset;
  for (uint32_t i = 0; i < n && s.size() < settings.count; ++i) {
    cumulative += importance[i];
    if (cumulative > next) {
      s.add(target, i);
      next += step;
    }
  }
  return s;
}

} // namespace hilight
