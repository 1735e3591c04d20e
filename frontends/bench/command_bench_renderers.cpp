// hilight bench renderers: the renderers side by side on the same scene,
// points and lights, in one process: seconds to evaluate one lighting
// configuration (4 lights, every vertex) and to compute φ for a batch of
// unit lights (default 1,000), plus each renderer's own stage figures
// (ism-vulkan: GPU seconds per stage from timestamps). JSON lines on stdout.
#include "bench_commands.hpp"
#include "bench_stats.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "hilight/threads.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <random>

namespace hilight::bench {

int run_bench_renderers(const std::vector<std::string>& args, Registry& registry) {
  CLI::App app("Compare renderers on the same scene and lights; prints one JSON object per line", "bench renderers");
  // name[:key=value,...]: the solve's fast settings are worth a line each.
  // hot_spots=off: the bounce before near-light patches (issue 11), side by side.
  std::vector<std::string> names = {"embree",          "embree:hot_spots=off", "embree:bounce_direct=vertex",
                                    "embree:bounce_direct=vertex,hot_spots=off", "ism-vulkan", "ism-vulkan:vpls=64"};
  int repeat = 3, threads = 0, light_count = 1000;
  float max_edge = 0.15f;
  app.add_option("--renderers", names, "renderers to compare, each NAME or NAME:key=value,key=value")->capture_default_str();
  app.add_option("--lights", light_count, "unit lights in the φ batch")->check(CLI::Range(1, 100000))->capture_default_str();
  app.add_option("--repeat", repeat, "runs per figure (median reported)")->check(CLI::Range(1, 50))->capture_default_str();
  app.add_option("--max-edge", max_edge, "tessellation of the room (0.15: about 25k vertices)")->check(FiniteNonNegative)->capture_default_str();
  app.add_option("--threads", threads, "worker threads (0 = all cores)")->check(CLI::Range(0, 1024));
  if (auto code = parse_arguments(app, args)) return *code;
  set_thread_limit(threads);

  auto scene = std::make_shared<const Scene>(finish_scene(builders::furnished_room(), {max_edge}));
  const SurfacePoints points = SurfacePoints::from_vertices(*scene);
  const Lighting config = {Light::point({1.5f, 2.5f, 1.1f}, Rgb(2.f)), Light::point({4.6f, 2.4f, 1.4f}, Rgb(2.f, 1.9f, 1.7f)),
                           Light::point({2.3f, 1.6f, 3.9f}, Rgb(1.6f, 1.7f, 2.f)), Light::point({4.8f, 2.2f, 3.8f}, Rgb(1.8f))};
  // Unit lights spread through the room's free space (the light cache's kind of batch).
  Lighting batch;
  std::mt19937 rng(7);
  const Bounds b = scene->bounds;
  std::uniform_real_distribution<float> ux(b.lo.x + 0.2f, b.hi.x - 0.2f), uy(b.lo.y + 1.2f, b.hi.y - 0.2f), uz(b.lo.z + 0.2f, b.hi.z - 0.2f);
  for (int k = 0; k < light_count; ++k) batch.push_back(Light::point({ux(rng), uy(rng), uz(rng)}, Rgb(1.f)));

  for (const auto& spec : names) {
    const std::string name = spec.substr(0, spec.find(':'));
    std::vector<std::string> settings;
    if (spec.find(':') != std::string::npos)
      for (size_t at = spec.find(':') + 1; at <= spec.size();) {
        size_t comma = std::min(spec.find(',', at), spec.size());
        settings.push_back(spec.substr(at, comma - at));
        at = comma + 1;
      }
    if (std::string why = registry.renderer_unavailable_reason(name); !why.empty()) {
      nlohmann::json skip = {{"figure", "renderers"}, {"renderer", spec}, {"unavailable", why}};
      std::printf("%s\n", skip.dump().c_str());
      continue;
    }
    auto renderer = registry.create_renderer(name, Properties::from_assignments(settings));
    renderer->set_scene(scene);
    renderer->illuminate(points, config);  // warm-up: per-point-set work, shader compilation
    std::vector<double> evaluate, phi;
    for (int r = 0; r < repeat; ++r) evaluate.push_back(seconds_of([&] { renderer->illuminate(points, config); }));
    for (int r = 0; r < repeat; ++r) phi.push_back(seconds_of([&] { renderer->unit_responses(points, batch); }));
    nlohmann::json out = {{"figure", "renderers"}, {"renderer", spec}, {"triangles", scene->triangles.size()},
                          {"points", points.size()}, {"evaluate_lights", config.size()}, {"evaluate_seconds", median(evaluate)},
                          {"phi_lights", batch.size()}, {"phi_seconds", median(phi)},
                          {"phi_seconds_per_light", median(phi) / double(batch.size())}, {"repeat", repeat}};
    for (const auto& [key, value] : renderer->baseline_figures(points, std::span<const Light>(config)))
      out["stages_4_lights"][key] = value;
    std::printf("%s\n", out.dump().c_str());
    std::fflush(stdout);
  }
  return 0;
}

} // namespace hilight::bench
