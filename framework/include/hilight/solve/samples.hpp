#pragma once
/// Surface samples: the few thousand target points the solve touches
/// (paper §3.2), drawn by a Sampler plugin (hilight/sampler.hpp).
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

/// Systematic sampling in proportion to `weights` (one per target point):
/// `count` points, each at most once (weights are capped at total/count),
/// deterministic for a seed. The common core of the sampler plugins.
SampleSet draw_by_weight(const Target& target, std::vector<double> weights, size_t count, uint64_t seed);

/// Every target point as a sample (final D̄ over the whole target).
SampleSet all_samples(const Target& target);

} // namespace hilight
