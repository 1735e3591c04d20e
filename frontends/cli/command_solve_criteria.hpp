#pragma once
/// `hilight solve SCENE --target C.json --luminaire L.ies`: lights for
/// illuminance criteria (pipeline/illuminance_design.hpp) instead of paint.
#include "cli_common.hpp"
#include "hilight/light_space.hpp"
#include "hilight/pipeline/illuminance_design.hpp"

#include <optional>
#include <string>

namespace hilight::cli {

struct CriteriaSolve {
  std::string scene_path, target_path, output, report_path, html_path, units_name;
  SceneLoadOptions scene_options;
  bool quiet = false;
  std::optional<Light> luminaire;
  PlacementRules placement;
  DesignSettings design;
  RendererOptions renderer;
};

/// A target file is criteria when it is JSON (paint comes as PLY or glTF).
bool is_criteria_target(const std::string& path);

/// Exit 0 when every grid's criteria are met, 3 when they cannot be (the
/// best lights are still written), 2 for input errors (thrown).
int solve_for_criteria(const CriteriaSolve& a, Registry& registry);

} // namespace hilight::cli
