#pragma once
/// Spotlights without hints (issue 10 §3): when point lights cannot explain
/// the target, spots are screened from nothing (spot_screening.hpp), refined
/// with a bounce estimate (spot_refinement.hpp) and kept while each pays by
/// eq. 9. The solver compares the answer with the point lights' answer.
#include "hilight/light_space.hpp"
#include "hilight/solve/samples.hpp"
#include "hilight/renderer.hpp"

#include <vector>

namespace hilight {

struct SpotProposalSettings {
  size_t max_spots = 4;
  double weak_threshold = 0.05;  ///< ε_w (eq. 6)
  double eps_impro = 1.6;        ///< ε_impro (eq. 9)
  double visible_dbar = 5e-3;    ///< below this D̄ a light more fits noise, not a lamp
  double split_dbar = 0.02;      ///< above this D̄ once the set is built, each spot is tried as two
};

/// Spotlights alone (intensities fitted) that explain the samples' target:
/// screened by `renderer`'s direct light, refined in rounds with the bounce
/// of `reference` taken where the cones stand. A spot whose removal leaves
/// D̄ within ε_impro (and within ε_w of ‖Ψ‖), or below visible_dbar, goes; a
/// spot of kWideSpotDeg or more becomes a point light unless its cone pays
/// (eq. 9); the answer is settled by a simplex, the bounce's spikes left
/// out at the end. `dbar`: D̄ at the samples by that model, the bounce
/// taken where the answer stands. Empty when no spot helps.
Lighting propose_spots(const SampleSet& samples, const LightSpace& space, Renderer& renderer, Renderer& reference,
                       const SpotProposalSettings& settings, double& dbar);

/// `lights` (spots and point lights, intensities fitted) settled as
/// propose_spots settles its answer: Levenberg–Marquardt and a simplex over
/// every light's geometry, the bounce of `reference` held and re-taken where
/// they went, the best round kept (never worse than `lights`), and rounds
/// without the bounce's spikes once they stall. `dbar`: the best's D̄ at the
/// samples by that model, its bounce re-taken where it stands.
Lighting settle_lights(const SampleSet& samples, const LightSpace& space, Renderer& renderer, Renderer& reference, Lighting lights,
                       double& dbar);

} // namespace hilight
