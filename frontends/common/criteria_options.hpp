#pragma once
/// The options of a solve for illuminance criteria (a .json target) that
/// `hilight solve` and `hilight paint` share: the layout's
/// (solve/criteria_in_scene.hpp). The CLI adds its report's own (the
/// schedule, LENI's inputs) in command_solve_criteria.
#include "hilight/solve/criteria_in_scene.hpp"

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace hilight::cli {

/// A target file is criteria when it is JSON (paint comes as PLY or glTF).
bool is_criteria_target(const std::string& path);

/// --maintenance-factor, --margin, --layout, --ceiling-grid,
/// --ceiling-grid-origin, --min-spacing, --max-spacing-ratio, --ugr-max,
/// --cylindrical-min and --posture into `design`, in `group` ("": the main
/// options).
void add_criteria_design_options(CLI::App& app, CriteriaDesign& design, const std::string& group = "");
/// Their names, as add_criteria_design_options adds them.
const std::vector<std::string>& criteria_design_option_names();
/// InputError naming the first of `names` given on `app`: they work with
/// illuminance criteria (a .json target), not with a painted one.
void refuse_without_criteria(const CLI::App& app, const std::vector<std::string>& names);

/// "a,b[,c]": exactly `count` finite numbers, or InputError naming `option`
/// with `example`.
std::vector<double> comma_numbers(const std::string& text, size_t count, const std::string& option, const std::string& example);

} // namespace hilight::cli
