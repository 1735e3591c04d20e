// The criteria solve on a loaded scene (criteria_in_scene.hpp).
#include "hilight/solve/criteria_in_scene.hpp"

#include "hilight/error.hpp"
#include "hilight/scene.hpp"
#include "hilight/scene_origin.hpp"

#include <cmath>
#include <string>

namespace hilight {

const Light& criteria_luminaire(const std::optional<Light>& luminaire, const std::string& source) {
  if (!luminaire) throw InputError(source + ": illuminance criteria need --luminaire FILE (the luminaire to place)");
  return *luminaire;
}

Lighting design_in_scene(Renderer& reference, const Scene& scene, const RayScene& rays, IlluminanceCriteria& criteria,
                         PlacementRules& rules, const Light& luminaire, const CriteriaDesign& design, DesignReport& report) {
  if (criteria.length_unit != scene.frame.unit)
    throw InputError(criteria.source, "its points are in " + criteria.length_unit + ", the scene in " + scene.frame.unit +
                                          " (--unit " + criteria.length_unit + "?)");
  // Positions read in the world's coordinates, solved in the scene's (scene_origin.hpp).
  for (auto& g : criteria.grids)
    for (auto& p : g.points) p = to_local(p, scene.frame);
  // Luminaires for a lux target hang from the ceiling unless told otherwise (--place anywhere lifts it).
  if (!rules.anywhere && !rules.ceiling_offset && !std::isfinite(rules.min_height) && !std::isfinite(rules.max_height)) rules.add("ceiling");
  DesignSettings settings = design.settings;
  settings.min_count = rules.min_count;
  settings.max_count = rules.max_count;
  if (design.grid_origin_world) {
    const Vec3 o = to_local(glm::dvec3(design.grid_origin_world->x, 0.0, design.grid_origin_world->y), scene.frame);
    settings.grid_origin = glm::dvec2(o.x, o.z);
  }
  const LightSpace space(rays, rules);
  return design_for_illuminance(reference, space, luminaire, criteria, settings, report);
}

} // namespace hilight
