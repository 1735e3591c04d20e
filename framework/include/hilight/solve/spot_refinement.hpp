#pragma once
/// Spotlights refined together by Levenberg–Marquardt over their geometry
/// (position, direction, cutoff, soft edge; a point light among them: its
/// position), intensities by NNLS beside fixed
/// base lights (variable projection). A spot's direct light is traced at
/// every step; its bounce, which changes slowly with the cone, is held at a
/// given estimate, so the cone is not stretched to paint its missing bounce.
/// A simplex wanders in a spot's long valley (distance trades against cutoff
/// and intensity); finite-difference Gauss–Newton follows it.
#include "hilight/light_space.hpp"
#include "hilight/solve/fit.hpp"
#include "hilight/solve/samples.hpp"
#include "hilight/renderer.hpp"

#include <vector>

namespace hilight {

/// The cones a refinement keeps a spot's geometry within (here and in the
/// reference's Gauss–Newton polish): a hard edge has no slope between
/// samples, so the softest edge kept is kMinSpotFalloffDeg.
constexpr float kMinSpotCutoffDeg = 1.f, kMaxSpotCutoffDeg = 89.f, kMinSpotFalloffDeg = 0.25f;
/// A spot's cutoff from which it is tried as a point light (the spot
/// search's cones go up to 89°; a downlight's beam is narrower).
constexpr float kWideSpotDeg = 60.f;

struct SpotRefineSettings {
  /// Jacobians evaluated at most. A spot's valley is long and curved: the
  /// steps stay small for a while before it is found, so stopping early
  /// leaves it short (measured: 40 iterations stopping below 1e-5 left a
  /// spot 0.8 m off along its axis, D̄ 1.3%; this finds it exactly).
  int iterations = 100;
  double min_improvement = 1e-7; ///< stop after two accepted steps that gain less (relative)
  /// Squared residuals where the model is brighter than the target count
  /// this many times (intensities by reweighted NNLS): a spot fitted alone
  /// beside others not yet found must not over-light the dark gaps between
  /// their pools to cover them all. 1: plain least squares.
  double over_weight = 1.0;
  /// The soft edge at most this share of the cutoff.
  double max_falloff_share = 1.0;
  /// After Levenberg–Marquardt, a Nelder–Mead simplex of at most this many
  /// evaluations, then Levenberg–Marquardt again (0: none). A shadow edge
  /// sweeping over samples as a lamp moves is a kink the finite differences
  /// leave out, and it can hold the slopes centimetres off.
  int simplex_evaluations = 0;
  /// The simplex's first steps, in finite-difference steps (a position's: a
  /// thousandth of the diagonal).
  double simplex_step = 10.0;
};

/// `lights` where a spot refinement's steps may put them: a step out of the
/// light bounds clamped back a hair inside (the spot slides along the bound
/// instead of stopping there), then placed by the rules; false if one may
/// not stand there.
bool place_within_bounds(const LightSpace& space, Lighting& lights);

/// `spots` refined (never worse by the model below). The model at the
/// samples: base lights (responses `base_phi`, `base_count` of them) plus
/// each spot's traced direct light and its fixed unit `bounce` (light-major,
/// one per spot; empty: none), every intensity by NNLS. The Fit's D̄: the
/// model's at the result (with over_weight: its weighted form).
Fit refine_spots(const Lighting& spots, const std::vector<Rgb>& bounce, const SampleSet& samples, const LightSpace& space,
                 Renderer& renderer, const std::vector<Rgb>& base_phi, size_t base_count, const SpotRefineSettings& settings = {});

} // namespace hilight
