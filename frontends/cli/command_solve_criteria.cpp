// hilight solve with illuminance criteria (command_solve_criteria.hpp).
#include "command_solve_criteria.hpp"

#include "ifc_luminaires.hpp"
#include "ifc_spaces.hpp"

#include "hilight/error.hpp"
#include "hilight/io/criteria_file.hpp"
#include "hilight/io/gltf.hpp"
#include "hilight/io/html_report.hpp"
#include "hilight/io/lights_file.hpp"
#include "hilight/threads.hpp"
#include "progress_display.hpp"
#include "hilight/units.hpp"
#include "hilight/scene_origin.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include "hilight/solve/criteria_in_scene.hpp"
#include "hilight/solve/solve_session.hpp"

namespace hilight::cli {

bool is_ifc_path(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".ifc";
}

namespace {

/// The report's options add_criteria_options adds (the layout's: criteria_options.hpp).
const std::vector<std::string> kReportOptions = {"--schedule", "--operating-hours", "--leni-factors", "--parasitic-power"};

std::string product_of(const Light& luminaire) {
  if (luminaire.profile && !luminaire.profile->product.empty()) return luminaire.profile->product;
  return std::filesystem::path(luminaire.profile_path).filename().string();
}

nlohmann::json finite_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json summary_json(const LayoutSummary& s) {
  if (!s.found) return {{"tried", s.tried}, {"found", false}};
  nlohmann::json j = {{"tried", s.tried},       {"found", true},          {"met", s.met},
                      {"luminaires", s.count},  {"luminous_flux_lm", s.flux_lm}, {"power_w", s.power_w},
                      {"shortfall_lux", s.shortfall_lux}, {"ugr", finite_or_null(s.ugr)}};
  if (!s.shape.empty()) j["shape"] = s.shape;
  return j;
}

/// Energy per EN 15193-1 (LENI) from the floor and the power: as designed
/// (each luminaire at its dimming, set once at commissioning) and installed
/// (every luminaire at full power, the standard's Pn).
struct Energy {
  double area = 0, power = 0, installed = 0, density = 0, installed_density = 0, leni = 0, installed_leni = 0;
};
Energy energy_of(const CriteriaSolve& a, const DesignReport& r, size_t count) {
  Energy e;
  e.area = r.room.floor_area;
  e.power = r.power_w;
  e.installed = double(count) * a.luminaire->profile->input_watts;
  if (e.area > 0) {
    e.density = e.power / e.area;
    e.installed_density = e.installed / e.area;
    const EnergyInputs& in = a.energy;
    const double hours = in.fc * (in.day_hours * in.fo * in.fd + in.night_hours * in.fo) / 1000.0;  // kWh per W
    const double parasitic = in.parasitic_w * std::max(0.0, 8760.0 - in.day_hours - in.night_hours) / 1000.0;
    e.leni = (e.power * hours + parasitic) / e.area;
    e.installed_leni = (e.installed * hours + parasitic) / e.area;
  }
  return e;
}

nlohmann::json luminaires_json(const CriteriaSolve& a, const DesignReport& r, const Lighting& lights, const SceneFrame& frame) {
  nlohmann::json out = nlohmann::json::array();
  const Photometry& p = *a.luminaire->profile;
  for (size_t j = 0; j < lights.size(); ++j) {
    const glm::dvec3 w = to_world(lights[j].position, frame);
    const double d = j < r.dimming.size() ? r.dimming[j] : luminaire_dimming(lights[j]);
    out.push_back({{"index", j + 1},
                   {"product", product_of(*a.luminaire)},
                   {"file", a.luminaire->profile_path},
                   {"position", {w.x, w.y, w.z}},
                   {"aim", {lights[j].direction.x, lights[j].direction.y, lights[j].direction.z}},
                   {"spin_deg", lights[j].spin_deg},
                   {"dimming_percent", 100.0 * d},
                   {"luminous_flux_lm", d * p.flux()},
                   {"power_w", p.input_watts > 0 ? nlohmann::json(d * p.input_watts) : nlohmann::json(nullptr)}});
  }
  return out;
}

/// The design's plan as run: each step's name and seconds, in order.
nlohmann::json steps_json(const DesignReport& r) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& [name, seconds] : r.steps) out.push_back({{"name", name}, {"seconds", seconds}});
  return out;
}

nlohmann::json report_json(const CriteriaSolve& a, const IlluminanceCriteria& criteria, const DesignReport& r, const Lighting& lights,
                           const SceneFrame& frame) {
  nlohmann::json grids = nlohmann::json::array();
  for (size_t g = 0; g < criteria.grids.size(); ++g) {
    const auto& c = criteria.grids[g];
    const auto& f = r.figures[g];
    grids.push_back({{"name", c.name}, {"kind", to_string(c.kind)}, {"points", c.points.size()}, {"lux_wanted", c.lux},
                     {"u0_wanted", c.u0}, {"mean_lux", f.mean}, {"min_lux", f.min}, {"max_lux", f.max}, {"u0", f.u0},
                     {"min_lux_whole_grid", r.min_whole[g]}, {"u0_whole_grid", r.u0_whole[g]}, {"met", f.met}});
  }
  nlohmann::json dimming = nlohmann::json::array(), spins = nlohmann::json::array();
  for (size_t j = 0; j < lights.size(); ++j) {
    dimming.push_back(j < r.dimming.size() ? r.dimming[j] : luminaire_dimming(lights[j]));
    spins.push_back(lights[j].spin_deg);
  }
  nlohmann::json walk = nlohmann::json::array();
  for (const auto& [count, flux] : r.walk) walk.push_back({{"lights", count}, {"flux_lm", flux}});
  nlohmann::json observers = nlohmann::json::array();
  for (const auto& o : r.glare) {
    const glm::dvec3 eye = to_world(o.observer.eye, frame);
    observers.push_back({{"name", o.observer.name}, {"eye", {eye.x, eye.y, eye.z}},
                         {"view", {o.observer.view.x, o.observer.view.y, o.observer.view.z}}, {"ugr", finite_or_null(o.ugr)}});
  }
  const Energy e = energy_of(a, r, lights.size());
  const bool watts = a.luminaire->profile->input_watts > 0;
  return {{"mode", "illuminance criteria"},
          {"criteria", a.target_path},
          {"met", r.met},
          {"unmet", r.unmet.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.unmet)},
          {"lights", lights.size()},
          {"lights_asked", a.design.settings.fixed_count ? nlohmann::json(a.design.settings.fixed_count) : nlohmann::json(nullptr)},
          {"luminaire", a.luminaire->profile_path},
          {"product", product_of(*a.luminaire)},
          {"luminaire_size_m", {r.luminaire_size[0], r.luminaire_size[1]}},
          {"maintenance_factor", r.maintenance_factor},
          {"margin", r.margin},
          {"dimming", dimming},
          {"spin_deg", spins},
          {"luminaires", luminaires_json(a, r, lights, frame)},
          {"grids", grids},
          {"layout", {{"asked", to_string(a.design.settings.layout)}, {"chosen", r.chosen}, {"why", r.why},
                      {"array", summary_json(r.array)}, {"free", summary_json(r.free)},
                      {"ceiling_grid_m", a.design.settings.ceiling_grid > 0 ? nlohmann::json(a.design.settings.ceiling_grid) : nlohmann::json(nullptr)},
                      {"min_spacing_m", a.design.settings.spacing.min_spacing},
                      {"max_spacing_ratio", a.design.settings.spacing.max_spacing_ratio > 0 ? nlohmann::json(a.design.settings.spacing.max_spacing_ratio)
                                                                                    : nlohmann::json(nullptr)},
                      {"fewest_free_meeting", r.fewest_free ? nlohmann::json(r.fewest_free) : nlohmann::json(nullptr)}}},
          {"room", {{"length_m", r.room.length()}, {"width_m", r.room.width()}, {"axis", {r.room.u.x, r.room.u.z}},
                    {"floor_area_m2", r.room.floor_area}}},
          {"ugr", {{"max", finite_or_null(r.ugr)}, {"limit", a.design.settings.ugr_max > 0 ? nlohmann::json(a.design.settings.ugr_max) : nlohmann::json(nullptr)},
                   {"luminous_area_m2", r.luminous_area}, {"observers", observers}}},
          {"posture", to_string(a.design.settings.posture)},
          {"cylindrical", {{"height_m", r.cylindrical.height}, {"min_mean_lux_wanted", r.cylindrical.wanted > 0 ? nlohmann::json(r.cylindrical.wanted) : nlohmann::json(nullptr)},
                           {"met", r.cylindrical.met}, {"points", r.cylindrical.points}, {"mean_lux", r.cylindrical.mean},
                           {"min_lux", r.cylindrical.min}, {"u0", r.cylindrical.u0}, {"modelling", r.cylindrical.modelling}}},
          {"energy", {{"floor_area_m2", e.area}, {"power_w", watts ? nlohmann::json(e.power) : nlohmann::json(nullptr)},
                      {"installed_power_w", watts ? nlohmann::json(e.installed) : nlohmann::json(nullptr)},
                      {"power_density_w_m2", watts && e.area > 0 ? nlohmann::json(e.density) : nlohmann::json(nullptr)},
                      {"installed_power_density_w_m2", watts && e.area > 0 ? nlohmann::json(e.installed_density) : nlohmann::json(nullptr)},
                      {"leni_kwh_m2_a", watts && e.area > 0 ? nlohmann::json(e.leni) : nlohmann::json(nullptr)},
                      {"installed_leni_kwh_m2_a", watts && e.area > 0 ? nlohmann::json(e.installed_leni) : nlohmann::json(nullptr)},
                      {"hours_day", a.energy.day_hours}, {"hours_night", a.energy.night_hours}, {"fc", a.energy.fc},
                      {"fo", a.energy.fo}, {"fd", a.energy.fd}, {"parasitic_w", a.energy.parasitic_w}}},
          {"total_luminous_flux_lm", r.flux_lm},
          {"least_luminous_flux_lm", r.least_flux_lm},
          {"energy_tolerance", a.design.settings.energy_tolerance},
          {"electrical_power_w", watts ? nlohmann::json(r.power_w) : nlohmann::json(nullptr)},
          {"candidates", r.candidates},
          {"tilt_max_deg", a.design.settings.tilt_max_deg},
          {"tilted", r.tilted},
          {"shortfall_lux", r.shortfall_lux},
          {"count_walk", walk},
          {"placement", a.placement.describe()},
          {"seconds", r.seconds},
          {"steps", steps_json(r)},
          {"length_unit", frame.unit},
          {"units", a.units_name},
          {"renderer", a.renderer.name},
          {"bounces", a.renderer.bounces},
          {"bounce_model", bounce_model(a.renderer.bounce_count())}};
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

/// The luminaire schedule: one row per luminaire, positions in the scene file's unit.
std::string schedule_csv(const CriteriaSolve& a, const DesignReport& r, const Lighting& lights, const SceneFrame& frame) {
  std::ostringstream out;
  out.precision(10);
  const Photometry& p = *a.luminaire->profile;
  out << "index,product,file,x_" << frame.unit << ",y_" << frame.unit << ",z_" << frame.unit
      << ",aim_x,aim_y,aim_z,spin_deg,dimming_percent,luminous_flux_lm,power_w\r\n";
  for (size_t j = 0; j < lights.size(); ++j) {
    const glm::dvec3 w = to_world(lights[j].position, frame);
    const double d = j < r.dimming.size() ? r.dimming[j] : luminaire_dimming(lights[j]);
    char numbers[256];
    std::snprintf(numbers, sizeof(numbers), "%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.2f,%.2f,%.1f,", w.x, w.y, w.z, double(lights[j].direction.x),
                  double(lights[j].direction.y), double(lights[j].direction.z), double(lights[j].spin_deg), 100.0 * d, d * p.flux());
    out << j + 1 << ',' << csv_field(product_of(*a.luminaire)) << ',' << csv_field(a.luminaire->profile_path) << ',' << numbers;
    if (p.input_watts > 0) {
      char w_text[32];
      std::snprintf(w_text, sizeof(w_text), "%.2f", d * p.input_watts);
      out << w_text;
    }
    out << "\r\n";
  }
  return out.str();
}

} // namespace

void add_criteria_options(CLI::App& app, CriteriaSolve& c, const std::string& group) {
  add_criteria_design_options(app, c.design, group);
  struct Grouped {  // the report's options in `group` too (when given)
    CLI::App& app;
    const std::string& group;
    ~Grouped() {
      if (group.empty()) return;
      for (const std::string& name : kReportOptions)
        if (CLI::Option* o = app.get_option_no_throw(name)) o->group(group);
    }
  } grouped{app, group};
  app.add_option("--schedule", c.schedule_path, "with criteria: write the luminaire schedule here (CSV: product, position, aim, dimming, lm, W)");
  app.add_option_function<std::string>(
      "--operating-hours",
      [&c](const std::string& v) {
        const auto n = comma_numbers(v, 2, "--operating-hours", "2250,250");
        if (n[0] < 0 || n[1] < 0 || n[0] + n[1] > 8760) throw InputError("--operating-hours " + v + ": day and night hours within one year (8760)");
        c.energy.day_hours = n[0], c.energy.night_hours = n[1];
      },
      "with criteria: LENI's hours of use a year by day and by night, tD,tN (EN 15193-1; default 2250,250)");
  app.add_option_function<std::string>(
      "--leni-factors",
      [&c](const std::string& v) {
        const auto n = comma_numbers(v, 3, "--leni-factors", "1,1,1");
        for (double f : n)
          if (!(f >= 0 && f <= 1)) throw InputError("--leni-factors " + v + ": FC, FO and FD are each in [0, 1]");
        c.energy.fc = n[0], c.energy.fo = n[1], c.energy.fd = n[2];
      },
      "with criteria: EN 15193-1's constant illuminance, occupancy and daylight factors FC,FO,FD (default 1,1,1)");
  app.add_option("--parasitic-power", c.energy.parasitic_w,
                 "with criteria: W of controls and emergency lighting on standby the rest of the year (LENI's parasitic energy)")
      ->check(FiniteNonNegative);
}

void check_criteria_options(const CLI::App& app, bool criteria_target) {
  if (criteria_target) return;
  refuse_without_criteria(app, criteria_design_option_names());
  refuse_without_criteria(app, kReportOptions);
}

int solve_for_criteria(const CriteriaSolve& a, Registry& registry) {
  criteria_luminaire(a.luminaire, a.target_path);
  check_design_settings(a.design.settings);
  if (!a.schedule_path.empty()) check_writable(a.schedule_path);
  if (is_ifc_path(a.output)) {  // the luminaires into a copy of the input IFC
    if (!is_ifc_path(a.scene_path))
      throw InputError("-o " + a.output + ": IFC output is a copy of the input IFC with the luminaires added; the scene " + a.scene_path +
                       " is not an .ifc file (write .json or .glb)");
    if (!ifc_output_available())
      throw InputError(a.output, "IFC output needs IfcPlusPlus, which this build lacks (apt install libifcplusplus-dev libboost-dev, then cmake again)");
  }
  IlluminanceCriteria criteria = read_criteria(a.target_path);
  set_thread_limit(a.renderer.threads);
  std::optional<ProgressStage> stage(std::in_place, "loading the scene");
  auto scene = std::make_shared<const Scene>(load_scene(a.scene_path, a.scene_options));
  auto rays = RayScene::shared(scene);
  // The renderer as every solve assembles it (SolveSession: the user's
  // settings and the solve's seed); the design needs its reference alone.
  SolveSpec spec;
  spec.renderer = a.renderer.name;
  spec.renderer_settings = a.renderer.assignments(&registry);
  spec.cache = PluginDefaults::no_cache;
  SolveSession session(registry, spec, scene, rays);
  a.renderer.note_bounces(registry);
  Renderer& reference = session.reference();
  PlacementRules rules = rules_to_local(a.placement, scene->frame);
  rules.resolve_room_names(scene_rooms(a.scene_path, rules, *rays));
  DesignReport report;
  stage.emplace("placing the luminaires");
  const Lighting lights = design_in_scene(reference, *scene, *rays, criteria, rules, *a.luminaire, a.design, report);

  stage.emplace("writing " + std::filesystem::path(a.output).filename().string());
  const Units units = parse_units(a.units_name);
  IfcWritten ifc;
  if (is_ifc_path(a.output)) {
    std::vector<IfcLuminaire> fixtures;
    const Photometry& p = *a.luminaire->profile;
    for (size_t j = 0; j < lights.size(); ++j) {
      IfcLuminaire f;
      f.position = to_world(lights[j].position, scene->frame) * scene->frame.scale;  // metres
      f.aim = glm::dvec3(lights[j].direction);
      const Vec3 axis = length_axis(lights[j]);
      f.spin_deg = std::atan2(-double(axis.z), double(axis.x)) * 180.0 / kPi;
      f.size = glm::dvec2(luminaire_size(lights[j]));
      f.product = product_of(*a.luminaire);
      f.profile = a.luminaire->profile_path;
      f.dimming = j < report.dimming.size() ? report.dimming[j] : luminaire_dimming(lights[j]);
      f.flux_lm = f.dimming * p.flux();
      f.power_w = f.dimming * p.input_watts;
      fixtures.push_back(f);
    }
    ifc = write_ifc_luminaires(a.scene_path, a.output, fixtures);
  } else if (is_gltf_path(a.output)) {
    GltfExport gltf;
    gltf.scene = scene.get();
    gltf.lights = lights;
    gltf.figures = {{"lights", double(lights.size())}, {"total_luminous_flux_lm", report.flux_lm}, {"maintenance_factor", report.maintenance_factor}};
    if (a.luminaire->profile->input_watts > 0) gltf.figures["electrical_power_w"] = report.power_w;
    write_gltf(a.output, gltf);
  } else {
    write_lights_file(a.output, lights, units, scene->frame);
  }
  CriteriaSolve with_rules = a;
  with_rules.placement = rules;
  if (!a.report_path.empty()) {
    const std::string text = report_json(with_rules, criteria, report, lights, scene->frame).dump(2) + "\n";
    write_atomically(a.report_path, text);
  }
  if (!a.schedule_path.empty()) write_atomically(a.schedule_path, schedule_csv(a, report, lights, scene->frame));
  if (!a.html_path.empty()) {
    stage.emplace("writing the HTML report");
    HtmlReport page;
    page.scene = scene.get();
    page.rays = rays.get();
    page.title = a.scene_path + " — criteria " + a.target_path;
    page.result = reference.illuminate(SurfacePoints::from_vertices(*scene), lights);
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
  const Energy energy = energy_of(a, report, lights.size());
  // A luminaire without a size (an IES file with no opening, nothing else
  // given) keeps no distance from its neighbours but the lattice's.
  if (report.luminaire_size == glm::vec2(0.f) && !(a.design.settings.spacing.min_spacing > 0) && lights.size() > 1)
    std::fprintf(stderr,
                 "hilight: warning: %s gives the luminaire no size (no luminous opening or body): luminaires may stand as close as "
                 "the lattice of places; give --luminaire-size W,L or --min-spacing\n",
                 name.c_str());
  if (!a.quiet) {
    for (size_t g = 0; g < criteria.grids.size(); ++g) {
      const auto& c = criteria.grids[g];
      const auto& f = report.figures[g];
      std::string between, margin;
      if (report.margin > 0) {
        char text[96];
        std::snprintf(text, sizeof(text), ", U0 %.2f with the points between", report.u0_whole[g]);
        between = text;
        std::snprintf(text, sizeof(text), ", each %g%% clear", 100 * report.margin);
        margin = text;
      }
      std::fprintf(stderr, "hilight: %s: maintained Ē %.0f lx, Emin %.0f lx, U0 %.2f%s (wanted Ē ≥ %g, U0 ≥ %g%s)%s\n", c.name.c_str(),
                   f.mean, f.min, f.u0, between.c_str(), c.lux, c.u0, margin.c_str(), f.met ? "" : "  NOT MET");
    }
    const auto layout_line = [&](const char* kind, const LayoutSummary& s) {
      std::string text = std::string(kind) + " ";
      if (!s.found) return text + (s.tried ? "none fits" : "not tried");
      if (!s.shape.empty()) text += s.shape + ", ";
      text += std::to_string(s.count) + " luminaire" + (s.count == 1 ? "" : "s");
      if (a.luminaire->profile->input_watts > 0) text += ", " + std::to_string(int(std::lround(s.power_w))) + " W";
      if (!s.met) text += " (not met)";
      return text;
    };
    std::fprintf(stderr, "hilight: layouts: %s; %s; kept: %s (%s)\n", layout_line("array", report.array).c_str(),
                 layout_line("free", report.free).c_str(), report.chosen.c_str(), report.why.c_str());
    if (report.cylindrical.points) {
      std::string wanted;
      if (report.cylindrical.wanted > 0) {
        char w[96];
        std::snprintf(w, sizeof(w), " (wanted Ēz ≥ %g%s)", report.cylindrical.wanted, report.cylindrical.met ? "" : ", NOT MET");
        wanted = w;
      }
      std::fprintf(stderr, "hilight: cylindrical Ēz %.0f lx at %.1f m (Emin %.0f lx, U0 %.2f), modelling Ēz/Ēh %.2f%s\n",
                   report.cylindrical.mean, report.cylindrical.height, report.cylindrical.min, report.cylindrical.u0,
                   report.cylindrical.modelling, wanted.c_str());
    }
    if (report.luminous_area > 0) {
      char text[160];
      if (std::isfinite(report.ugr)) std::snprintf(text, sizeof(text), "UGR %.1f at the standard observers", report.ugr);
      else std::snprintf(text, sizeof(text), "UGR below 10 at the standard observers (no luminaire in view)");
      std::string limit;
      if (a.design.settings.ugr_max > 0) {
        char l[64];
        std::snprintf(l, sizeof(l), " (limit %g)", a.design.settings.ugr_max);
        limit = l;
      }
      std::fprintf(stderr, "hilight: %s%s\n", text, limit.c_str());
    }
    if (is_ifc_path(a.output)) {
      std::string where;
      for (const auto& room : ifc.spaces)
        if (where.find("'" + room + "'") == std::string::npos) where += (where.empty() ? "'" : ", '") + room + "'";
      std::fprintf(stderr, "hilight: %s: a copy of %s with %zu IfcLightFixture (%zu in IfcSpaces, %zu in storeys: %s), IFC4\n",
                   a.output.c_str(), a.scene_path.c_str(), lights.size(), ifc.in_spaces, ifc.in_storeys, where.c_str());
    }
    std::string power;
    if (a.luminaire->profile->input_watts > 0) {
      char text[160];
      if (energy.area > 0)
        std::snprintf(text, sizeof(text), ", %.0f W, %.2f W/m², LENI %.1f kWh/(m²·a) (installed at full power: %.1f)", energy.power,
                      energy.density, energy.leni, energy.installed_leni);
      else
        std::snprintf(text, sizeof(text), ", %.0f W", energy.power);
      power = text;
    }
    if (a.design.settings.tilt_max_deg > 0 && report.chosen == "array")
      std::fprintf(stderr, "hilight: the array keeps its aims (--tilt-max tilts a free layout's luminaires)\n");
    else if (a.design.settings.tilt_max_deg > 0)
      std::fprintf(stderr, "hilight: %zu of them tilted from their aim (at most %.0f°), where that saved flux or luminaires\n", report.tilted,
                   a.design.settings.tilt_max_deg);
    std::fprintf(stderr, "hilight: %zu luminaire%s (%s, %s, MF %.2f), %.0f lm%s (least possible %.0f lm), %s -> %s\n", lights.size(),
                 lights.size() == 1 ? "" : "s", name.c_str(), rules.describe().c_str(), report.maintenance_factor, report.flux_lm,
                 power.c_str(), report.least_flux_lm, command_time_summary(report.seconds["total"]).c_str(), a.output.c_str());
  }
  if (!report.met && report.shortfall_lux <= 0) {  // the program met them; the layout or the measurement did not
    std::fprintf(stderr, "hilight: %s: %s (lights written to %s)\n", a.target_path.c_str(),
                 report.unmet.empty() ? "the criteria are not met when the lights found are measured" : report.unmet.c_str(),
                 a.output.c_str());
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
