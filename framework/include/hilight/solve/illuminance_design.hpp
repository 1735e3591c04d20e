#pragma once
/// Lights for illuminance criteria (issue 14 §3, issue 34; docs/solve.md,
/// "Illuminance criteria"): how many of a given luminaire, where, turned
/// how and dimmed how much, so that every grid's maintained Ē and U0 are
/// met at the least total flux, in a layout a designer can build.
///
/// 1. Candidates: the luminaire on a lattice over the room where the
///    LightSpace lets it stand (on the ceiling mount, say) and its outline
///    clears the walls, at each spin its profile's symmetry tells apart;
///    their maintained illuminance (× the maintenance factor) at every point
///    from the reference renderer (direct and bounce).
/// 2. A linear program over all candidates' dimming in [0, 1]: minimise
///    Σ flux subject to Ē ≥ lux and E_i ≥ u0·Ē per grid (each with the
///    margin asked for; with a margin, E_i also between the grid's points).
///    Its optimum is the least flux any layout on the lattice can have.
/// 3. Free layouts (the count walk): from the program's lights, the weakest
///    is deleted or merged with its nearest (eq. 7's weighted place), the
///    program solved again; layouts whose luminaires overlap or stand
///    nearer than the minimum spacing are spread apart on the lattice; the
///    fewest lights within `energy_tolerance` of the bound are kept, moved
///    on the lattice where the program's duals say a neighbour is cheaper.
/// 4. Arrays: rows × columns aligned with the room (or on the tiles of a
///    ceiling grid), all dimmed alike; the fewest whose flux is within
///    `energy_tolerance` of the best array's.
/// 5. The array is kept where it costs nothing against the free layout
///    (no more luminaires, no more flux beyond the tolerance); both are
///    reported. The lights found are rendered once more and Ē, Emin, U0
///    and the UGR at the standard observers measured.
#include "hilight/illuminance_criteria.hpp"
#include "hilight/light_space.hpp"
#include "hilight/lighting.hpp"
#include "hilight/solve/luminaire_layout.hpp"
#include "hilight/renderer.hpp"

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hilight {

enum class LayoutChoice { Auto, Array, Free };
const char* to_string(LayoutChoice choice);

struct DesignSettings {
  /// The fewest luminaires whose total flux is within this share of the least possible.
  double energy_tolerance = 0.05;
  /// Lattice step (0: a third of the finest grid's spacing).
  double candidate_spacing = 0;
  size_t min_count = 0, max_count = 0;  ///< 0: no bound
  /// Exactly this many luminaires (--lights N; 0: the design chooses).
  size_t fixed_count = 0;
  /// Maintained illuminance = MF × the new installation's (EN 12464-1's Ēm).
  double maintenance_factor = 0.8;
  /// Every criterion this share clear of its limit: Ē ≥ (1+m)·lux, U0 ≥
  /// (1+m)·u0 with Emin taken on the whole grid (its points and between
  /// them), UGR ≤ (1−m)·limit.
  double margin = 0;
  LayoutChoice layout = LayoutChoice::Auto;
  SpacingRules spacing;
  /// Arrays on a ceiling grid of this tile (m; 0: aligned with the room),
  /// tile corners at `grid_origin` (world x, z, the scene's frame; default:
  /// the room's corner).
  double ceiling_grid = 0;
  std::optional<glm::dvec2> grid_origin;
  /// UGR limit at the standard observers (0: reported only). Needs a
  /// luminaire with a luminous area.
  double ugr_max = 0;
  /// Who the room is for (EN 12464-1): seated people's eyes (the UGR
  /// observers) and cylindrical illuminance at 1.2 m over the floor,
  /// standing people's at 1.6 m.
  enum class Posture { Seated, Standing };
  /// Maintained cylindrical illuminance Ēz at the eyes' height over the
  /// work planes' points at least this (lux; EN 12464-1 asks 50, or 150
  /// where faces must be seen): a row of the program as Ē's (0: reported
  /// only).
  double cylindrical_min = 0;
  Posture posture = Posture::Seated;
  /// A free layout's luminaires may tilt up to this many degrees from
  /// their aim, toward the room's four sides (half and all of it), each
  /// kept only where the layout then meets the criteria with less flux or
  /// fewer luminaires (0: aims as the luminaire's; at most 60). Arrays keep
  /// their aims.
  double tilt_max_deg = 0;
  float eye_height() const { return posture == Posture::Standing ? 1.6f : 1.2f; }
};
const char* to_string(DesignSettings::Posture posture);

/// What one kind of layout came to.
struct LayoutSummary {
  bool tried = false, found = false, met = false;
  size_t count = 0;
  double flux_lm = 0, power_w = 0, shortfall_lux = 0;
  double ugr = 0;  ///< the largest at the observers (NaN: none in view)
  std::string shape;  ///< arrays: "3 × 4 at 3.00 × 3.00 m"
};

struct ObserverGlare {
  GlareObserver observer;
  double ugr = 0;  ///< NaN: no luminaire in view
};

struct DesignReport {
  bool met = false;          ///< every grid's criteria met by the lights found (with the margin), and the UGR limit
  size_t candidates = 0;     ///< lattice places × spins that light some point
  double least_flux_lm = 0;  ///< the program over every candidate: no layout on the lattice needs less
  double flux_lm = 0;        ///< the lights found, at their dimming
  double power_w = 0;        ///< at the profile's rated input (0: the file gives none)
  double shortfall_lux = 0;  ///< when the criteria cannot be met: Σ lux short with every candidate allowed
  double maintenance_factor = 1, margin = 0;
  std::vector<GridFigures> figures;  ///< per grid, maintained, measured on the lights found at the grid's points
  /// Per grid: Emin and Emin/Ē over its points and the points between
  /// them (with a margin; else as at the points).
  std::vector<double> min_whole, u0_whole;
  std::vector<double> lux;           ///< per point, grid after grid (maintained)
  std::vector<double> dimming;       ///< per light, share of the rated output
  std::vector<std::pair<size_t, double>> walk;  ///< (count, flux lm) of each layout kept on the way
  LayoutSummary array, free;
  std::string chosen;  ///< "array" or "free"
  std::string why;     ///< why that one
  std::string unmet;   ///< when not met: why, in a line (empty: met, or the criteria cannot be met at all)
  size_t tilted = 0;  ///< luminaires tilted from their aim (--tilt-max)
  size_t fewest_free = 0;  ///< the fewest free luminaires the walk found meeting the criteria (0: none)
  RoomFrame room;
  glm::vec2 luminaire_size{0.f};  ///< its outline on the ceiling (luminaire_size: the body, or the opening)
  double luminous_area = 0;  ///< m², for luminance (0: the luminaire gives none; no UGR)
  /// EN 12464-1's cylindrical illuminance of the lights found, maintained:
  /// over the work planes' points at `height` over the floor, Ēz (the mean
  /// of four vertical illuminances, facing ±x and ±z: the standard's
  /// approximation), its Emin and U0, and the modelling (Ēz/Ēh, the
  /// horizontal there; EN 12464-1 asks 0.3 to 0.6). `height` is the
  /// posture's eye height; `wanted`: DesignSettings::cylindrical_min, met
  /// (with the margin) when `met`.
  struct Cylindrical {
    double height = 1.2, mean = 0, min = 0, u0 = 0, modelling = 0, wanted = 0;
    size_t points = 0;
    bool met = true;
  } cylindrical;
  std::vector<ObserverGlare> glare;  ///< per observer, the lights found
  double ugr = 0;                    ///< the largest (NaN: none in view or no luminous area)
  std::map<std::string, double> seconds;  ///< per step of the plan (its name), "set-up" and "total"
  std::vector<std::pair<std::string, double>> steps;  ///< the plan's steps as run, in order, with their seconds
};

/// InputError for a maintenance factor outside (0, 1] or a margin outside
/// [0, 1), naming the option (design_for_illuminance checks them too;
/// callers call it first to fail before loading a scene).
void check_design_settings(const DesignSettings& settings);

/// `luminaire`: the template (its profile, aim and spin; a point-like
/// luminaire, or an area source with a profile); the lights returned are
/// copies with position, spin (or `up`) and intensity (dimming × the
/// profile's peak). InputError when no candidate can stand anywhere, or for
/// sizes, spacings and grids that cannot fit the room.
Lighting design_for_illuminance(Renderer& reference, const LightSpace& space, const Light& luminaire,
                                const IlluminanceCriteria& criteria, const DesignSettings& settings, DesignReport& report);

} // namespace hilight
