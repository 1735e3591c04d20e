#pragma once
/// Spotlights refined together by Levenberg–Marquardt over their geometry
/// (position, direction, cutoff, soft edge), intensities by NNLS beside fixed
/// base lights (variable projection). A spot's direct light is traced at
/// every step; its bounce, which changes slowly with the cone, is held at a
/// given estimate, so the cone is not stretched to paint its missing bounce.
/// A simplex wanders in a spot's long valley (distance trades against cutoff
/// and intensity); finite-difference Gauss–Newton follows it.
#include "hilight/light_space.hpp"
#include "hilight/pipeline/samples.hpp"
#include "hilight/renderer.hpp"

#include <vector>

namespace hilight {

struct SpotRefineSettings {
  int iterations = 40;           ///< Jacobians evaluated at most
  double min_improvement = 1e-5; ///< stop after two accepted steps that gain less (relative)
};

/// `spots` refined (never worse by the model below). The model at the
/// samples: base lights (responses `base_phi`, `base_count` of them) plus
/// each spot's traced direct light and its fixed unit `bounce` (light-major,
/// one per spot; empty: none), every intensity by NNLS. `dbar` gets the
/// model's D̄ at the result.
Lighting refine_spots(const Lighting& spots, const std::vector<Rgb>& bounce, const SampleSet& samples, const LightSpace& space,
                      Renderer& renderer, const std::vector<Rgb>& base_phi, size_t base_count, double& dbar,
                      const SpotRefineSettings& settings = {});

} // namespace hilight
