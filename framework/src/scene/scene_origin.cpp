// Where a scene sits (scene_origin.hpp).
#include "hilight/scene_origin.hpp"
#include "hilight/io/lights_file.hpp"

#include "hilight/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hilight {

glm::dvec3 recentring_origin(const Bounds& bounds) {
  if (bounds.empty()) return glm::dvec3(0.0);
  const glm::dvec3 lo(bounds.lo), hi(bounds.hi);
  const double size = glm::length(hi - lo);
  if (!(size > 0) || !std::isfinite(size)) return glm::dvec3(0.0);
  // A power of two at least the scene's size: the origin is a multiple of
  // it, so world − origin is exact (both are multiples of the vertices' float
  // step) and small enough for a float to hold it exactly.
  const double step = std::exp2(std::ceil(std::log2(size)));
  const glm::dvec3 centre = 0.5 * (lo + hi);
  return glm::dvec3(std::round(centre.x / step) * step, std::round(centre.y / step) * step, std::round(centre.z / step) * step);
}

double metres_per_unit(const std::string& unit) {
  if (unit == "mm") return 0.001;
  if (unit == "cm") return 0.01;
  if (unit == "m") return 1.0;
  if (unit == "in") return 0.0254;
  if (unit == "ft") return 0.3048;
  throw InputError("--unit " + unit + ": mm, cm, m, in or ft");
}

Lighting lights_from_file(const std::filesystem::path& path, Units units, const Scene& scene) {
  const std::string file = path.string();
  Lighting lights = read_lights_file(path, units, &scene.frame);
  const glm::dvec3 centre = 0.5 * (glm::dvec3(scene.bounds.lo) + glm::dvec3(scene.bounds.hi));
  const double reach = 1e6 * std::max(double(scene.diagonal()), 1.0);  // metres (local)
  for (size_t j = 0; j < lights.size(); ++j) {
    const double distance = glm::length(glm::dvec3(lights[j].position) - centre);
    if (distance <= reach) continue;  // NaN, infinity (from a far world position) and too far fall through
    const glm::dvec3 world = to_world(lights[j].position, scene.frame);
    char text[300];
    std::snprintf(text, sizeof(text), "light %zu at (%g, %g, %g) is %.3g m from the scene, farther than a million times its size (%.3g m): beyond what the renderers trace",
                  j, world.x, world.y, world.z, distance, double(scene.diagonal()));
    throw InputError(file, text);
  }
  return lights;
}

PlacementRules rules_to_local(PlacementRules rules, const SceneFrame& frame) {
  for (auto* list : {&rules.boxes, &rules.excluded})
    for (auto& b : *list) {
      b.lo = to_local(b.lo, frame);
      b.hi = to_local(b.hi, frame);
    }
  rules.min_height = float((double(rules.min_height) - frame.origin.y) * frame.scale);  // ±infinity stays
  rules.max_height = float((double(rules.max_height) - frame.origin.y) * frame.scale);
  if (rules.ceiling_offset) rules.ceiling_offset = length_to_local(*rules.ceiling_offset, frame);
  return rules;
}

PlacementRules rules_to_world(PlacementRules rules, const SceneFrame& frame) {
  for (auto* list : {&rules.boxes, &rules.excluded})
    for (auto& b : *list) {
      b.lo = Vec3(to_world(b.lo, frame));
      b.hi = Vec3(to_world(b.hi, frame));
    }
  rules.min_height = float(double(rules.min_height) / frame.scale + frame.origin.y);  // ±infinity stays
  rules.max_height = float(double(rules.max_height) / frame.scale + frame.origin.y);
  if (rules.ceiling_offset) rules.ceiling_offset = float(double(*rules.ceiling_offset) / frame.scale);
  return rules;
}

} // namespace hilight
