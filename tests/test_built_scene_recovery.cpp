// Issue 10's randomized recovery on the built scenes (a two-storey building,
// an L corridor, a product on a turntable, a stage lit by spotlights):
// seeded random light configurations, full solves with the defaults (only
// the target given; the stage's spots are found without hints).
// Asserted per scene: the right count in >= 95% of trials; D̄ <= 1.5% and a
// mean position error <= 1% of the diagonal in every trial with the right
// count. CI runs a few trials a scene; the hidden [built-sweep] case runs 20.
// The engine is a real model (assimp-testmodels' glTF), lit the same way.
#include "hilight/fixtures/built_scenes.hpp"
#include "hilight/io/ply.hpp"
#include "hilight/solve/solve_renderers.hpp"
#include "hilight/solve/solver.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <iostream>

using namespace hilight;

namespace {

struct Outcome {
  size_t trials = 0, right = 0, good = 0;
};

/// Mean distance from each true light to the found light matched to it
/// (greedy, nearest pair first); `found` and `truth` have the same size.
float mean_position_error(const Lighting& found, const Lighting& truth) {
  std::vector<std::tuple<float, size_t, size_t>> pairs;
  for (size_t i = 0; i < found.size(); ++i)
    for (size_t j = 0; j < truth.size(); ++j) pairs.emplace_back(glm::length(found[i].position - truth[j].position), i, j);
  std::sort(pairs.begin(), pairs.end());
  std::vector<char> used_f(found.size()), used_t(truth.size());
  float sum = 0.f;
  for (const auto& [d, i, j] : pairs)
    if (!used_f[i] && !used_t[j]) used_f[i] = used_t[j] = 1, sum += d;
  return sum / float(truth.size());
}

/// Distance between the two closest lights, as a share of `diagonal`.
float closest_pair(const Lighting& lights, float diagonal) {
  float closest = std::numeric_limits<float>::max();
  for (size_t i = 0; i < lights.size(); ++i)
    for (size_t j = i + 1; j < lights.size(); ++j) closest = std::min(closest, glm::length(lights[i].position - lights[j].position));
  return closest / diagonal;
}

/// What a scene's trials vary beyond the count: its tessellation (0: the
/// default), the fewest lights, the share of spots (RandomLightRules).
struct TrialScene {
  float max_edge = 0.f;
  size_t min_lights = 1;
  float spot_share = 0.f;
  std::vector<std::string> renderer;  ///< the renderer's settings (none: its defaults, every bounce)
  double max_dbar = 0.015;             ///< D̄ asked of a trial with the right count
};

/// `min_apart`: the share of the diagonal random lights keep between them.
Outcome recovery_trials(builders::BuiltScene (*make)(), const std::vector<uint64_t>& seeds, size_t max_lights,
                        float min_apart = builders::RandomLightRules{}.min_apart, const TrialScene& kind = {}) {
  builders::BuiltScene built = make();
  auto scene = std::make_shared<const Scene>(finish_scene(built.scene, {kind.max_edge}));
  auto rays = std::make_shared<const RayScene>(*scene);
  const auto settings = reference_renderer_settings(kind.renderer, 1);
  auto reference = test::make_renderer("embree", scene, settings);
  auto fast = test::make_renderer("embree", scene, fast_renderer_settings(test::registry().renderer_traits("embree"), settings));
  auto sampler = test::registry().create_sampler("importance", {});
  auto optimizer = test::registry().create_optimizer("varpro", {});
  // Sweeps may compare light caches: HILIGHT_CACHE=grid|adaptive|none.
  const char* cache_name = std::getenv("HILIGHT_CACHE");
  const std::string cache_choice = cache_name ? cache_name : PluginDefaults::cache;
  auto cache = cache_choice == PluginDefaults::no_cache ? nullptr : test::registry().create_cache(cache_choice, {});
  const auto dir = test::output_dir("built_recovery_" + built.name);
  Outcome out;
  for (const uint64_t seed : seeds) {
    std::mt19937_64 rng(seed);
    builders::RandomLightRules rules;
    rules.max_count = max_lights;
    rules.min_count = kind.min_lights;
    rules.min_apart = min_apart;
    rules.spot_share = kind.spot_share;
    const Lighting truth = builders::random_lights(built, *rays, rng, rules);
    REQUIRE(!truth.empty());
    write_illuminated_ply(dir / "target.ply", *scene, reference->illuminate(SurfacePoints::from_vertices(*scene), truth));
    const Target target = read_target(dir / "target.ply", *scene, *rays);
    SolveSettings s;
    s.cache_dir = dir / "cache";
    if (const char* spots = std::getenv("HILIGHT_PROPOSE_SPOTS")) s.propose_spots = std::string(spots) == "1";  // sweeps: on/off
    Solver solver(scene, rays, *fast, *reference, *sampler, *optimizer, cache.get(), s);
    SolveReport report;
    const Lighting found = solver.solve(target, report);
    const bool right = found.size() == truth.size();
    const float error = right ? mean_position_error(found, truth) / scene->diagonal() : 1.f;
    out.right += right;
    out.good += right && report.dbar <= kind.max_dbar && error <= 0.01f;
    ++out.trials;
    std::cout << built.name << ", seed " << seed << ": " << found.size() << " lights (true " << truth.size() << "), D̄ "
              << 100 * report.dbar << "%, position error " << 100 * error << "% of the diagonal"
              << (report.open_space ? ", lit from outside" : "") << ", " << report.seconds["total"] << " s"
              << (truth.size() > 1 ? ", closest lights " + std::to_string(100 * closest_pair(truth, scene->diagonal())) + "% of the diagonal apart" : "")
              << "\n";
    if (std::getenv("HILIGHT_TRIALS")) {  // rerunning a few: show them
      auto show = [](const char* what, const Light& l) {
        std::cout << "  " << what << (l.type == LightType::Spot ? " spot " : " point ") << "(" << l.position.x << ", " << l.position.y
                  << ", " << l.position.z << ")";
        if (l.type == LightType::Spot)
          std::cout << " dir (" << l.direction.x << ", " << l.direction.y << ", " << l.direction.z << ") cutoff " << l.cutoff_deg
                    << " falloff " << l.falloff_deg;
        std::cout << " I " << l.intensity.g << "\n";
      };
      std::cout << " ";
      for (const auto& [stage, secs] : report.seconds) std::cout << " " << stage << " " << secs << " s;";
      std::cout << "\n";
      for (const StageRecord& r : report.stages)
        std::cout << "  stage " << r.name << ": " << (r.skipped.empty() ? "" : "skipped (" + r.skipped + "), ") << 100 * r.dbar_before
                  << "% -> " << 100 * r.dbar_after << "%" << (r.kept ? ", kept" : "") << ", " << r.seconds << " s\n";
      std::cout << "  seeds " << report.seed_lights << " of " << report.seeds_tried << " tried\n";
      for (const auto& l : truth) show("true ", l);
      for (const auto& l : found) show("found", l);
    }
    if (right) {
      CHECK(report.dbar <= kind.max_dbar);
      CHECK(error <= 0.01f);
    }
  }
  std::cout << built.name << ": right count in " << out.right << " of " << out.trials << " trials (failure rate "
            << 100.0 * double(out.trials - out.right) / double(out.trials) << "%), all good in " << out.good << "\n";
  return out;
}

/// Seeds first_seed, first_seed + 1, ... (`trials` of them).
Outcome recovery_trials(builders::BuiltScene (*make)(), uint64_t first_seed, size_t trials, size_t max_lights,
                        float min_apart = builders::RandomLightRules{}.min_apart, const TrialScene& kind = {}) {
  std::vector<uint64_t> seeds(trials);
  for (size_t t = 0; t < trials; ++t) seeds[t] = first_seed + t;
  return recovery_trials(make, seeds, max_lights, min_apart, kind);
}

/// "first,count" from HILIGHT_TRIALS, else the defaults.
std::pair<uint64_t, size_t> trial_range(uint64_t first, size_t count) {
  const char* env = std::getenv("HILIGHT_TRIALS");
  if (!env) return {first, count};
  return {std::stoull(env), std::strchr(env, ',') ? std::stoul(std::strchr(env, ',') + 1) : count};
}

void check_rate(const Outcome& o) { CHECK(o.right * 100 >= o.trials * 95); }

} // namespace

TEST_CASE("built scenes: random lights stand apart, clear of surfaces, in their zones", "[built]") {
  for (auto make : {builders::two_storey_building, builders::l_corridor, builders::product_on_turntable, builders::stage}) {
    const builders::BuiltScene built = make();
    INFO(built.name);
    const Scene scene = finish_scene(built.scene, {});
    const RayScene rays(scene);
    std::mt19937_64 rng(11);
    const builders::RandomLightRules rules;
    const Lighting lights = builders::random_lights(built, rays, rng, rules);
    REQUIRE(lights.size() >= rules.min_count);
    for (size_t i = 0; i < lights.size(); ++i) {
      CHECK_FALSE(rays.closest_point(lights[i].position, 0.99f * rules.clearance * scene.diagonal()).valid());
      bool in_zone = false;
      for (const auto& z : built.zones) in_zone |= z.contains(lights[i].position);
      CHECK(in_zone);
      for (size_t j = i + 1; j < lights.size(); ++j)
        CHECK(glm::length(lights[i].position - lights[j].position) > rules.min_apart * scene.diagonal());
    }
  }
}

TEST_CASE("recovery: random lights in the rooms of a two-storey building", "[solve][built][recovery]") {
  check_rate(recovery_trials(builders::two_storey_building, 300, 2, 8));
}

TEST_CASE("recovery: random lights along an L-shaped corridor", "[solve][built][recovery]") {
  check_rate(recovery_trials(builders::l_corridor, 400, 2, 4));
}

TEST_CASE("recovery: random key, fill and rim lights around a product, outside its bounds", "[solve][built][recovery]") {
  check_rate(recovery_trials(builders::product_on_turntable, 500, 2, 3));
}

TEST_CASE("recovery: random key, fill and rim lights around a real product (the glTF engine), outside its bounds",
          "[solve][built][recovery][real][slow]") {
  check_rate(recovery_trials(builders::engine_product, 700, 1, 3));
}

TEST_CASE("recovery: random spotlights over a stage, no hints", "[solve][built][recovery][spot][slow]") {
  check_rate(recovery_trials(builders::stage, 600, 2, 3));
}

/// The home's trials: one bounce keeps 20 solves within the suite's
/// minutes (HILIGHT_BOUNCES=all sweeps it with every bounce).
TrialScene home_trials(float spot_share) {
  const char* bounces = std::getenv("HILIGHT_BOUNCES");
  // D̄ up to 3%: a lamp 0.18 m under a ceiling found 2 mm off (seed 917)
  // leaves D̄ 2.2% on the hot spot over it, though every light is right.
  return {builders::kHomeTestEdge, 2, spot_share, {std::string("bounces=") + (bounces ? bounces : "1")}, 0.03};
}

// Issue 33: a furnished flat of five rooms joined by doorways (the IFC
// house's ground floor, real models on its tables), 2–6 lamps hanging under
// its ceilings. 6 seeded layouts in CI (the suite's minutes), every count
// right; the 20-layout sweep is the hidden [home-sweep] below (20 of 20).
// Then seed 914 of the sweep, in the same run so that it finds the light
// cache built: the split-lamps move made one lamp into itself and a light
// of 6e-5 its intensity pressed against the ceiling, fitting bounce noise at
// a few samples. A split may leave no weak light more (eq. 6).
TEST_CASE("recovery: 2 to 6 ceiling lamps in the rooms of a furnished five-room home, none split into a weak light",
          "[solve][built][recovery][home]") {
  const auto [first, count] = trial_range(900, 6);
  std::vector<uint64_t> seeds;
  for (size_t t = 0; t < count; ++t) seeds.push_back(first + t);
  if (!std::getenv("HILIGHT_TRIALS")) seeds.push_back(914);
  const Outcome o = recovery_trials(builders::furnished_home, seeds, 6, builders::RandomLightRules{}.min_apart, home_trials(0.f));
  CHECK(o.right == o.trials);
}

TEST_CASE("recovery sweep: 20 ceiling-lamp layouts in the furnished home (bench)", "[.][home-sweep]") {
  const auto [first, count] = trial_range(900, 20);
  const Outcome o = recovery_trials(builders::furnished_home, first, count, 6, builders::RandomLightRules{}.min_apart, home_trials(0.f));
  CHECK(o.right + 1 >= o.trials);
}

// Seed 904 of the spot sweep below: four point lamps and a downlight spot
// tilted 20° in the hall. The points answer left the spot's pool dark (D̄
// 5.4% at the samples) and the spot search, spots against all the lamps at
// once, lost: 4 lights. The add-a-missing-spot move screens spots from what
// the lamps leave and keeps the one that pays: 5 lights, D̄ 0.4%.
TEST_CASE("recovery: a downlight spot among four ceiling lamps in the five-room home", "[solve][built][recovery][home][spot]") {
  const Outcome o = recovery_trials(builders::furnished_home, std::vector<uint64_t>{904}, 6, builders::RandomLightRules{}.min_apart,
                                    home_trials(0.2f));
  CHECK(o.right == 1);
  CHECK(o.good == 1);
}

// The same with a fifth of the lamps downlight spots (aimed down, tilted up
// to 35°, 20–40° wide) among the point lamps: a spot beside point lamps is
// found by the add-a-missing-spot move (8 of the first 8 layouts right,
// 5 of 8 before it); a sweep of minutes, so out of CI (docs/benchmarks.md).
TEST_CASE("recovery sweep: ceiling lamps and downlight spots in the furnished home (bench)", "[.][home-spot-sweep]") {
  const auto [first, count] = trial_range(900, 20);
  const Outcome o = recovery_trials(builders::furnished_home, first, count, 6, builders::RandomLightRules{}.min_apart, home_trials(0.2f));
  CHECK(o.right + 1 >= o.trials);
}

TEST_CASE("recovery sweep: 20 configurations a built scene (bench)", "[.][built-sweep]") {
  const char* only = std::getenv("HILIGHT_SCENE");
  struct Kind {
    const char* name;
    builders::BuiltScene (*make)();
    uint64_t seed;
    size_t max_lights;
  };
  for (const Kind& k : {Kind{"building", builders::two_storey_building, 300, 8}, Kind{"corridor", builders::l_corridor, 400, 4},
                        Kind{"product", builders::product_on_turntable, 500, 3}, Kind{"stage", builders::stage, 600, 3},
                        Kind{"engine", builders::engine_product, 700, 3}}) {
    if (only && std::strcmp(only, k.name) != 0) continue;
    const auto [first, count] = trial_range(k.seed, 20);
    check_rate(recovery_trials(k.make, first, count, k.max_lights));
  }
}

TEST_CASE("recovery: two lamps 0.44 m apart in one room of the building are found as two", "[solve][built][recovery][split][slow]") {
  // Seed 328 of the close-lamp sweep: 8 lamps, two of them 2.7% of the
  // diagonal apart; found as one (7 lights, D̄ 3.1%) until a poor fit tried
  // splitting its worst-explained light (Solver::split_lamps).
  check_rate(recovery_trials(builders::two_storey_building, 328, 1, 8, 0.02f));
}

TEST_CASE("recovery sweep: lamps close together in the building's rooms (bench)", "[.][close-sweep]") {
  // Random lights 2% of the diagonal apart at least (0.3 m in the building),
  // not the 10% the other sweeps keep: close lamps must not be found as one.
  const auto [first, count] = trial_range(320, 20);
  check_rate(recovery_trials(builders::two_storey_building, first, count, 8, 0.02f));
}
