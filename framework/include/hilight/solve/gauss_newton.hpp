#pragma once
/// The last stretch of refinement: Levenberg–Marquardt over point-light
/// positions (and spots' geometry, if asked) and all intensities together,
/// on the anchored sample problem, with finite-difference Jacobians (one
/// extra response per parameter and iteration, one batch). A simplex stalls
/// in the narrow valleys of lights near surfaces — a ceiling lamp 15 cm
/// below the ceiling moved 6 mm changes its hot spot by 8% — where
/// Gauss–Newton converges in a few steps.
#include "hilight/solve/refine_problem.hpp"

namespace hilight {

struct GaussNewtonSettings {
  int iterations = 12;           ///< Jacobians evaluated at most
  double relative_step = 1e-4;   ///< finite-difference step, fraction of the diagonal
  double min_improvement = 1e-4; ///< stop when an accepted step gains less (relative)
  /// A sample whose response changes by more than this share over one
  /// finite-difference step crosses a shadow edge: it gives no slope.
  double jump = 0.25;
  /// Spots' geometry moves too (position, aim, cutoff, soft edge): the
  /// reference's polish takes them to the bottom of their valley, where the
  /// fast model's refinement left them near it.
  bool move_spots = false;
};

/// Refined `start`: never worse than it by the problem's objective. Spot
/// lights keep their geometry unless `move_spots` (the optimizer refines
/// it); their intensities take part. Intensities stay non-negative and
/// positions admissible.
Lighting gauss_newton_polish(SampleRefineProblem& problem, const Lighting& start, const GaussNewtonSettings& settings = {});

} // namespace hilight
