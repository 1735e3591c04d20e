// The criteria solve's shared options (criteria_options.hpp).
#include "criteria_options.hpp"

#include "cli_common.hpp"
#include "hilight/error.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace hilight::cli {

bool is_criteria_target(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".json";
}

std::vector<double> comma_numbers(const std::string& text, size_t count, const std::string& option, const std::string& example) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(v)) break;
    out.push_back(v);
  }
  if (out.size() != count || std::count(text.begin(), text.end(), ',') != long(count - 1))
    throw InputError(option + " " + text + ": give " + std::to_string(count) + " numbers separated by commas, e.g. " + example);
  return out;
}

const std::vector<std::string>& criteria_design_option_names() {
  static const std::vector<std::string> names = {"--maintenance-factor", "--margin",      "--layout",            "--ceiling-grid",
                                                 "--ceiling-grid-origin", "--min-spacing", "--max-spacing-ratio", "--ugr-max",
                                                 "--posture", "--cylindrical-min", "--tilt-max"};
  return names;
}

void add_criteria_design_options(CLI::App& app, CriteriaDesign& design, const std::string& group) {
  DesignSettings& s = design.settings;
  app.add_option("--maintenance-factor", s.maintenance_factor,
                 "with criteria: maintained illuminance = MF × new (EN 12464-1's Ēm; in (0, 1])")
      ->capture_default_str();
  app.add_option("--margin", s.margin,
                 "with criteria: keep every criterion this share clear of its limit (0.05: Ē and U0 5% above, Emin also between "
                 "the grid's points, UGR 5% below)")
      ->capture_default_str();
  app.add_option_function<std::string>(
         "--layout",
         [&s](const std::string& v) { s.layout = v == "array" ? LayoutChoice::Array : v == "free" ? LayoutChoice::Free : LayoutChoice::Auto; },
         "with criteria: array (rows × columns aligned with the room, or on --ceiling-grid), free (anywhere on the lattice), "
         "auto (both; the array where it costs nothing; default)")
      ->check(CLI::IsMember({"auto", "array", "free"}));
  app.add_option("--ceiling-grid", s.ceiling_grid, "with criteria: arrays on a ceiling grid of this tile, metres (0.6, 0.625)")
      ->check(CLI::Range(1e-3, 1e3));
  app.add_option_function<std::string>(
      "--ceiling-grid-origin",
      [&design](const std::string& v) {
        const auto n = comma_numbers(v, 2, "--ceiling-grid-origin", "0,0");
        design.grid_origin_world = glm::dvec2(n[0], n[1]);
      },
      "X,Z of a tile corner of --ceiling-grid, in the scene file's coordinates (default: the room's corner)");
  app.add_option("--min-spacing", s.spacing.min_spacing,
                 "with criteria: luminaires' centres at least this far apart, metres (outlines never overlap in any case)")
      ->check(FiniteNonNegative);
  app.add_option("--max-spacing-ratio", s.spacing.max_spacing_ratio,
                 "with criteria: spacing at most this × the mounting height over the work plane (SHR; 0: none)")
      ->check(FiniteNonNegative);
  app.add_option("--ugr-max", s.ugr_max, "with criteria: UGR (CIE 117, standard observers) at most this, e.g. 19")->check(CLI::Range(1.0, 40.0));
  app.add_option("--cylindrical-min", s.cylindrical_min,
                 "with criteria: maintained cylindrical illuminance Ēz at the eyes' height over the work planes at least this, "
                 "lux (EN 12464-1: 50, or 150 where faces must be seen; default: reported only)")
      ->check(CLI::Range(0.0, 1e6));
  app.add_option_function<std::string>(
         "--posture",
         [&s](const std::string& v) { s.posture = v == "standing" ? DesignSettings::Posture::Standing : DesignSettings::Posture::Seated; },
         "with criteria: who the room is for (EN 12464-1): seated (the UGR observers' eyes and the cylindrical illuminance at "
         "1.2 m; default) or standing (1.6 m)")
      ->check(CLI::IsMember({"seated", "standing"}));
  app.add_option("--tilt-max", s.tilt_max_deg,
                 "with criteria: a free layout's luminaires may tilt up to this many degrees from their aim toward the room's "
                 "sides, where that saves flux or luminaires (0: as the luminaire aims; at most 60)")
      ->check(CLI::Range(0.0, 60.0));
  if (!group.empty())
    for (const std::string& name : criteria_design_option_names())
      if (CLI::Option* o = app.get_option_no_throw(name)) o->group(group);
}

void refuse_without_criteria(const CLI::App& app, const std::vector<std::string>& names) {
  for (const std::string& name : names)
    if (app.count(name)) throw InputError(name + " works with illuminance criteria (a .json target), not with a painted target");
}

} // namespace hilight::cli
