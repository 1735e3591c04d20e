#pragma once
/// φ for the solver: the response of unit lights at the samples. Point lights
/// take direct light from the renderer and the bounce from the light cache
/// when there is one (paper §3.4); spotlights, and point lights without a
/// cache, take everything from the renderer.
#include "hilight/solve/samples.hpp"
#include "hilight/renderer.hpp"

#include <atomic>
#include <span>
#include <vector>

namespace hilight {

class LightCacheView;

class ResponseModel {
public:
  ResponseModel(Renderer& renderer, const SampleSet& samples, const LightCacheView* indirect_cache)
      : m_renderer(renderer), m_samples(samples), m_cache(indirect_cache) {}

  const SampleSet& samples() const { return m_samples; }
  /// Light-major: [j * m + i]. Intensities are ignored (unit white).
  std::vector<Rgb> responses(std::span<const Light> lights);
  /// Lights whose φ has been computed so far (a cost measure for reports).
  size_t light_evaluations() const { return m_evaluations; }

private:
  Renderer& m_renderer;
  const SampleSet& m_samples;
  const LightCacheView* m_cache;
  std::atomic<size_t> m_evaluations{0};  ///< refinements of two cuts may run at once
};

} // namespace hilight
