// hilight bench cache: the light cache plugins side by side on the same
// scenes: build time, traced lights, size on disk, and the bounce they give
// against the exact bounce at seeded random light positions (every vertex).
// JSON lines on stdout, one per scene and cache, all in one process.
#include "bench_commands.hpp"
#include "hilight/fixtures/built_scenes.hpp"
#include "hilight/light_bounds.hpp"
#include "hilight/light_cache_file.hpp"
#include "hilight/light_space.hpp"
#include "hilight/solve/solve_renderers.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "hilight/threads.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <random>

namespace hilight::bench {

namespace {

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, size_t(q * double(v.size())))];
}

float luminance(const Rgb& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

/// Relative L1 error of `cached` against `exact` over the points.
double relative_error(const Rgb* cached, const Rgb* exact, size_t count) {
  double wrong = 0, total = 0;
  for (size_t i = 0; i < count; ++i) {
    wrong += std::abs(double(luminance(cached[i])) - double(luminance(exact[i])));
    total += double(luminance(exact[i]));
  }
  return total > 0 ? wrong / total : 0.0;
}

/// Seeded light positions in the light space's free part; `near` > 0: only
/// those within `near` of a surface (where lamps hang: under ceilings, on walls).
std::vector<Vec3> probe_positions(const RayScene& rays, const Bounds& bounds, size_t count, float clearance, float near) {
  std::mt19937_64 rng(near > 0 ? 13 : 11);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  std::vector<Vec3> out;
  for (size_t tries = 0; out.size() < count && tries < 100 * count; ++tries) {
    const Vec3 p = bounds.lo + Vec3(u(rng), u(rng), u(rng)) * bounds.extent();
    if (LightSpace::free_at(rays, p, clearance) && (near <= 0 || rays.closest_point(p, near).valid()))
      out.push_back(p);
  }
  return out;
}

/// "grid" or "grid:cells=10,..." → the plugin's name and its settings.
std::pair<std::string, std::vector<std::string>> cache_choice(const std::string& text) {
  const size_t colon = text.find(':');
  std::vector<std::string> settings;
  if (colon != std::string::npos) {
    std::string rest = text.substr(colon + 1);
    for (size_t start = 0; start <= rest.size();) {
      const size_t comma = std::min(rest.find(',', start), rest.size());
      if (comma > start) settings.push_back(rest.substr(start, comma - start));
      start = comma + 1;
    }
  }
  return {text.substr(0, colon), settings};
}

struct BenchScene {
  std::string name;
  std::shared_ptr<const Scene> scene;
};

void bench_scene(const BenchScene& s, const std::vector<std::string>& caches, size_t probes, const std::filesystem::path& dir,
                 const std::string& bounces, Registry& registry) {
  const Scene& scene = *s.scene;
  const RayScene rays(scene);
  // The cache keeps the bounce of the solve's fast twin: bench that renderer.
  auto renderer = registry.create_renderer(
      PluginDefaults::renderer,
      Properties::from_assignments(fast_renderer_settings(registry.renderer_traits(PluginDefaults::renderer),
                                                         reference_renderer_settings({"bounces=" + bounces}, 1))));
  renderer->set_scene(s.scene);
  const Bounds bounds = scene.light_bounds();
  const Target target = bind_target("vertices", scene.positions, std::vector<Rgb>(scene.positions.size(), Rgb(1.f)),
                                    std::vector<float>(scene.positions.size(), 1.f), scene, rays, scene.normals);
  const SampleSet samples = all_samples(target);
  const size_t m = samples.size();
  // Two sets: anywhere in the light space, and within 3% of the diagonal of a surface.
  std::vector<Vec3> where[2];
  std::vector<Rgb> exact[2];
  for (int set = 0; set < 2; ++set) {
    where[set] = probe_positions(rays, bounds, probes, 2e-3f * scene.diagonal(), set ? 0.03f * scene.diagonal() : 0.f);
    Lighting lights;
    for (const auto& p : where[set]) lights.push_back(Light::point(p, Rgb(1.f)));
    exact[set] = renderer->unit_responses(samples.points, lights, Transport::IndirectOnly);
  }
  for (const auto& name : caches) {
    const auto [plugin, settings] = cache_choice(name);
    auto builder = registry.create_cache(plugin, Properties::from_assignments(settings));
    const auto t0 = std::chrono::steady_clock::now();
    auto cache = builder->build({scene, rays, *renderer, bounds});
    const double build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const auto file = dir / (s.name + "-" + plugin + ".bin");
    save_light_cache(file, 1, *cache);
    const auto view = cache->view(rays, samples);
    std::vector<double> errors[2];
    std::vector<Rgb> cached(m);
    for (int set = 0; set < 2; ++set)
      for (size_t j = 0; j < where[set].size(); ++j) {
        std::fill(cached.begin(), cached.end(), Rgb(0.f));
        view->add_indirect(where[set][j], cached.data());
        errors[set].push_back(relative_error(cached.data(), exact[set].data() + j * m, m));
      }
    nlohmann::json line = {{"bench", "cache"},
                           {"scene", s.name},
                           {"cache", name},
                           {"vertices", scene.positions.size()},
                           {"nodes", cache->node_count()},
                           {"build_s", build_seconds},
                           {"file_mb", double(std::filesystem::file_size(file)) / (1024.0 * 1024.0)},
                           {"probes", where[0].size() + where[1].size()},
                           {"bounce_error_median", percentile(errors[0], 0.5)},
                           {"bounce_error_p90", percentile(errors[0], 0.9)},
                           {"near_surface_error_median", percentile(errors[1], 0.5)},
                           {"near_surface_error_p90", percentile(errors[1], 0.9)}};
    std::printf("%s\n", line.dump().c_str());
    std::fflush(stdout);
  }
}

} // namespace

int run_bench_cache(const std::vector<std::string>& args, Registry& registry) {
  CLI::App app("Compare the light cache plugins: build time, size on disk, bounce against exact; one JSON object per line",
               "bench cache");
  std::vector<std::string> caches = {"grid", "adaptive"}, scenes = {"room", "building", "real-room"};
  size_t probes = 64;
  int threads = 0;
  std::string dir = (std::filesystem::temp_directory_path() / "hilight-bench-cache-files").string();
  app.add_option("--caches", caches, "cache plugins to compare, each NAME or NAME:key=value,...")->capture_default_str();
  app.add_option("--scenes", scenes, "room (furnished, built), building (two storeys, built), real-room (assimp-testmodels furniture), home (five rooms, the tests' tessellation)")
      ->capture_default_str();
  app.add_option("--probes", probes, "random light positions the bounce is compared at")->check(CLI::Range(1, 4096))->capture_default_str();
  app.add_option("--dir", dir, "scratch folder for the cache files")->capture_default_str();
  app.add_option("--threads", threads, "worker threads (0 = all cores)")->check(CLI::Range(0, 1024));
  std::string bounces = "1";
  app.add_option("--bounces", bounces, "diffuse bounces the cache keeps, as hilight solve takes them")->check(BounceCount)->capture_default_str();
  if (auto code = parse_arguments(app, args)) return *code;
  set_thread_limit(threads);
  for (const auto& name : caches) {  // unknown names and settings fail before any work
    const auto [plugin, settings] = cache_choice(name);
    registry.create_cache(plugin, Properties::from_assignments(settings));
  }
  std::filesystem::create_directories(dir);
  for (const auto& name : scenes) {
    BenchScene s{name, nullptr};
    if (name == "room") s.scene = std::make_shared<const Scene>(finish_scene(builders::furnished_room(), {0.15f}));
    else if (name == "building") s.scene = std::make_shared<const Scene>(finish_scene(builders::two_storey_building().scene, {0.22f}));
    else if (name == "real-room") s.scene = std::make_shared<const Scene>(finish_scene(builders::real_furnished_room(), {}));
    else if (name == "home") s.scene = std::make_shared<const Scene>(finish_scene(builders::furnished_home().scene, {builders::kHomeTestEdge}));
    else throw InputError("bench cache: unknown scene '" + name + "' (room, building, real-room, home)");
    bench_scene(s, caches, probes, dir, bounces, registry);
  }
  return 0;
}

} // namespace hilight::bench
