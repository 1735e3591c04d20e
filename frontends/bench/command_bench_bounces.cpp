// hilight bench bounces: the reference render of a built scene's vertices
// under seeded random lights, at each bounce model side by side (issue 32:
// every bounce at most 1.5x the first bounce's time). The models alternate
// within each repeat so that a noisy machine hits them alike; medians and
// the ratio to the first model are printed as JSON lines. Memory is the
// process's: run one model per process (--bounces all) to compare it.
#include "bench_commands.hpp"
#include "bench_stats.hpp"
#include "hilight/fixtures/built_scenes.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "hilight/solve/solve_session.hpp"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <random>

namespace hilight::bench {

namespace {

struct BenchScene {
  std::string name;
  builders::BuiltScene built;
  float max_edge;
  size_t lights;
};

void bench_scene_bounces(const BenchScene& b, const std::vector<std::string>& models, int repeat, Registry& registry) {
  auto scene = std::make_shared<const Scene>(finish_scene(b.built.scene, {b.max_edge}));
  auto rays = RayScene::shared(scene);
  std::mt19937_64 rng(7);
  builders::RandomLightRules rules;
  rules.min_count = rules.max_count = b.lights;
  const Lighting lights = builders::random_lights(b.built, *rays, rng, rules);
  const SurfacePoints points = SurfacePoints::from_vertices(*scene);
  std::vector<std::unique_ptr<SolveSession>> sessions;
  for (const auto& model : models) {
    SolveSpec spec;
    spec.renderer_settings = {"bounces=" + model};
    sessions.push_back(std::make_unique<SolveSession>(registry, spec, scene, rays));
  }
  std::vector<std::vector<double>> seconds(models.size());
  std::vector<double> mean_value(models.size(), 0.0);
  for (int r = 0; r < repeat; ++r)
    for (size_t k = 0; k < models.size(); ++k) {
      const size_t m = (k + size_t(r)) % models.size();  // alternate which model runs first
      std::vector<Rgb> values;
      seconds[m].push_back(seconds_of([&] { values = sessions[m]->reference().illuminate(points, lights); }));
      double sum = 0;
      for (const Rgb& v : values) sum += double(v.r + v.g + v.b) / 3.0;
      mean_value[m] = values.empty() ? 0.0 : sum / double(values.size());
    }
  for (size_t m = 0; m < models.size(); ++m) {
    nlohmann::json j = {{"figure", "render_bounces"}, {"scene", b.name}, {"vertices", scene->positions.size()},
                        {"lights", lights.size()}, {"bounces", models[m]}, {"repeat", repeat},
                        {"seconds_median", median(seconds[m])},
                        {"seconds_over_first_model", median(seconds[m]) / std::max(1e-9, median(seconds[0]))},
                        {"mean_radiosity", mean_value[m]},
                        {"mean_over_first_model", mean_value[m] / std::max(1e-30, mean_value[0])},
                        {"peak_rss_mb_so_far", peak_rss_mb()}};
    std::printf("%s\n", j.dump().c_str());
    std::fflush(stdout);
  }
}

} // namespace

int run_bench_bounces(const std::vector<std::string>& args, Registry& registry) {
  CLI::App app("Benchmark the reference render at each bounce model, side by side; prints one JSON object per line",
               "bench bounces");
  std::vector<std::string> models = {"1", "all"};
  std::vector<std::string> scenes = {"building", "home"};
  int repeat = 3;
  float home_edge = builders::kHomeBenchEdge;
  app.add_option("--bounces", models, "bounce models to compare, as hilight render --bounces takes them; ratios are to the first")
      ->check(BounceCount)
      ->capture_default_str();
  app.add_option("--scenes", scenes,
                 "building (two storeys, 6 lights), home (a furnished flat of five "
                 "rooms, 5 ceiling lamps, about 260k vertices; needs assimp-testmodels)")
      ->capture_default_str();
  app.add_option("--repeat", repeat, "runs per model (median reported)")->check(CLI::Range(1, 50))->capture_default_str();
  app.add_option("--home-edge", home_edge, "tessellation of the home (0.2: about 260k vertices)")->check(FiniteNonNegative)->capture_default_str();
  if (auto code = parse_arguments(app, args)) return *code;
  const auto wants = [&](const char* name) { return std::find(scenes.begin(), scenes.end(), name) != scenes.end(); };
  if (wants("building")) bench_scene_bounces({"building", builders::two_storey_building(), 0.22f, 6}, models, repeat, registry);
  if (wants("home")) bench_scene_bounces({"home", builders::furnished_home(), home_edge, 5}, models, repeat, registry);
  return 0;
}

} // namespace hilight::bench
