#pragma once
/// The surface samples a solve touches (paper §3.2): a Sampler plugin picks a
/// few thousand of the target's points; the solve's objective sums over them.
#include "hilight/solve/samples.hpp"

#include <cstdint>

namespace hilight {

struct SampleRequest {
  size_t count = 3000;              ///< samples wanted (every point if the target has fewer)
  float neighbourhood_radius = 0.f; ///< scale of "local" for importance (about two tessellation edges)
  uint64_t seed = 1;
};

class Sampler {
public:
  virtual ~Sampler() = default;
  /// Deterministic for a request; each target point at most once.
  virtual SampleSet draw(const Target& target, const SampleRequest& request) = 0;
};

} // namespace hilight
