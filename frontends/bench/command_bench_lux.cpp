// hilight bench lux: the illuminance design on an open-plan office (issue
// 14's 10 m × 20 m, 500 lx, U0 0.6 work plane), JSON lines on stdout.
#include "bench_commands.hpp"
#include "hilight/io/photometry_io.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/solve/illuminance_design.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "hilight/threads.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace hilight::bench {

namespace {

/// A recessed LED panel: Lambertian below, dark above, 4000 lm at 36 W.
std::shared_ptr<const Photometry> led_panel() {
  auto p = std::make_shared<Photometry>();
  p->source = "builtin:led-panel";
  p->symmetry = Photometry::Symmetry::Rotational;
  p->horizontal = {0.0};
  for (int g = 0; g <= 180; g += 5) {
    p->vertical.push_back(g);
    p->candela.push_back(g <= 90 ? 4000.0 / kPi * std::cos(double(g) * kPi / 180.0) : 0.0);
  }
  p->rated_lumens = 4000;
  p->input_watts = 36;
  p->opening_length = p->opening_width = 0.6;  // a 600 × 600 panel
  p->product = "LED panel 600 × 600, 4000 lm, 36 W (built in)";
  return p;
}

/// The figures of one kind of layout: count, W, W/m².
nlohmann::json layout_json(const LayoutSummary& s, double area) {
  if (!s.found) return {{"found", false}};
  return {{"found", true},
          {"met", s.met},
          {"luminaires", s.count},
          {"power_w", s.power_w},
          {"w_per_m2", area > 0 ? nlohmann::json(s.power_w / area) : nlohmann::json(nullptr)},
          {"flux_lm", s.flux_lm},
          {"shape", s.shape}};
}

/// One scene's design, timed: the first (cold) and the median of `repeat` after it.
nlohmann::json bench_scene(const std::shared_ptr<const Scene>& scene, const IlluminanceCriteria& criteria, const PlacementRules& rules,
                           const Light& luminaire, Registry& registry, int repeat, double setup) {
  const RayScene rays(*scene);
  const LightSpace space(rays, rules);
  Properties props;
  props.set("bounces", "1");
  auto renderer = registry.create_renderer(PluginDefaults::renderer, props);
  renderer->set_scene(scene);
  std::vector<double> seconds, candidates_s, program_s, arrays_s;
  double first = 0;
  DesignReport report;
  Lighting lights;
  for (int r = 0; r <= repeat; ++r) {
    report = DesignReport{};
    lights = design_for_illuminance(*renderer, space, luminaire, criteria, DesignSettings{}, report);
    if (r == 0) {  // the first: cold (the renderer's first call builds its gathers)
      first = report.seconds["total"];
      continue;
    }
    seconds.push_back(report.seconds["total"]);
    // The plan's steps (design/design_plan.cpp): the set-up renders nothing.
    candidates_s.push_back(report.seconds["set-up"] + report.seconds["candidates"]);
    program_s.push_back(report.seconds["program"] + report.seconds["free layouts"] + report.seconds["count asked"]);
    arrays_s.push_back(report.seconds["arrays"]);
  }
  const auto median = [](std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  const GridFigures& f = report.figures.front();
  const double area = report.room.floor_area;
  return {{"figure", "illuminance_design"}, {"scene", scene->source}, {"triangles", scene->triangles.size()},
          {"grid_points", criteria.size()}, {"candidates", report.candidates}, {"luminaire", luminaire.profile_path},
          {"repeat", repeat}, {"setup_seconds", setup}, {"first_seconds", first}, {"seconds_median", median(seconds)},
          {"candidates_seconds_median", median(candidates_s)}, {"free_seconds_median", median(program_s)},
          {"arrays_seconds_median", median(arrays_s)}, {"maintenance_factor", report.maintenance_factor},
          {"floor_area_m2", area}, {"room_m", {report.room.length(), report.room.width()}},
          {"luminaires", lights.size()}, {"chosen", report.chosen}, {"flux_lm", report.flux_lm},
          {"least_flux_lm", report.least_flux_lm}, {"power_w", report.power_w},
          {"w_per_m2", area > 0 ? nlohmann::json(report.power_w / area) : nlohmann::json(nullptr)},
          {"array", layout_json(report.array, area)}, {"free", layout_json(report.free, area)}, {"mean_lux", f.mean},
          {"min_lux", f.min}, {"u0", f.u0}, {"met", report.met}};
}

} // namespace

int run_bench_lux(const std::vector<std::string>& args, Registry& registry) {
  CLI::App app("The illuminance design on an open-plan office and the IFC house: seconds, luminaires, W and W/m², array against "
               "free (JSON lines)",
               "bench lux");
  float width = 20.f, depth = 10.f, offset = 0.1f;
  double lux = 500, u0 = 0.6;
  int repeat = 5, threads = 0;
  std::string luminaire_path, house = (builders::testmodels_dir() / "IFC" / "AC14-FZK-Haus.ifc").string();
  app.add_option("--width", width, "office width, m")->check(CLI::Range(2.0, 200.0))->capture_default_str();
  app.add_option("--depth", depth, "office depth, m")->check(CLI::Range(2.0, 200.0))->capture_default_str();
  app.add_option("--lux", lux, "work plane Ē wanted (maintained, MF 0.8)")->capture_default_str();
  app.add_option("--u0", u0, "work plane U0 wanted")->capture_default_str();
  app.add_option("--offset", offset, "luminaires this far below the ceiling")->capture_default_str();
  app.add_option("--luminaire", luminaire_path, "IES or EULUMDAT file (default: a 4000 lm, 36 W Lambertian LED panel, 0.6 × 0.6 m)");
  app.add_option("--repeat", repeat, "timed designs after the first (median reported)")->check(CLI::Range(1, 100))->capture_default_str();
  app.add_option("--house", house, "the IFC house (its region 3, a ground-floor room, is designed too; skipped when missing)")
      ->capture_default_str();
  app.add_option("--threads", threads, "worker threads (0 = all cores)")->check(CLI::Range(0, 1024));
  if (auto code = parse_arguments(app, args)) return *code;
  set_thread_limit(threads);

  Light luminaire;
  luminaire.type = LightType::Luminaire;
  luminaire.profile = luminaire_path.empty() ? led_panel() : std::make_shared<const Photometry>(read_photometry(luminaire_path));
  luminaire.profile_path = luminaire_path.empty() ? "builtin:led-panel" : luminaire_path;
  PlacementRules rules;
  rules.add("ceiling:" + std::to_string(offset));

  {
    const auto t_scene = std::chrono::steady_clock::now();
    auto scene = std::make_shared<const Scene>(finish_scene(builders::open_plan_office(width, depth), {0.f}));
    const RayScene rays(*scene);
    const Regions regions(rays);
    IlluminanceCriteria criteria;
    criteria.grids.push_back(make_work_plane(rays, regions, {}, 0.75f, lux, u0));
    const double setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_scene).count();
    nlohmann::json line = bench_scene(scene, criteria, rules, luminaire, registry, repeat, setup);
    line["width_m"] = width;
    line["depth_m"] = depth;
    std::printf("%s\n", line.dump().c_str());
    std::fflush(stdout);
  }
  if (std::filesystem::exists(house)) {
    const auto t_scene = std::chrono::steady_clock::now();
    auto scene = std::make_shared<const Scene>(load_scene(house, {}));
    const RayScene rays(*scene);
    const Regions regions(rays);
    IlluminanceCriteria criteria;
    GridArea room;
    room.region = 3;  // a ground-floor room (hilight info lists the regions by size)
    criteria.grids.push_back(make_work_plane(rays, regions, room, 0.75f, lux, u0));
    const double setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_scene).count();
    nlohmann::json line = bench_scene(scene, criteria, rules, luminaire, registry, std::min(repeat, 2), setup);
    line["region"] = 3;
    std::printf("%s\n", line.dump().c_str());
  } else {
    std::printf("%s\n", nlohmann::json({{"figure", "illuminance_design"}, {"scene", house}, {"skipped", "not installed (assimp-testmodels)"}}).dump().c_str());
  }
  return 0;
}

} // namespace hilight::bench
