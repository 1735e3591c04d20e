#pragma once
/// A solve for illuminance criteria on a loaded scene, as `hilight solve
/// SCENE --target C.json --luminaire L` and the painter (`hilight paint
/// SCENE --target C.json --luminaire L`) both run it: one path, so the two
/// place the same luminaires.
#include "hilight/illuminance_criteria.hpp"
#include "hilight/light_space.hpp"
#include "hilight/renderer.hpp"
#include "hilight/solve/illuminance_design.hpp"

#include <glm/vec2.hpp>
#include <optional>
#include <string>

namespace hilight {

struct CriteriaDesign {
  DesignSettings settings;
  /// --ceiling-grid-origin: X, Z of a tile corner in the scene file's
  /// coordinates (none: the room's corner).
  std::optional<glm::dvec2> grid_origin_world;
};

/// The luminaire to place for the criteria of file `source`, or InputError
/// naming the file when none was given (--luminaire).
const Light& criteria_luminaire(const std::optional<Light>& luminaire, const std::string& source);

/// Moves `criteria`'s points from the scene file's coordinates into the
/// scene's own (InputError, naming `criteria.source`, when their unit is not
/// the scene's), hangs a lux target's luminaires from the ceiling unless
/// `rules` (the scene's own frame, room names resolved) say where they go
/// (`anywhere` lifts it; `rules` come back with it), takes the rules' count
/// bounds as the design's, and places the luminaires
/// (design_for_illuminance).
Lighting design_in_scene(Renderer& reference, const Scene& scene, const RayScene& rays, IlluminanceCriteria& criteria,
                         PlacementRules& rules, const Light& luminaire, const CriteriaDesign& design, DesignReport& report);

} // namespace hilight
