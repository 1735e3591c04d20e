// The light cache plugins (grid, adaptive): their bounce against the exact
// bounce, their files (round trip, keys, damage), the adaptive one's budget,
// and a solve that finds its cache file damaged.
#include "hilight/error.hpp"
#include "hilight/light_cache.hpp"
#include "hilight/light_cache_file.hpp"
#include "hilight/solve/solve_session.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <random>

using namespace hilight;

namespace {

struct CacheRig {
  std::shared_ptr<const Scene> scene = test::finish(builders::furnished_room(), 0.3f);
  std::shared_ptr<const RayScene> rays = std::make_shared<const RayScene>(*scene);
  std::unique_ptr<Renderer> renderer = test::make_renderer("embree", scene, {"bounce_samples=64", "bounce_direct=vertex"});
  Target target = bind_target("vertices", scene->positions, std::vector<Rgb>(scene->positions.size(), Rgb(1.f)),
                              std::vector<float>(scene->positions.size(), 1.f), *scene, *rays, scene->normals);
  SampleSet samples = all_samples(target);

  std::unique_ptr<LightCache> build(const LightCacheBuilder& builder) const {
    return builder.build({*scene, *rays, *renderer, scene->light_bounds()});
  }
  /// The cached bounce of a unit light at `p` at every vertex.
  std::vector<Rgb> cached(const LightCache& cache, const Vec3& p) const {
    std::vector<Rgb> out(samples.size(), Rgb(0.f));
    cache.view(*rays, samples)->add_indirect(p, out.data());
    return out;
  }
  std::vector<Rgb> exact(const Vec3& p) const {
    const Light light = Light::point(p, Rgb(1.f));
    return renderer->unit_responses(samples.points, std::span<const Light>(&light, 1), Transport::IndirectOnly);
  }
};

/// Normalized L2 error of `a` against `exact`.
double l2_error(const std::vector<Rgb>& a, const std::vector<Rgb>& exact) {
  double num = 0, den = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    num += glm::dot(DVec3(a[i] - exact[i]), DVec3(a[i] - exact[i]));
    den += glm::dot(DVec3(exact[i]), DVec3(exact[i]));
  }
  return std::sqrt(num / den);
}

} // namespace

TEST_CASE("each light cache plugin's bounce is close to the exact bounce and survives a disk round trip", "[cache]") {
  const CacheRig rig;
  const Lighting probes = {Light::point({2.1f, 1.7f, 3.1f}, Rgb(1.f)), Light::point({3.9f, 2.3f, 1.2f}, Rgb(1.f))};
  for (const std::string name : {"grid", "adaptive"}) {
    INFO("cache " << name);
    const auto builder = test::registry().create_cache(name, {});
    const auto cache = rig.build(*builder);
    CHECK(cache->node_count() > 50);
    const auto dir = test::output_dir("cache_roundtrip_" + name);
    const Bounds bounds = rig.scene->light_bounds();
    const uint64_t key = light_cache_key(*rig.scene, rig.renderer->settings_key(), builder->settings_key(), bounds);
    save_light_cache(dir / "c.bin", key, *cache);
    LoadedCache loaded = load_light_cache(dir / "c.bin", key, *builder, rig.scene->positions.size());
    REQUIRE(loaded.cache);
    CHECK(loaded.damage.empty());
    CHECK(loaded.cache->node_count() == cache->node_count());
    // Another key (scene, renderer, setting, bounds) or no file: not loaded, and not called damage.
    for (const auto& other : {load_light_cache(dir / "c.bin", key + 1, *builder, rig.scene->positions.size()),
                              load_light_cache(dir / "missing.bin", key, *builder, rig.scene->positions.size())}) {
      CHECK_FALSE(other.cache);
      CHECK(other.damage.empty());
    }
    for (const auto& probe : probes) {
      const auto built = rig.cached(*cache, probe.position), read_back = rig.cached(*loaded.cache, probe.position);
      // The built cache holds what the file holds (half floats): a cold
      // solve and a warm one see the same numbers.
      CHECK(built == read_back);
      const double error = l2_error(built, rig.exact(probe.position));
      INFO("normalized L2 error of the cached bounce " << error);
      // Blends of nodes ~0.6 m apart (grid) or split where needed
      // (adaptive); refinement removes the rest by anchoring (solver.cpp).
      CHECK(error < 0.10);
    }
  }
}

TEST_CASE("a cache blends only the nodes on a light's side of a wall: no bounce leaks into the next room", "[cache]") {
  // Two 3 m rooms side by side, a solid wall between them (x 2.9 to 3.1) and
  // no door: a light in the left room lights nothing in the right one. The
  // grid's nodes stand 0.75 m apart, so a light 0.1 m from the wall has a
  // node behind it in its cell; blending that node would bring the right
  // room's bounce of a light standing there.
  Scene raw = builders::box_room({6.f, 3.f, 3.f});
  builders::add_box(raw, {2.9f, 0.f, 0.f}, {3.1f, 3.f, 3.f}, Rgb(0.8f), false, "wall");
  const auto scene = test::finish(std::move(raw), 0.3f);
  const RayScene rays(*scene);
  const auto renderer = test::make_renderer("embree", scene, {"bounce_samples=64", "bounce_direct=vertex"});
  const auto& points = scene->positions;
  const Target target = bind_target("vertices", points, std::vector<Rgb>(points.size(), Rgb(1.f)),
                                    std::vector<float>(points.size(), 1.f), *scene, rays, scene->normals);
  const SampleSet samples = all_samples(target);
  std::vector<size_t> right_room;
  for (size_t i = 0; i < samples.size(); ++i)
    if (points[samples.target_index[i]].x > 3.15f) right_room.push_back(i);
  REQUIRE(right_room.size() > 50);
  for (const std::string name : {"grid", "adaptive"}) {
    INFO("cache " << name);
    const auto builder = test::registry().create_cache(name, {});
    const auto cache = builder->build({*scene, rays, *renderer, scene->light_bounds()});
    for (const Vec3 light : {Vec3(2.8f, 1.4f, 1.6f), Vec3(2.75f, 2.2f, 0.9f)}) {
      INFO("light at " << light.x << " " << light.y << " " << light.z);
      std::vector<Rgb> cached(samples.size(), Rgb(0.f));
      cache->view(rays, samples)->add_indirect(light, cached.data());
      const Light unit = Light::point(light, Rgb(1.f));
      const auto exact = renderer->unit_responses(samples.points, std::span<const Light>(&unit, 1), Transport::IndirectOnly);
      double left = 0, right = 0;
      for (size_t i = 0; i < samples.size(); ++i) left += cached[i].g;
      for (size_t i : right_room) right += cached[i].g;
      CHECK(left > 0);
      CHECK(right <= 1e-6 * left);
      CHECK(l2_error(cached, exact) < 0.35);
    }
  }
}

TEST_CASE("a damaged or truncated light cache file is detected and never read", "[cache]") {
  const CacheRig rig;
  const auto builder = test::registry().create_cache("grid", Properties::from_assignments({"cells=4"}));
  const auto cache = rig.build(*builder);
  const auto dir = test::output_dir("cache_damage");
  const uint64_t key = light_cache_key(*rig.scene, rig.renderer->settings_key(), builder->settings_key(), rig.scene->light_bounds());
  save_light_cache(dir / "c.bin", key, *cache);
  std::string bytes;
  {
    std::ifstream in(dir / "c.bin", std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  REQUIRE(bytes.size() > 1000);
  auto write = [&](const std::string& contents) {
    std::ofstream out(dir / "bad.bin", std::ios::binary | std::ios::trunc);
    out << contents;
  };
  // Bytes flipped anywhere after the header, seeded.
  std::mt19937_64 pick(7);
  for (int trial = 0; trial < 20; ++trial) {
    std::string flipped = bytes;
    const size_t at = 40 + pick() % (bytes.size() - 40);
    flipped[at] = char(flipped[at] ^ (1 + pick() % 255));
    write(flipped);
    const LoadedCache loaded = load_light_cache(dir / "bad.bin", key, *builder, rig.scene->positions.size());
    INFO("byte " << at << " flipped");
    CHECK_FALSE(loaded.cache);
    CHECK_FALSE(loaded.damage.empty());
  }
  for (size_t keep : {bytes.size() - 1, bytes.size() / 2, size_t(41)}) {
    write(bytes.substr(0, keep));
    const LoadedCache loaded = load_light_cache(dir / "bad.bin", key, *builder, rig.scene->positions.size());
    INFO("truncated to " << keep << " bytes");
    CHECK_FALSE(loaded.cache);
    CHECK(loaded.damage.find("truncated") != std::string::npos);
  }
}

TEST_CASE("a solve with direct light only builds no light cache: there is no bounce to keep", "[cache][solver]") {
  const CacheRig rig;
  const Lighting truth = {Light::point({2.2f, 2.2f, 2.4f}, Rgb(1.5f))};
  const Target target = bind_target("truth", rig.scene->positions, rig.renderer->illuminate(SurfacePoints::from_vertices(*rig.scene), truth),
                                    std::vector<float>(rig.scene->positions.size(), 1.f), *rig.scene, *rig.rays, rig.scene->normals);
  for (const std::string bounces : {"0", "1"}) {
    SolveSpec spec;
    spec.renderer_settings = {"bounces=" + bounces};
    spec.cache_settings = {"cells=4"};
    spec.settings.evaluation_points = 2000;
    SolveReport report;
    SolveSession(test::registry(), spec, rig.scene, rig.rays).make_solver()->fine_tune(target, truth, report);
    CHECK(report.cache_state == (bounces == "0" ? "off" : "built"));
  }
}

TEST_CASE("a solve whose cache file is damaged builds it again", "[cache][solver]") {
  const CacheRig rig;
  const Lighting truth = {Light::point({2.2f, 2.2f, 2.4f}, Rgb(1.5f))};
  const Target target = bind_target("truth", rig.scene->positions, rig.renderer->illuminate(SurfacePoints::from_vertices(*rig.scene), truth),
                                    std::vector<float>(rig.scene->positions.size(), 1.f), *rig.scene, *rig.rays, rig.scene->normals);
  SolveSpec spec;
  spec.cache_settings = {"cells=4"};
  spec.settings.cache_dir = test::output_dir("cache_damage_solve");
  std::filesystem::remove_all(spec.settings.cache_dir);
  spec.settings.evaluation_points = 2000;
  SolveSession session(test::registry(), spec, rig.scene, rig.rays);
  SolveReport first, second, third;
  session.make_solver()->fine_tune(target, truth, first);
  CHECK(first.cache_state == "built");
  session.make_solver()->fine_tune(target, truth, second);
  CHECK(second.cache_state == "loaded");
  size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(spec.settings.cache_dir)) {
    ++files;
    std::fstream f(entry.path(), std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(std::streamoff(std::filesystem::file_size(entry.path()) / 2));
    f.put('\x5a');
  }
  REQUIRE(files == 1);
  session.make_solver()->fine_tune(target, truth, third);
  CHECK(third.cache_state == "built");
  CHECK(third.dbar == Approx(second.dbar).margin(1e-6));
}

TEST_CASE("the adaptive cache is the grid's lattice refined where its blend is wrong, within its budget", "[cache]") {
  const CacheRig rig;
  auto build = [&](const std::string& name, std::vector<std::string> settings) {
    return rig.build(*test::registry().create_cache(name, Properties::from_assignments(settings)));
  };
  const auto grid = build("grid", {});
  const auto same = build("adaptive", {"growth=1"});  // no budget for tests or splits
  const auto refined = build("adaptive", {"growth=2", "tolerance=0.01"});
  CHECK(same->node_count() == grid->node_count());
  CHECK(refined->node_count() > grid->node_count());
  CHECK(refined->node_count() <= 2 * grid->node_count());
  // Seeded light positions anywhere in the room's free space.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  const Bounds b = rig.scene->light_bounds();
  double grid_error = 0, refined_error = 0;
  size_t probes = 0;
  while (probes < 24) {
    const Vec3 p = b.lo + Vec3(u(rng), u(rng), u(rng)) * b.extent();
    if (rig.rays->inside_solid(p) || rig.rays->closest_point(p, 0.01f * rig.scene->diagonal()).valid()) continue;
    ++probes;
    const auto from_grid = rig.cached(*grid, p), from_same = rig.cached(*same, p);
    for (size_t i = 0; i < from_grid.size(); i += 97)  // the same blend of the same nodes
      CHECK(glm::length(from_same[i] - from_grid[i]) <= 1e-5f * (1.f + glm::length(from_grid[i])));
    const auto exact = rig.exact(p);
    grid_error += l2_error(from_grid, exact);
    refined_error += l2_error(rig.cached(*refined, p), exact);
  }
  INFO("mean bounce error over 24 probes: grid " << grid_error / 24 << ", refined " << refined_error / 24);
  CHECK(refined_error < grid_error);
}

TEST_CASE("cache plugins refuse settings they do not read, and --cache none takes none", "[cache]") {
  CHECK_THROWS_AS(test::registry().create_cache("grid", Properties::from_assignments({"cellz=4"})), InputError);
  CHECK_THROWS_AS(test::registry().create_cache("adaptive", Properties::from_assignments({"depth=9"})), InputError);
  CHECK_THROWS_AS(test::registry().create_cache("octree", {}), InputError);
  SolveSpec spec;
  spec.cache = PluginDefaults::no_cache;
  CHECK_NOTHROW(SolveSession::check_names(test::registry(), spec));
  spec.cache_settings = {"cells=4"};
  CHECK_THROWS_AS(SolveSession::check_names(test::registry(), spec), InputError);
}
