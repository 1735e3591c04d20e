#pragma once
/// Spotlights without hints (issue 10 §3): where the target holds a bright
/// pool that the lights found leave under-lit (a sharp-edged cone point
/// lights cannot paint), propose a spotlight for it. The solver keeps a
/// proposal only when the improvement-ratio rule says it pays.
#include "hilight/light_space.hpp"
#include "hilight/pipeline/samples.hpp"
#include "hilight/renderer.hpp"

#include <optional>
#include <vector>

namespace hilight {

/// The samples of the pool around the sample the fit `lit` under-explains
/// most: linked within `link` of each other, each at least a tenth as bright
/// (luminance) as that sample. Empty when nothing is under-lit.
std::vector<size_t> underlit_pool(const std::vector<Rgb>& lit, const SampleSet& samples, float link);

/// A unit spotlight for `pool`: among free apexes of the light space, aimed
/// at the pool's brightness-weighted centroid, its cutoff just covering the
/// pool; the apex whose spot (direct light, intensities by NNLS beside
/// `base_phi`'s `base_count` lights) explains the samples best, then refined
/// alone (refine_spot).
std::optional<Light> spot_for_pool(const std::vector<size_t>& pool, const SampleSet& samples, const LightSpace& space,
                                   Renderer& renderer, const std::vector<Rgb>& base_phi, size_t base_count);

/// `start` refined alone (position, direction, cutoff, soft edge) by the
/// simplex on its direct light, intensities by NNLS beside the base lights.
Light refine_spot(const Light& start, const SampleSet& samples, const LightSpace& space, Renderer& renderer,
                  const std::vector<Rgb>& base_phi, size_t base_count);

} // namespace hilight
