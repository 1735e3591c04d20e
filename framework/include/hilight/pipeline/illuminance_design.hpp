#pragma once
/// Lights for illuminance criteria (issue 14 §3; docs/solve.md,
/// "Illuminance criteria"): how many of a given luminaire, where, turned
/// how and dimmed how much, so that every grid's Ē and U0 are met at the
/// least total flux.
///
/// 1. Candidates: the luminaire on a lattice over the criteria's area where
///    the LightSpace lets it stand (on the ceiling mount, say), at each
///    spin its profile's symmetry tells apart; their illuminance at every
///    point from the reference renderer (direct and bounce).
/// 2. A linear program over all candidates' dimming in [0, 1]: minimise
///    Σ flux subject to Ē ≥ lux and E_i ≥ u0·Ē per grid. Its optimum is the
///    least flux any layout on the lattice can have (the bound reported).
/// 3. The count walk: from the program's lights, the weakest is deleted or
///    merged with its nearest (eq. 7's weighted place), the program solved
///    again for the dimming; the fewest lights within `energy_tolerance` of
///    the bound are kept, moved on the lattice where the program's duals say
///    a neighbour is cheaper, and walked down again while they stay within it.
/// 4. The lights found are rendered once more and Ē, Emin, U0 measured.
#include "hilight/illuminance_criteria.hpp"
#include "hilight/light_space.hpp"
#include "hilight/lighting.hpp"
#include "hilight/renderer.hpp"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace hilight {

struct DesignSettings {
  /// The fewest luminaires whose total flux is within this share of the least possible.
  double energy_tolerance = 0.05;
  /// Lattice step (0: a third of the finest grid's spacing).
  double candidate_spacing = 0;
  size_t min_count = 0, max_count = 0;  ///< 0: no bound
};

struct DesignReport {
  bool met = false;          ///< every grid's criteria met by the lights found
  size_t candidates = 0;     ///< lattice places × spins that light some point
  double least_flux_lm = 0;  ///< the program over every candidate: no layout on the lattice needs less
  double flux_lm = 0;        ///< the lights found, at their dimming
  double power_w = 0;        ///< at the profile's rated input (0: the file gives none)
  double shortfall_lux = 0;  ///< when the criteria cannot be met: Σ lux short with every candidate allowed
  std::vector<GridFigures> figures;  ///< per grid, measured on the lights found
  std::vector<double> lux;           ///< per point, grid after grid
  std::vector<std::pair<size_t, double>> walk;  ///< (count, flux lm) of each layout kept on the way
  std::map<std::string, double> seconds;
};

/// `luminaire`: the template (its profile, aim and spin); the lights
/// returned are copies with position, spin and intensity (dimming × the
/// profile's peak). InputError when no candidate can stand anywhere.
Lighting design_for_illuminance(Renderer& reference, const LightSpace& space, const Light& luminaire,
                                const IlluminanceCriteria& criteria, const DesignSettings& settings, DesignReport& report);

} // namespace hilight
