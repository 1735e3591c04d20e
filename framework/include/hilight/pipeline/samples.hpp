#pragma once
/// Surface samples: the few thousand target points the solve touches
/// (paper §3.2). The sampler draws them with importance: points where the
/// target changes quickly (shadow edges, highlights, painted detail) and
/// points in shadow are drawn more often.
#include "hilight/target.hpp"

#include <cstdint>
#include <vector>

namespace hilight {

struct SampleSet {
  SurfacePoints points;
  std::vector<SurfaceBinding> binding;
  std::vector<Rgb> target;    ///< Ψ at each sample
  std::vector<float> weight;  ///< the target's weight (objective weight)
  std::vector<uint32_t> target_index;

  size_t size() const { return target.size(); }
  /// Appends target point i as a sample.
  void add(const Target& from, uint32_t i);
  /// Weighted ‖Ψ‖ over the samples.
  double target_norm() const;
};

struct SamplerSettings {
  size_t count = 3000;       ///< samples wanted (all points if the target has fewer)
  float contrast_gain = 4.f; ///< importance = weight · (1 + gain · local contrast)
  float shadow_gain = 1.f;   ///< extra importance for points darker than their neighbourhood
  uint64_t seed = 1;
};

/// Importance of every target point (exposed for tests).
std::vector<double> sample_importance(const Target& target, float neighbourhood_radius, const SamplerSettings& settings);

/// Systematic sampling by importance (each point at most once), deterministic for a seed.
SampleSet draw_samples(const Target& target, float neighbourhood_radius, const SamplerSettings& settings);

/// Every target point as a sample (final D̄ over the whole target).
SampleSet all_samples(const Target& target);

} // namespace hilight
