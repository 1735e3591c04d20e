#include "hilight/solve/samples.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

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

SampleSet draw_by_weight(const Target& target, std::vector<double> importance, size_t count, uint64_t seed) {
  const size_t n = target.size();
  if (count >= n) return all_samples(target);
  // Cap each point's share so that no point can be drawn twice.
  double total = std::accumulate(importance.begin(), importance.end(), 0.0);
  for (int pass = 0; pass < 8; ++pass) {
    double cap = total / double(count);
    double capped = 0;
    for (auto& v : importance) capped += std::min(v, cap);
    for (auto& v : importance) v = std::min(v, cap);
    total = capped;
  }
  const double step = total / double(count);
  // The start from the seed, mixed so every 64-bit seed gives its own.
  uint64_t mixed = seed + 0x9E3779B97F4A7C15ull;
  mixed = (mixed ^ (mixed >> 30)) * 0xBF58476D1CE4E5B9ull;
  mixed = (mixed ^ (mixed >> 27)) * 0x94D049BB133111EBull;
  mixed ^= mixed >> 31;
  double next = double(mixed >> 11) * (1.0 / 9007199254740992.0) * step;
  SampleSet s;
  double cumulative = 0;
  for (uint32_t i = 0; i < n && s.size() < count; ++i) {
    cumulative += importance[i];
    if (cumulative > next) {
      s.add(target, i);
      next += step;
    }
  }
  return s;
}

} // namespace hilight
