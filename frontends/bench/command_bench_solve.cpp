// hilight bench solve: the inverse solve on the interior room (≥20k vertices,
// 4 known lights) for each optimizer: cold start (light cache built), warm
// start (cache on disk), fine-tune after a small edit. JSON lines on stdout;
// medians over --repeat runs, all in one process so the figures compare.
#include "bench_commands.hpp"
#include "bench_stats.hpp"
#include "hilight/fixtures/built_scenes.hpp"
#include "hilight/io/lights_json.hpp"
#include "hilight/light_cache_store.hpp"
#include "hilight/solve/solve_session.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "hilight/threads.hpp"

#include "hilight/error.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <nlohmann/json.hpp>

namespace hilight::bench {

namespace {

/// The bench's cache folder: --cache-dir as given (only its light caches are
/// ever removed), or a new private temporary folder, removed whole at the end.
class BenchCacheFolder {
public:
  explicit BenchCacheFolder(std::string& given) : m_path(given) {
    if (!given.empty()) return;
    std::string pattern = (std::filesystem::temp_directory_path() / "hilight-bench-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw InputError(pattern, std::string("cannot make a folder: ") + std::strerror(errno));
    given = pattern;
    m_owned = true;
  }
  ~BenchCacheFolder() {
    std::error_code ec;
    if (m_owned) std::filesystem::remove_all(m_path, ec);
    else clear_cache(m_path);
  }
  BenchCacheFolder(const BenchCacheFolder&) = delete;
  BenchCacheFolder& operator=(const BenchCacheFolder&) = delete;

private:
  const std::string& m_path;
  bool m_owned = false;
};

/// Mean distance from each true light to the nearest found light.
double mean_position_error(const Lighting& truth, const Lighting& found) {
  double sum = 0;
  for (const auto& t : truth) {
    double best = 1e30;
    for (const auto& f : found) best = std::min(best, double(glm::length(t.position - f.position)));
    sum += best;
  }
  return truth.empty() ? 0.0 : sum / double(truth.size());
}

/// What every solve of a `bench solve` run shares.
struct BenchRun {
  std::string cache_root;                       ///< where the light caches go
  std::string bounces;                          ///< as `hilight solve --bounces` takes it
  std::vector<std::string> optimizer_settings;  ///< --opt KEY=VALUE, as `hilight solve --opt` takes them
};

/// The solve as `hilight solve` assembles it, its light cache kept in the run's folder.
SolveSpec bench_spec(const BenchRun& run, const std::string& optimizer = PluginDefaults::optimizer) {
  SolveSpec spec;
  spec.optimizer = optimizer;
  spec.optimizer_settings = run.optimizer_settings;
  spec.renderer_settings = {"bounces=" + run.bounces};
  spec.settings.cache_dir = run.cache_root;
  return spec;
}

/// The report's log of moves, in the order they ran: what each cost and did.
nlohmann::json moves_json(const SolveReport& report) {
  nlohmann::json moves = nlohmann::json::array();
  for (const StageRecord& s : report.stages)
    moves.push_back({{"move", s.name}, {"seconds", s.seconds}, {"dbar_before", s.dbar_before}, {"dbar_after", s.dbar_after},
                     {"kept", s.kept}, {"skipped", s.skipped}});
  return moves;
}

/// The cuts the count walk looked at: each one's D̄ from the hierarchy and, where refined, after.
nlohmann::json cuts_json(const SolveReport& report) {
  nlohmann::json cuts = nlohmann::json::array();
  for (const CutRecord& c : report.cuts)
    cuts.push_back({{"lights", c.lights}, {"dbar_initial", c.dbar_initial}, {"refined", c.refined}, {"dbar_refined", c.dbar_refined}});
  return cuts;
}

/// A solve that builds the light cache anew: its seconds, and each stage's
/// added to `stages` (where a cold solve's time goes).
double cold_solve_seconds(const SolveSession& session, const Target& target, const std::string& cache_root,
                          std::map<std::string, std::vector<double>>& stages) {
  clear_cache(cache_root);
  SolveReport report;
  session.make_solver()->solve(target, report);
  for (const auto& [stage, seconds] : report.seconds) stages[stage].push_back(seconds);
  return report.seconds["total"];
}

/// A built scene (issue 10) with one seeded random configuration of `lights`
/// lights: cold and warm solve, D̄, position error, the light cache's size.
void bench_built_scene(builders::BuiltScene built, float max_edge, size_t lights, int repeat, const BenchRun& run, Registry& registry) {
  auto scene = std::make_shared<const Scene>(finish_scene(built.scene, {max_edge}));
  auto rays = RayScene::shared(scene);
  std::mt19937_64 rng(7);
  builders::RandomLightRules rules;
  rules.min_count = rules.max_count = lights;
  const Lighting truth = builders::random_lights(built, *rays, rng, rules);
  SolveSession session(registry, bench_spec(run), scene, rays);
  const std::vector<Rgb> values = session.reference().illuminate(SurfacePoints::from_vertices(*scene), truth);
  const Target target = bind_target("bench", scene->positions, values, std::vector<float>(values.size(), 1.f), *scene, *rays, scene->normals);
  std::vector<double> cold, warm, dbar, pos_err;
  std::map<std::string, std::vector<double>> stages, cold_stages;
  size_t found_count = 0;
  double cache_mb = 0;
  nlohmann::json last_moves = nlohmann::json::array(), last_cuts = nlohmann::json::array();
  for (int r = 0; r < repeat; ++r) {
    cold.push_back(cold_solve_seconds(session, target, run.cache_root, cold_stages));
    uint64_t bytes = 0;
    for (const auto& f : list_cache(run.cache_root)) bytes += f.bytes;
    cache_mb = double(bytes) / (1024.0 * 1024.0);
    SolveReport report;
    const Lighting found = session.make_solver()->solve(target, report);  // a new Solver: the cache from disk
    warm.push_back(report.seconds["total"]);
    for (const auto& [stage, seconds] : report.seconds) stages[stage].push_back(seconds);
    dbar.push_back(report.dbar);
    pos_err.push_back(mean_position_error(truth, found) / scene->diagonal());
    found_count = found.size();
    last_moves = moves_json(report);
    last_cuts = cuts_json(report);
  }
  nlohmann::json j = {{"figure", "solve_scene"}, {"scene", built.name}, {"bounces", run.bounces}, {"vertices", scene->positions.size()},
                            {"true_lights", truth.size()}, {"found_lights", found_count}, {"repeat", repeat},
                            {"dbar_median", median(dbar)}, {"position_error_over_diagonal_median", median(pos_err)},
                            {"cold_seconds_median", median(cold)}, {"warm_seconds_median", median(warm)},
                            {"light_cache_mb", cache_mb}, {"peak_rss_mb_so_far", peak_rss_mb()}};
  for (const auto& [stage, v] : stages) j["warm_stage_seconds_median"][stage] = median(v);
  for (const auto& [stage, v] : cold_stages) j["cold_stage_seconds_median"][stage] = median(v);
  j["last_warm_moves"] = last_moves;
  j["last_warm_cuts"] = last_cuts;
  std::printf("%s\n", j.dump().c_str());
  std::fflush(stdout);
}

} // namespace

int run_bench_solve(const std::vector<std::string>& args, Registry& registry) {
  CLI::App app("Benchmark the inverse solve; prints one JSON object per line", "bench solve");
  std::vector<std::string> optimizers = {"varpro", "nelder-mead"};
  int repeat = 3, threads = 0;
  float max_edge = 0.15f;
  BenchRun run;
  run.bounces = "all";
  app.add_option("--optimizers", optimizers, "optimizer plugins to compare")->capture_default_str();
  app.add_option("--repeat", repeat, "runs per figure (median reported)")->check(CLI::Range(1, 50))->capture_default_str();
  app.add_option("--max-edge", max_edge, "tessellation of the room (0.15: about 25k vertices)")->check(FiniteNonNegative)->capture_default_str();
  app.add_option("--cache-dir", run.cache_root,
                 "folder for the light caches (default: a new temporary one, removed after); only its light cache files are removed");
  app.add_option("--threads", threads, "worker threads (0 = all cores)")->check(CLI::Range(0, 1024));
  bool no_cache_figure = false;
  app.add_option("--bounces", run.bounces, "diffuse bounces of the targets and the solve, as hilight solve takes them")
      ->check(BounceCount)
      ->capture_default_str();
  std::vector<std::string> scenes = {"room", "building", "product"};
  float building_edge = 0.22f, home_edge = builders::kHomeBenchEdge;
  app.add_option("--scenes", scenes,
                 "room (the furnished room, each optimizer), building (two storeys, 6 lights), product (3 lights outside it), "
                 "home (a furnished flat of five rooms from the IFC house and real models, 5 ceiling lamps; needs assimp-testmodels)")
      ->capture_default_str();
  app.add_option("--building-edge", building_edge, "tessellation of the building (0.22: about 100k vertices)")
      ->check(FiniteNonNegative)
      ->capture_default_str();
  app.add_option("--home-edge", home_edge, "tessellation of the home (0.2: about 260k vertices)")->check(FiniteNonNegative)->capture_default_str();
  app.add_flag("--skip-no-cache", no_cache_figure, "skip the comparison solve without the light cache");
  app.add_option("--opt", run.optimizer_settings, "an optimizer setting KEY=VALUE (repeatable), as hilight solve --opt takes it");
  if (auto code = parse_arguments(app, args)) return *code;
  set_thread_limit(threads);
  const BenchCacheFolder cache_folder(run.cache_root);
  auto wants = [&](const char* s) { return std::find(scenes.begin(), scenes.end(), s) != scenes.end(); };
  if (wants("building")) bench_built_scene(builders::two_storey_building(), building_edge, 6, repeat, run, registry);
  if (wants("product")) bench_built_scene(builders::product_on_turntable(), 0.f, 3, repeat, run, registry);
  if (wants("home")) bench_built_scene(builders::furnished_home(), home_edge, 5, repeat, run, registry);
  if (!wants("room")) return 0;

  auto scene = std::make_shared<const Scene>(finish_scene(builders::furnished_room(), {max_edge}));
  auto rays = RayScene::shared(scene);
  const Lighting truth = {Light::point({1.5f, 2.5f, 1.1f}, Rgb(2.f)), Light::point({4.6f, 2.4f, 1.4f}, Rgb(2.f, 1.9f, 1.7f)),
                          Light::point({2.3f, 1.6f, 3.9f}, Rgb(1.6f, 1.7f, 2.f)), Light::point({4.8f, 2.2f, 3.8f}, Rgb(1.8f))};
  // The target comes from the solve's reference renderer, as `hilight
  // render` would make it; the solve evaluates with its fast twin.
  std::vector<Rgb> values = SolveSession(registry, bench_spec(run), scene, rays).reference().illuminate(SurfacePoints::from_vertices(*scene), truth);
  Target target = bind_target("bench", scene->positions, values, std::vector<float>(values.size(), 1.f), *scene, *rays, scene->normals);
  // A small edit for fine-tune: 10% brighter on the floor's left half.
  Target edited = target;
  for (size_t i = 0; i < edited.size(); ++i)
    if (edited.points.positions[i].y < 0.01f && edited.points.positions[i].x < 3.f) edited.value[i] *= 1.1f;

  for (const auto& name : optimizers) {
    SolveSession session(registry, bench_spec(run, name), scene, rays);
    std::vector<double> cold, warm, fine, dbar, pos_err;
    nlohmann::json last_fine_tune = nlohmann::json::array();
    std::map<std::string, std::vector<double>> fine_stages;
    std::map<std::string, std::vector<double>> stages, cold_stages;
    size_t count = 0;
    for (int r = 0; r < repeat; ++r) {
      cold.push_back(cold_solve_seconds(session, target, run.cache_root, cold_stages));
      const auto solver = session.make_solver();  // a new Solver: the cache from disk
      SolveReport report;
      Lighting found = solver->solve(target, report);
      warm.push_back(report.seconds["total"]);
      for (const auto& [stage, s] : report.seconds) stages[stage].push_back(s);
      dbar.push_back(report.dbar);
      pos_err.push_back(mean_position_error(truth, found) / scene->diagonal());
      count = found.size();
      SolveReport tune;
      solver->fine_tune(edited, found, tune);
      fine.push_back(tune.seconds["total"]);
      last_fine_tune = moves_json(tune);
      for (const auto& [stage, seconds] : tune.seconds) fine_stages[stage].push_back(seconds);
    }
    nlohmann::json j = {{"figure", "solve"}, {"optimizer", name}, {"bounces", run.bounces}, {"vertices", scene->positions.size()},
                        {"true_lights", truth.size()}, {"found_lights", count}, {"repeat", repeat},
                        {"dbar_median", median(dbar)}, {"position_error_over_diagonal_median", median(pos_err)},
                        {"cold_seconds_median", median(cold)}, {"warm_seconds_median", median(warm)},
                        {"fine_tune_seconds_median", median(fine)}, {"last_fine_tune_moves", last_fine_tune}};
    for (const auto& [stage, v] : stages) j["warm_stage_seconds_median"][stage] = median(v);
    for (const auto& [stage, v] : cold_stages) j["cold_stage_seconds_median"][stage] = median(v);
    for (const auto& [stage, v] : fine_stages) j["fine_tune_stage_seconds_median"][stage] = median(v);
    std::printf("%s\n", j.dump().c_str());
    std::fflush(stdout);
  }
  // Does the light cache pay? The same solve with every φ from the renderer.
  if (!no_cache_figure) {
    SolveSpec spec = bench_spec(run, optimizers.front());
    spec.cache = PluginDefaults::no_cache;
    SolveReport report;
    Lighting found = SolveSession(registry, spec, scene, rays).make_solver()->solve(target, report);
    nlohmann::json j = {{"figure", "solve_without_cache"}, {"optimizer", optimizers.front()}, {"found_lights", found.size()},
                        {"dbar", report.dbar}, {"position_error_over_diagonal", mean_position_error(truth, found) / scene->diagonal()},
                        {"seconds", report.seconds["total"]}, {"stage_seconds", report.seconds}};
    std::printf("%s\n", j.dump().c_str());
  }
  return 0;
}

} // namespace hilight::bench
