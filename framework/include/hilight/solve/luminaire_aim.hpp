#pragma once
/// Turning luminaires about their aim for a painted target (`hilight solve
/// --luminaire` with a profile that is not rotationally symmetric): the
/// pipeline places the luminaires as points with the template's spin; this
/// stage then tries, light by light, every spin the profile's symmetry
/// tells apart (distinct_spins), with the intensities re-fitted by NNLS
/// (eq. 5) each time, and keeps a turn only where D̄ at the samples falls.
#include "hilight/solve/fit.hpp"
#include "hilight/solve/samples.hpp"
#include "hilight/renderer.hpp"

namespace hilight {

/// `lights`: luminaires (others are left as they are). Returns them turned
/// and re-fitted, or as given when no turn helps, with D̄ at the samples.
Fit aim_luminaires(Renderer& reference, const SampleSet& samples, Lighting lights);

} // namespace hilight
