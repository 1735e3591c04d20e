// hilight solve with illuminance criteria (command_solve_criteria.hpp).
#include "command_solve_criteria.hpp"

#include "hilight/error.hpp"
#include "hilight/io/criteria_file.hpp"
#include "hilight/io/gltf.hpp"
#include "hilight/io/html_report.hpp"
#include "hilight/io/lights_file.hpp"
#include "hilight/threads.hpp"
#include "progress_display.hpp"
#include "hilight/units.hpp"
#include "hilight/scene_origin.hpp"

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

namespace hilight::cli {

bool is_criteria_target(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".json";
}

namespace {

nlohmann::json report_json(const CriteriaSolve& a, const IlluminanceCriteria& criteria, const DesignReport& r, const Lighting& lights) {
  nlohmann::json grids = nlohmann::json::array();
  for (size_t g = 0; g < criteria.grids.size(); ++g) {
    const auto& c = criteria.grids[g];
    const auto& f = r.figures[g];
    grids.push_back({{"name", c.name}, {"kind", to_string(c.kind)}, {"points", c.points.size()}, {"lux_wanted", c.lux},
                     {"u0_wanted", c.u0}, {"mean_lux", f.mean}, {"min_lux", f.min}, {"max_lux", f.max}, {"u0", f.u0}, {"met", f.met}});
  }
  nlohmann::json dimming = nlohmann::json::array(), spins = nlohmann::json::array();
  for (const auto& l : lights) {
    dimming.push_back(luminaire_dimming(l));
    spins.push_back(l.spin_deg);
  }
  nlohmann::json walk = nlohmann::json::array();
  for (const auto& [count, flux] : r.walk) walk.push_back({{"lights", count}, {"flux_lm", flux}});
  return {{"mode", "illuminance criteria"},
          {"criteria", a.target_path},
          {"met", r.met},
          {"lights", lights.size()},
          {"luminaire", a.luminaire->profile_path},
          {"dimming", dimming},
          {"spin_deg", spins},
          {"grids", grids},
          {"total_luminous_flux_lm", r.flux_lm},
          {"least_luminous_flux_lm", r.least_flux_lm},
          {"energy_tolerance", a.design.energy_tolerance},
          {"electrical_power_w", a.luminaire->profile->input_watts > 0 ? nlohmann::json(r.power_w) : nlohmann::json(nullptr)},
          {"candidates", r.candidates},
          {"shortfall_lux", r.shortfall_lux},
          {"count_walk", walk},
          {"placement", a.placement.describe()},
          {"seconds", r.seconds},
          {"length_unit", a.scene_options.unit.empty() ? "m" : a.scene_options.unit},
          {"units", a.units_name},
          {"renderer", a.renderer.name},
          {"bounces", a.renderer.bounces},
          {"bounce_model", bounce_model(a.renderer.bounce_count())}};
}

} // namespace

int solve_for_criteria(const CriteriaSolve& a, Registry& registry) {
  if (!a.luminaire) throw InputError(a.target_path + ": illuminance criteria need --luminaire FILE (the luminaire to place)");
  IlluminanceCriteria criteria = read_criteria(a.target_path);
  set_thread_limit(a.renderer.threads);
  std::optional<ProgressStage> stage(std::in_place, "loading the scene");
  auto scene = std::make_shared<const Scene>(load_scene(a.scene_path, a.scene_options));
  auto rays = RayScene::shared(scene);
  const auto reference = a.renderer.create(registry, scene);
  if (criteria.length_unit != scene->frame.unit)
    throw InputError(a.target_path, "its points are in " + criteria.length_unit + ", the scene in " + scene->frame.unit +
                                        " (--unit " + criteria.length_unit + "?)");
  // Positions read in the world's coordinates, solved in the scene's (scene_origin.hpp).
  for (auto& g : criteria.grids)
    for (auto& p : g.points) p = to_local(p, scene->frame);
  PlacementRules rules = rules_to_local(a.placement, scene->frame);
  // Luminaires for a lux target hang from the ceiling unless told otherwise.
  if (!rules.ceiling_offset && !std::isfinite(rules.min_height) && !std::isfinite(rules.max_height)) rules.add("ceiling");
  DesignSettings settings = a.design;
  settings.min_count = rules.min_count;
  settings.max_count = rules.max_count;
  const LightSpace space(*rays, rules);
  DesignReport report;
  stage.emplace("placing the luminaires");
  const Lighting lights = design_for_illuminance(*reference, space, *a.luminaire, criteria, settings, report);

  stage.emplace("writing " + std::filesystem::path(a.output).filename().string());
  const Units units = parse_units(a.units_name);
  if (is_gltf_path(a.output)) {
    GltfExport gltf;
    gltf.scene = scene.get();
    gltf.lights = lights;
    gltf.figures = {{"lights", double(lights.size())}, {"total_luminous_flux_lm", report.flux_lm}};
    write_gltf(a.output, gltf);
  } else {
    write_lights_file(a.output, lights, units, scene->frame);
  }
  CriteriaSolve with_rules = a;
  with_rules.placement = rules;
  if (!a.report_path.empty()) {
    const std::string text = report_json(with_rules, criteria, report, lights).dump(2) + "\n";
    write_atomically(a.report_path, text);
  }
  if (!a.html_path.empty()) {
    stage.emplace("writing the HTML report");
    HtmlReport page;
    page.scene = scene.get();
    page.rays = rays.get();
    page.title = a.scene_path + " — criteria " + a.target_path;
    page.result = reference->illuminate(SurfacePoints::from_vertices(*scene), lights);
    page.lights = lights;
    page.report.seconds = report.seconds;
    page.units = a.units_name;
    page.criteria = &criteria;
    page.design = report;
    write_html_report(a.html_path, page);
  }
  stage.reset();
  stop_command_progress();  // the bar's line is cleared before the summary
  const std::string name = std::filesystem::path(a.luminaire->profile_path).filename().string();
  if (!a.quiet) {
    for (size_t g = 0; g < criteria.grids.size(); ++g) {
      const auto& c = criteria.grids[g];
      const auto& f = report.figures[g];
      std::fprintf(stderr, "hilight: %s: Ē %.0f lx, Emin %.0f lx, U0 %.2f (wanted Ē ≥ %g, U0 ≥ %g)%s\n", c.name.c_str(), f.mean, f.min,
                   f.u0, c.lux, c.u0, f.met ? "" : "  NOT MET");
    }
    std::string power = a.luminaire->profile->input_watts > 0 ? ", " + std::to_string(int(std::lround(report.power_w))) + " W" : "";
    std::fprintf(stderr, "hilight: %zu luminaire%s (%s, %s), %.0f lm%s (least possible %.0f lm), %s -> %s\n", lights.size(),
                 lights.size() == 1 ? "" : "s", name.c_str(), rules.describe().c_str(), report.flux_lm, power.c_str(),
                 report.least_flux_lm, command_time_summary(report.seconds["total"]).c_str(), a.output.c_str());
  }
  if (!report.met && report.shortfall_lux <= 0) {  // the program met them; the measurement did not
    std::fprintf(stderr, "hilight: %s: the criteria are not met when the lights found are measured (lights written to %s)\n",
                 a.target_path.c_str(), a.output.c_str());
    return 3;
  }
  if (!report.met) {
    std::fprintf(stderr,
                 "hilight: %s: the criteria cannot be met with %s where --place lets it stand (short by %.0f lx over the "
                 "points with every place at full output): a brighter luminaire, or other places (lights written to %s)\n",
                 a.target_path.c_str(), name.c_str(), report.shortfall_lux, a.output.c_str());
    return 3;
  }
  return 0;
}

} // namespace hilight::cli
