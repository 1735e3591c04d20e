#pragma once
/// Spotlights without hints (issue 10 §3): when point lights cannot explain
/// the target, spots are screened from nothing (spot_screening.hpp), refined
/// with a bounce estimate (spot_refinement.hpp) and kept while each pays by
/// eq. 9. The solver compares the answer with the point lights' answer.
#include "hilight/light_space.hpp"
#include "hilight/solve/fit.hpp"
#include "hilight/solve/judge.hpp"
#include "hilight/solve/samples.hpp"
#include "hilight/renderer.hpp"

#include <vector>

namespace hilight {

struct SpotProposalSettings {
  /// Eq. 9 (ε_impro, ε_w), the visibility floor, the spot split's threshold
  /// (Judge::kSplitSpotDbar) and the most spots (Judge::max_spots()).
  Judge judge;
};

/// Spotlights alone (intensities fitted) that explain the samples' target:
/// screened by `renderer`'s direct light, refined in rounds with the bounce
/// of `reference` taken where the cones stand. A spot whose removal leaves
/// D̄ within ε_impro (and within ε_w of ‖Ψ‖), or below the visible D̄, goes; a
/// spot of kWideSpotDeg or more becomes a point light unless its cone pays
/// (eq. 9); the answer is settled by a simplex, the bounce's spikes left
/// out at the end. The Fit's D̄: at the samples by that model, the bounce
/// taken where the answer stands. No lights when no spot helps.
Fit propose_spots(const SampleSet& samples, const LightSpace& space, Renderer& renderer, Renderer& reference,
                  const SpotProposalSettings& settings);
/// `lights` (spots and point lights, intensities fitted) settled as
/// propose_spots settles its answer: Levenberg–Marquardt and a simplex over
/// every light's geometry, the bounce of `reference` held and re-taken where
/// they went, the best round kept (never worse than `lights`), a round's
/// lights carried on where the rounds head when that fits better
/// (round_extrapolation.hpp), and rounds without the bounce's spikes once
/// they stall. The Fit's D̄: the best's at
/// the samples by that model, its bounce re-taken where it stands.
Fit settle_lights(const SampleSet& samples, const LightSpace& space, Renderer& renderer, Renderer& reference, Lighting lights);

} // namespace hilight
