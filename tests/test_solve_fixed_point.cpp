// Issue 18's invariants on real models (Debian's assimp-testmodels), with
// seeded random lights — ceiling lamps 15–40 cm below the ceiling among them:
// - the lights that made a target are a fixed point of the solve: fine-tune
//   from them reports D̄ ≈ 0 and moves nothing, for every renderer, with and
//   without the bounce and the light cache;
// - the D̄ a solve reports is the D̄ an independent render-and-compare finds.
#include "hilight/bounces.hpp"
#include "hilight/io/ply.hpp"
#include "hilight/light_cache.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/solve/solve_renderers.hpp"
#include "hilight/solve/solver.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "random_lights.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <unistd.h>
#include <cstdlib>
#include <functional>
#include <cstring>
#include <iostream>

using namespace hilight;

namespace {

struct RealCase {
  std::string name;
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const RayScene> rays;
  Lighting truth;
};

/// Seeded lights in a scene already made (and its rays).
RealCase with_lights(const std::string& name, std::shared_ptr<const Scene> scene, std::shared_ptr<const RayScene> rays, uint64_t seed,
                     size_t lamps, size_t free_lights) {
  RealCase c{name, std::move(scene), std::move(rays), {}};
  std::mt19937_64 rng(seed);
  if (lamps) c.truth = test::random_ceiling_lamps(*c.rays, rng, lamps);
  if (free_lights) {
    Lighting more = test::random_free_lights(*c.rays, rng, free_lights);
    c.truth.insert(c.truth.end(), more.begin(), more.end());
  }
  return c;
}

RealCase make_case(const std::string& name, Scene scene, uint64_t seed, size_t lamps, size_t free_lights) {
  auto shared = std::make_shared<const Scene>(std::move(scene));
  auto rays = std::make_shared<const RayScene>(*shared);
  return with_lights(name, std::move(shared), std::move(rays), seed, lamps, free_lights);
}

/// The IFC house: a real two-storey building, two ceiling lamps and a free light.
RealCase house_case(uint64_t seed) {
  return make_case("IFC house", load_scene(builders::testmodels_dir() / "IFC/AC14-FZK-Haus.ifc"), seed, 2, 1);
}
/// The Wuson and the spider on a floor (open: no ceiling), two free lights.
RealCase curved_case(uint64_t seed) {
  return make_case("curved models", finish_scene(builders::curved_models_on_floor(), {}), seed, 0, 2);
}
/// A room furnished with real models, two ceiling lamps and a free light.
RealCase room_case(uint64_t seed) {
  return make_case("real furnished room", finish_scene(builders::real_furnished_room(), {}), seed, 2, 1);
}

/// A solve set up as the CLI sets it up, on a target rendered and written as
/// `hilight render` writes it, read back as `hilight solve` reads it.
struct SolveRig {
  std::unique_ptr<Renderer> reference, fast;
  std::unique_ptr<Sampler> sampler;
  std::unique_ptr<Optimizer> optimizer;
  std::unique_ptr<LightCacheBuilder> cache;  ///< null: no light cache
  std::unique_ptr<Solver> solver;
  Target target;
};

/// `r`'s solver made anew, with the light cache or without (the renderers
/// and the target kept: a renderer that has lit the scene before gives what
/// a fresh one gives, the renderer contract's test).
void set_solver(SolveRig& r, const RealCase& c, bool cache, size_t samples = 0) {
  r.cache = cache ? test::registry().create_cache(PluginDefaults::cache, {}) : nullptr;
  SolveSettings s;
  s.evaluation_points = 0;  // every point: the fixed point is asserted over the whole target
  if (samples) s.samples = samples;
  r.solver = std::make_unique<Solver>(c.scene, c.rays, *r.fast, *r.reference, *r.sampler, *r.optimizer, r.cache.get(), s);
}

/// `r`'s target made anew from `c`'s lights (in the scene `r` was rigged for).
void set_target(SolveRig& r, const RealCase& c, const std::string& renderer) {
  // Its own folder per process: ctest runs the fixed-point cases side by side.
  const auto dir = test::output_dir("fixed_point_" + renderer + "_" + std::to_string(::getpid()));
  write_illuminated_ply(dir / "target.ply", *c.scene, r.reference->illuminate(SurfacePoints::from_vertices(*c.scene), c.truth));
  r.target = read_target(dir / "target.ply", *c.scene, *c.rays);
}

std::unique_ptr<SolveRig> rig(const RealCase& c, const std::string& renderer, int bounces, bool cache, size_t samples = 0) {
  auto r = std::make_unique<SolveRig>();
  const auto settings = reference_renderer_settings({"bounces=" + bounces_text(bounces)}, 1);
  r->reference = test::make_renderer(renderer, c.scene, settings);
  r->fast = test::make_renderer(renderer, c.scene, fast_renderer_settings(test::registry().renderer_traits(renderer), settings));
  r->sampler = test::registry().create_sampler("importance", {});
  r->optimizer = test::registry().create_optimizer("varpro", {});
  set_target(*r, c, renderer);
  set_solver(*r, c, cache, samples);
  return r;
}

/// Fine-tune from the true lights with `r` (rigged for `c`); `bound`: the
/// largest D̄ it may report there.
void check_fixed_point(SolveRig& r, const RealCase& c, const std::string& renderer, int bounces, bool cache, double bound) {
  INFO(c.name << ", " << renderer << ", bounces " << bounces_text(bounces) << (cache ? ", light cache" : ", no cache"));
  SolveReport report;
  const Lighting tuned = r.solver->fine_tune(r.target, c.truth, report);
  std::cout << "fixed point: " << c.name << ", " << renderer << ", bounces " << bounces_text(bounces) << (cache ? ", cache" : ", no cache")
            << ": reported D̄ " << 100 * report.dbar << "% over " << report.dbar_points << " points\n";
  CHECK(report.dbar_points == r.target.size());
  CHECK(report.dbar <= bound);
  REQUIRE(tuned.size() == c.truth.size());
  for (size_t j = 0; j < tuned.size(); ++j) {
    CHECK(glm::length(tuned[j].position - c.truth[j].position) <= 1e-3f * c.scene->diagonal());
    for (int k = 0; k < 3; ++k) CHECK(tuned[j].intensity[k] == Approx(c.truth[j].intensity[k]).epsilon(0.005));
  }
}

void check_fixed_point(const RealCase& c, const std::string& renderer, int bounces, bool cache, double bound,
                       size_t samples = 0) {
  auto r = rig(c, renderer, bounces, cache, samples);
  check_fixed_point(*r, c, renderer, bounces, cache, bound);
}

void check_fixed_points(const RealCase& c, const std::string& renderer, std::initializer_list<bool> caches = {false, true},
                        double bounce_bound = 0.001) {
  // Direct light only has no bounce for a cache to keep (a solve takes none: SolveSession).
  check_fixed_point(c, renderer, 0, false, 0.001);
  // With the bounce, one target and one pair of renderers serve the solves
  // with and without the cache.
  std::unique_ptr<SolveRig> r;
  for (bool cache : caches) {
    if (!r) r = rig(c, renderer, 1, cache);
    else set_solver(*r, c, cache);
    check_fixed_point(*r, c, renderer, 1, cache, bounce_bound);
  }
}

} // namespace

TEST_CASE("fixed point: the IFC house's random ceiling lamps stay put under fine-tune (embree)", "[solve][fixed-point][real][slow]") {
  check_fixed_points(house_case(18), "embree");
}

TEST_CASE("fixed point: random lights on the curved models stay put under fine-tune (embree)", "[solve][fixed-point][real]") {
  check_fixed_points(curved_case(7), "embree");
}

TEST_CASE("fixed point: the real furnished room's ceiling lamps stay put under fine-tune (embree)", "[solve][fixed-point][real]") {
  check_fixed_points(room_case(3), "embree");
}

TEST_CASE("fixed point with every bounce: the IFC house's lamps and the curved models' lights stay put (embree)",
          "[solve][fixed-point][real][bounce][slow]") {
  // One with the light cache (its all-bounce responses), one without: both
  // pairs were measured at D̄ 0%; the four together take 2.7 min, the
  // house's cache build most of it, so the cache is checked on the curved models.
  check_fixed_point(house_case(18), "embree", kAllBounces, false, 0.001);
  check_fixed_point(curved_case(7), "embree", kAllBounces, true, 0.001);
}

TEST_CASE("fixed point: the curved models under ism-vulkan", "[solve][fixed-point][real][ism]") {
  if (test::skip_without_renderer("ism-vulkan")) return;
  check_fixed_points(curved_case(7), "ism-vulkan");
}

// POV-Ray bakes the points of each call in a run of its own (about a
// second each), so only its direct light is checked here, without the light
// cache (building it takes hundreds of runs) and with 1000 samples: 0.02–0.2%
// D̄ at the true lights were measured, from its output's precision, hence
// the 0.5% bound. Its first bounce (radiosity) depends on the whole point set
// baked at once: 0.2–0.3% measured at the true lights (not in ctest: 6 min).
TEST_CASE("fixed point: the curved models under povray, direct light", "[solve][fixed-point][real][povray]") {
  if (test::skip_without_renderer("povray")) return;
  check_fixed_point(curved_case(7), "povray", 0, false, 0.005, 1000);
}

TEST_CASE("a solve's reported D̄ is what an independent render-and-compare finds", "[solve][fixed-point][real][report]") {
  for (const RealCase& c : {curved_case(11), room_case(12)}) {
    INFO(c.name);
    auto r = rig(c, "embree", 1, true);
    SolveReport report;
    const Lighting found = r->solver->solve(r->target, report);
    // Independent: a fresh renderer with the user's settings, every vertex.
    auto fresh = test::make_renderer("embree", c.scene, reference_renderer_settings({"bounces=1"}, 1));
    const auto target = fresh->illuminate(SurfacePoints::from_vertices(*c.scene), c.truth);
    const double independent = test::dbar(fresh->illuminate(SurfacePoints::from_vertices(*c.scene), found), target);
    std::cout << "reported vs independent: " << c.name << ": " << found.size() << " lights (true " << c.truth.size()
              << "), reported " << 100 * report.dbar << "%, independent " << 100 * independent << "%\n";
    CHECK(std::abs(report.dbar - independent) <= 0.001);
  }
}

namespace {

struct TrialOutcome {
  size_t right = 0, trials = 0, good = 0;
};

/// Full solves with the defaults, each on its own seeded set of 1–4 ceiling
/// lamps in the real furnished room (or in `scene_of()`).
TrialOutcome ceiling_lamp_trials(uint64_t first_seed, size_t trials,
                                 const std::function<Scene()>& scene_of = [] { return finish_scene(builders::real_furnished_room(), {}); },
                                 const std::string& name = "real furnished room") {
  TrialOutcome out;
  const auto cache_dir = std::filesystem::path(HILIGHT_TEST_OUTPUT_DIR) / "ceiling_lamp_trials_cache";
  const std::string label = name == "real furnished room" ? "ceiling lamps" : "ceiling lamps (" + name + ")";
  std::filesystem::create_directories(cache_dir);
  // One scene and one pair of renderers for all the trials (a renderer that
  // has lit the scene before gives what a fresh one gives: the contract).
  const auto scene = std::make_shared<const Scene>(scene_of());
  const auto rays = std::make_shared<const RayScene>(*scene);
  std::unique_ptr<SolveRig> r;
  for (size_t t = 0; t < trials; ++t) {
    const uint64_t seed = first_seed + t;
    std::mt19937_64 pick(seed);
    const size_t lamps = 1 + pick() % 4;
    const RealCase c = with_lights(name, scene, rays, seed, lamps, 0);
    if (!r) r = rig(c, "embree", 1, true);
    else set_target(*r, c, "embree");
    SolveSettings s;
    s.cache_dir = cache_dir;
    if (const char* n = std::getenv("HILIGHT_SAMPLES")) s.samples = std::stoul(n);
    r->cache = test::registry().create_cache(PluginDefaults::cache, {});  // a fresh builder: it reads the folder's cache
    r->solver = std::make_unique<Solver>(c.scene, c.rays, *r->fast, *r->reference, *r->sampler, *r->optimizer, r->cache.get(), s);
    SolveReport report;
    const Lighting found = r->solver->solve(r->target, report);
    const bool right = found.size() == c.truth.size();
    out.right += right;
    out.good += right && report.dbar <= 0.015;
    ++out.trials;
    std::cout << label << ", seed " << seed << ": " << found.size() << " lights (true " << c.truth.size() << "), D̄ "
              << 100 * report.dbar << "%, samples " << 100 * report.dbar_samples << "%, " << report.seconds["total"] << " s\n";
    if (std::getenv("HILIGHT_TRIALS")) {
      std::cout << "  seeds " << report.seed_lights << ", cuts:";
      for (const auto& k : report.cuts)
        std::cout << " [" << k.lights << ": " << 100 * k.dbar_initial << (k.refined ? " -> " + std::to_string(100 * k.dbar_refined) : "") << "]";
      std::cout << "\n";
    }
    for (const auto& l : found) {
      float best = 1e30f;
      Vec3 nearest(0.f);
      for (const auto& truth : c.truth)
        if (glm::length(truth.position - l.position) < best) best = glm::length(truth.position - l.position), nearest = truth.position;
      const Vec3 d = l.position - nearest;
      std::cout << "  found - true: (" << d.x << ", " << d.y << ", " << d.z << ")\n";
    }
  }
  std::cout << label << ": right count and D̄ <= 1.5% in " << out.good << " of " << out.trials << " trials\n";
  return out;
}

} // namespace

TEST_CASE("ceiling lamps in a room of real models: right count and D̄ ≤ 1.5% with the defaults", "[solve][real][ceiling]") {
  // Six trials in CI (all must pass: 95% of 6 rounds up); the 40-trial sweep
  // is the hidden [sweep] case below (docs/benchmarks.md).
  const TrialOutcome o = ceiling_lamp_trials(100, 6);
  CHECK(o.good * 100 >= o.trials * 95);
}

TEST_CASE("ceiling lamps in a room of real models, the full sweep (bench)", "[.][sweep]") {
  const char* env = std::getenv("HILIGHT_TRIALS");  // "first_seed,count" to rerun a few
  const uint64_t first = env ? std::stoull(env) : 100;
  const size_t count = env && std::strchr(env, ',') ? std::stoul(std::strchr(env, ',') + 1) : 40;
  const TrialOutcome o = ceiling_lamp_trials(first, count);
  CHECK(o.good * 100 >= o.trials * 95);
}

TEST_CASE("ceiling lamps in the IFC house, the full sweep (bench, issue 10)", "[.][house-sweep]") {
  const char* env = std::getenv("HILIGHT_TRIALS");
  const uint64_t first = env ? std::stoull(env) : 200;
  const size_t count = env && std::strchr(env, ',') ? std::stoul(std::strchr(env, ',') + 1) : 20;
  const TrialOutcome o = ceiling_lamp_trials(
      first, count, [] { return load_scene(builders::testmodels_dir() / "IFC/AC14-FZK-Haus.ifc"); }, "IFC house");
  CHECK(o.good * 100 >= o.trials * 95);
}

TEST_CASE("the light cache's bounce under ceiling lamps: its error, and what anchoring leaves of it", "[solve][real][cache]") {
  // Measured where the cache matters most: lamps 15–40 cm under the ceiling
  // of the room of real models, at every vertex. Raw: trilinear interpolation
  // between grid nodes. Anchored: the refinement's view, the cache corrected
  // by the exact bounce at the lamp, moved 2 cm away.
  const RealCase c = room_case(21);
  auto fast = test::make_renderer("embree", c.scene, fast_renderer_settings(test::registry().renderer_traits("embree"), reference_renderer_settings({}, 1)));
  const auto cache = test::registry().create_cache(PluginDefaults::cache, {})->build({*c.scene, *c.rays, *fast, c.scene->light_bounds()});
  const Target target = bind_target("vertices", c.scene->positions, std::vector<Rgb>(c.scene->positions.size(), Rgb(1.f)),
                                    std::vector<float>(c.scene->positions.size(), 1.f), *c.scene, *c.rays, c.scene->normals);
  const SampleSet samples = all_samples(target);
  const auto view = cache->view(*c.rays, samples);
  const size_t m = samples.size();
  auto error_of = [&](const std::vector<Rgb>& a, const std::vector<Rgb>& exact) { return test::dbar(a, exact); };
  for (size_t j = 0; j < c.truth.size(); ++j) {
    const Light lamp = Light::point(c.truth[j].position, Rgb(1.f));
    Light moved = lamp;
    moved.position += Vec3(0.02f, -0.01f, 0.015f);
    const auto exact = fast->unit_responses(samples.points, std::span<const Light>(&lamp, 1), Transport::IndirectOnly);
    const auto exact_moved = fast->unit_responses(samples.points, std::span<const Light>(&moved, 1), Transport::IndirectOnly);
    std::vector<Rgb> cached(m, Rgb(0.f)), cached_moved(m, Rgb(0.f));
    view->add_indirect(lamp.position, cached.data());
    view->add_indirect(moved.position, cached_moved.data());
    std::vector<Rgb> anchored(m);
    for (size_t i = 0; i < m; ++i) anchored[i] = cached_moved[i] + (exact[i] - cached[i]);
    const double raw = error_of(cached, exact), after = error_of(anchored, exact_moved);
    std::cout << "light cache under a lamp " << c.scene->bounds.hi.y - lamp.position.y << " m below the ceiling: bounce error "
              << 100 * raw << "% raw, " << 100 * after << "% anchored 2.7 cm away\n";
    // The bound is what was measured (26–62% raw, 3–14% anchored under the
    // ceiling, 9% and 1% for a free light): the grid interpolates 1/d² across
    // nodes 0.35 m apart. The solve's answer does not depend on it — its last
    // word is the reference (fixed-point tests above) — but cut refinement
    // near ceilings does (docs/solve.md, "The light cache near surfaces").
    CHECK(raw < 0.75);
    CHECK(after < 0.2);
  }
}
