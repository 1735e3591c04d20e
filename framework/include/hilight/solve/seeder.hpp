#pragma once
/// The initial lighting configuration (paper §3.2, Fig. 2): unit lights at the
/// centres of coarse cells in free space, intensities by NNLS, weak lights
/// deleted (eq. 6) and the rest re-solved; cells that kept a light are split
/// into 8 and the spread–solve–delete step repeats.
#include "hilight/solve/responses.hpp"
#include "hilight/light_space.hpp"

namespace hilight {

struct SeedSettings {
  int coarse_cells = 6;         ///< cells along the scene's longest axis at the first level
  int iterations = 2;           ///< levels of spreading (the paper: 2)
  double weak_threshold = 0.05; ///< ε_w of eq. 6
  int residual_rounds = 3;      ///< rounds of candidates placed where the fit is worst (0: the paper's seeding)
  double residual_dbar = 0.05;  ///< ...while the seeding's D̄ is above this
  size_t residual_candidates = 12; ///< places per round (each tried at 4 distances)
};

struct SeedResult {
  Lighting lights;          ///< point lights that survived, with intensities, then the spots
  std::vector<Rgb> phi;     ///< their responses, light-major
  size_t spot_count = 0;    ///< the last spot_count lights are the given spotlights
  double dbar = 0.0;        ///< D̄ at the samples
  size_t lights_tried = 0;  ///< unit lights spread over all levels
};

/// Unit point lights where the fit `lit` (at the samples) leaves the most
/// light unexplained: in front of the worst samples, along their normals, at
/// 0.1–1 `cell_size` (a lamp near a surface paints a hot spot right in front
/// of it); one place per `cell_size`/2, at most `count` places.
Lighting residual_candidates(const std::vector<Rgb>& lit, const SampleSet& samples, const LightSpace& space, float cell_size,
                             size_t count);

/// Centres of a grid (`along_longest` cells on the longest axis of the
/// space's bounds) where a light may stand: placed, admissible, clear of
/// surfaces. Candidate apexes for spotlights.
std::vector<Vec3> free_grid_points(const LightSpace& space, int along_longest);
/// free_grid_points() and, in each room (Regions) that grid barely reaches,
/// places of its own at half that density across the room (as the seeding
/// adds them): a small closed room of a large building gets some.
std::vector<Vec3> free_places_in_every_room(const LightSpace& space, int along_longest);

/// `spots`: spotlights the target asked for (fixed positions/directions);
/// they join every NNLS and are never deleted.
SeedResult seed_lights(ResponseModel& model, const LightSpace& space, const Lighting& spots, const SeedSettings& settings);

} // namespace hilight
