#pragma once
/// `hilight solve SCENE --target C.json --luminaire L.ies`: lights for
/// illuminance criteria (solve/illuminance_design.hpp) instead of paint.
#include "cli_common.hpp"
#include "criteria_options.hpp"
#include "hilight/light_space.hpp"
#include "hilight/solve/illuminance_design.hpp"

#include <optional>
#include <string>
#include <vector>

namespace hilight::cli {

/// EN 15193-1's inputs for LENI: hours of use by day and night in a year,
/// the constant-illuminance, occupancy and daylight factors, and the
/// parasitic power of controls and emergency lighting (W, standing by the
/// rest of the year).
struct EnergyInputs {
  double day_hours = 2250, night_hours = 250;  ///< EN 15193-1's office
  double fc = 1, fo = 1, fd = 1;
  double parasitic_w = 0;
};

struct CriteriaSolve {
  std::string scene_path, target_path, output, report_path, html_path, units_name, schedule_path;
  SceneLoadOptions scene_options;
  bool quiet = false;
  std::optional<Light> luminaire;
  PlacementRules placement;
  CriteriaDesign design;  ///< the layout's options, as the painter takes them
  RendererOptions renderer;
  EnergyInputs energy;
};

/// .ifc (any case): -o writes the luminaires into a copy of the input IFC.
bool is_ifc_path(const std::string& path);

/// The options only a solve for criteria takes: the layout's
/// (add_criteria_design_options) and the report's (--schedule, LENI's
/// inputs), added to `app`.
void add_criteria_options(CLI::App& app, CriteriaSolve& solve, const std::string& group = "");
/// InputError naming the first of them given when the target is not criteria.
void check_criteria_options(const CLI::App& app, bool criteria_target);

/// Exit 0 when every grid's criteria are met, 3 when they cannot be (the
/// best lights are still written), 2 for input errors (thrown).
int solve_for_criteria(const CriteriaSolve& a, Registry& registry);

} // namespace hilight::cli
