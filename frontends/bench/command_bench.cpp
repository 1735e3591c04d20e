// hilight bench: renderer throughput as JSON lines on stdout (one object per
// figure set), so runs can be compared by scripts. Medians over --repeat runs.
#include "bench_commands.hpp"
#include "bench_stats.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "hilight/threads.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace hilight::bench {

namespace {

/// The furnished room refined until it has at least `min_triangles`.
Scene bench_scene(size_t min_triangles) {
  float edge = 0.2f;
  for (;;) {
    Scene s = finish_scene(builders::furnished_room(), {edge});
    if (s.triangles.size() >= min_triangles) return s;
    edge *= 0.8f;
  }
}

/// About `count` of the points, evenly spaced in order.
SurfacePoints every_kth(const SurfacePoints& points, size_t count) {
  SurfacePoints out;
  size_t stride = std::max<size_t>(1, points.size() / std::max<size_t>(1, count));
  for (size_t i = 0; i < points.size() && out.size() < count; i += stride) {
    out.positions.push_back(points.positions[i]);
    out.normals.push_back(points.normals[i]);
    out.albedo.push_back(points.albedo[i]);
  }
  return out;
}

/// A grid of point lights filling the room's interior.
Lighting light_grid(int count) {
  Lighting lights;
  for (int i = 0; i < count; ++i) {
    float fx = (float(i % 4) + 0.5f) / 4.f, fz = (float((i / 4) % 4) + 0.5f) / 4.f, fy = (float(i / 16) + 0.5f) / float((count + 15) / 16);
    lights.push_back(Light::point({0.2f + 5.6f * fx, 0.9f + 2.f * fy, 0.2f + 4.6f * fz}, Rgb(1.f)));
  }
  return lights;
}

} // namespace

int run_bench(const std::vector<std::string>& args, Registry& registry) {
  if (!args.empty() && args[0] == "solve") return run_bench_solve(std::vector<std::string>(args.begin() + 1, args.end()), registry);
  if (!args.empty() && args[0] == "cache") return run_bench_cache(std::vector<std::string>(args.begin() + 1, args.end()), registry);
  if (!args.empty() && args[0] == "renderers")
    return run_bench_renderers(std::vector<std::string>(args.begin() + 1, args.end()), registry);
  if (!args.empty() && args[0] == "bounces") return run_bench_bounces(std::vector<std::string>(args.begin() + 1, args.end()), registry);
  if (!args.empty() && args[0] == "lux") return run_bench_lux(std::vector<std::string>(args.begin() + 1, args.end()), registry);
  if (!args.empty() && args[0] == "render") return run_bench(std::vector<std::string>(args.begin() + 1, args.end()), registry);
  CLI::App app("Measure renderer throughput; prints one JSON object per line (hilight bench solve: the inverse solve; hilight bench renderers: renderers side by side; hilight bench cache: light caches side by side; hilight bench lux: the illuminance design; hilight bench bounces: the render at each bounce model)", "bench");
  std::string renderer_name = PluginDefaults::renderer;
  int min_triangles = 100000, light_count = 32, repeat = 5, bounce_points = 2000, threads = 0;
  app.add_option("--renderer", renderer_name, "renderer plugin")->capture_default_str();
  app.add_option("--triangles", min_triangles, "minimum triangles of the benchmark scene")->check(CLI::Range(1000, 20000000))->capture_default_str();
  app.add_option("--lights", light_count, "unit lights in the φ batch")->check(CLI::Range(1, 4096))->capture_default_str();
  app.add_option("--repeat", repeat, "timed runs per figure (median reported)")->check(CLI::Range(1, 100))->capture_default_str();
  app.add_option("--bounce-points", bounce_points, "points for the first-bounce φ figure")->check(CLI::Range(1, 1000000))->capture_default_str();
  app.add_option("--threads", threads, "worker threads (0 = all cores)")->check(CLI::Range(0, 1024));
  int reference_points = 10000;
  app.add_option("--reference-points", reference_points, "points for the POV-Ray comparison (0: skip)")->check(CLI::Range(0, 1000000))->capture_default_str();
  if (auto code = parse_arguments(app, args)) return *code;
  set_thread_limit(threads);

  auto scene = std::make_shared<const Scene>(bench_scene(size_t(min_triangles)));
  SurfacePoints points = SurfacePoints::from_vertices(*scene);
  Lighting lights = light_grid(light_count);

  // Direct-light φ against the renderer's own raw ray-query baseline.
  Properties direct_props;
  direct_props.set("bounces", "0");
  auto direct = registry.create_renderer(renderer_name, direct_props);
  direct->set_scene(scene);
  std::vector<double> phi_seconds;
  uint64_t rays = 0;
  for (int r = 0; r < repeat; ++r) {
    phi_seconds.push_back(seconds_of([&] { direct->unit_responses(points, lights); }));
    rays = direct->rays_cast();
  }
  nlohmann::json phi = {{"figure", "phi_direct"}, {"renderer", renderer_name}, {"triangles", scene->triangles.size()},
                        {"points", points.size()}, {"lights", lights.size()}, {"repeat", repeat},
                        {"shadow_rays", rays}, {"seconds_median", median(phi_seconds)},
                        {"rays_per_second", double(rays) / median(phi_seconds)}};
  std::map<std::string, std::vector<double>> baseline;
  for (int r = 0; r < repeat; ++r)
    for (const auto& [name, value] : direct->baseline_figures(points, lights)) baseline[name].push_back(value);
  for (const auto& [name, values] : baseline) phi[name] = median(values);
  if (baseline.count("raw_occlusion_rays_per_second"))
    phi["phi_over_raw"] = phi["rays_per_second"].get<double>() / phi["raw_occlusion_rays_per_second"].get<double>();
  std::printf("%s\n", phi.dump().c_str());
  std::fflush(stdout);

  // First-bounce φ on a subset of points (the solver's sample count scale).
  SurfacePoints subset = every_kth(points, size_t(bounce_points));
  Properties bounce_props;
  bounce_props.set("bounces", "1");
  auto bounce = registry.create_renderer(renderer_name, bounce_props);
  bounce->set_scene(scene);
  double gather_seconds = seconds_of([&] { bounce->unit_responses(subset, std::span<const Light>(lights.data(), 1)); });
  std::vector<double> bounce_seconds;
  for (int r = 0; r < repeat; ++r) {
    bounce_seconds.push_back(seconds_of([&] { bounce->unit_responses(subset, lights); }));
    rays = bounce->rays_cast();
  }
  nlohmann::json phi_bounce = {{"figure", "phi_bounce"}, {"renderer", renderer_name}, {"points", subset.size()},
                               {"lights", lights.size()}, {"first_call_seconds_with_gather", gather_seconds},
                               {"rays", rays}, {"seconds_median", median(bounce_seconds)},
                               {"rays_per_second", double(rays) / median(bounce_seconds)},
                               {"seconds_per_light", median(bounce_seconds) / double(lights.size())}};
  std::printf("%s\n", phi_bounce.dump().c_str());
  std::fflush(stdout);

  // The reference renderer on the same scene and lights, when it can run:
  // seconds per 10k points for one lighting, against Embree in the same run.
  if (registry.find("renderer", "povray") && registry.renderer_unavailable_reason("povray").empty() && reference_points > 0) {
    SurfacePoints some = every_kth(points, size_t(reference_points));
    Lighting few(lights.begin(), lights.begin() + std::min<size_t>(4, lights.size()));
    nlohmann::json cmp = {{"figure", "reference_renderer"}, {"points", some.size()}, {"lights", few.size()}};
    for (int bounces : {0, 1}) {
      Properties props;
      props.set("bounces", std::to_string(bounces));
      for (const std::string name : {"embree", "povray"}) {
        auto r = registry.create_renderer(name, props);
        r->set_scene(scene);
        double s = seconds_of([&] { r->illuminate(some, few); });
        cmp[name + "_bounces" + std::to_string(bounces) + "_seconds_per_10k_points"] = s * 10000.0 / double(some.size());
      }
    }
    std::printf("%s\n", cmp.dump().c_str());
  }
  return 0;
}

} // namespace hilight::bench
