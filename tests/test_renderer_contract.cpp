// The renderer contract (issue 11): the same cases for every registered
// renderer that can run here, so a new renderer plugin is held to all of them
// by being registered. Each case runs at bounces 0 (the direct light every
// renderer computes exactly) unless it says otherwise.
#include "hilight/bounces.hpp"
#include "hilight/error.hpp"
#include "hilight/registry.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "support.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <sstream>

using namespace hilight;

namespace {

/// Registered renderers, each case once per name; "" when none can run.
/// HILIGHT_CONTRACT_RENDERERS (comma-separated) holds the cases to those
/// renderers: a plugin's author runs the contract on theirs alone
/// (docs/plugins.md, tests/sdk/test_example_plugin.sh).
std::vector<std::string> renderer_names() {
  std::vector<std::string> names = test::registry().names("renderer");
  const char* only = std::getenv("HILIGHT_CONTRACT_RENDERERS");
  if (!only || !*only) return names;
  std::vector<std::string> wanted;
  std::stringstream list(only);
  for (std::string name; std::getline(list, name, ',');)
    if (!name.empty()) wanted.push_back(name);
  for (const auto& name : wanted)
    if (std::find(names.begin(), names.end(), name) == names.end())
      FAIL("HILIGHT_CONTRACT_RENDERERS names '" << name << "', which is not a loaded renderer");
  return wanted;
}

/// A closed 4 x 3 x 4 room with a floating slab: shadows, creases, both sides.
std::shared_ptr<const Scene> room() {
  static auto scene = [] {
    Scene raw = builders::box_room({4.f, 3.f, 4.f}, Rgb(0.7f));
    builders::add_box(raw, {1.5f, 0.8f, 2.f}, {2.5f, 1.f, 3.f}, Rgb(0.3f, 0.5f, 0.7f), false, "floating slab");
    return test::finish(std::move(raw), 0.5f);
  }();
  return scene;
}

/// Every other vertex of the room: few enough for POV-Ray's runs.
SurfacePoints some_points(const Scene& scene) {
  SurfacePoints all = SurfacePoints::from_vertices(scene), some;
  for (size_t i = 0; i < all.size(); i += 2) {
    some.positions.push_back(all.positions[i]);
    some.normals.push_back(all.normals[i]);
    some.albedo.push_back(all.albedo[i]);
  }
  return some;
}

/// Relative tolerance of a renderer's values: POV-Ray's bakes are half floats.
double tolerance(const std::string& name) { return name == "povray" ? 2e-3 : 1e-4; }

/// |a − b| within `relative` of b, plus `floor` of the largest value (`scale`).
void require_close(const std::vector<Rgb>& a, const std::vector<Rgb>& b, double relative, double scale, double floor = 1e-5) {
  REQUIRE(a.size() == b.size());
  for (size_t i = 0; i < a.size(); ++i)
    for (int c = 0; c < 3; ++c) REQUIRE(std::abs(a[i][c] - b[i][c]) <= relative * std::abs(b[i][c]) + floor * scale);
}

double largest(const std::vector<Rgb>& v) {
  double m = 0;
  for (const auto& c : v) m = std::max({m, double(c.r), double(c.g), double(c.b)});
  return m;
}

struct Superposition {
  std::vector<Rgb> together, a, b, sum;
};

/// The two lights rendered together and one by one, and the sum of the two.
Superposition superposition(hilight::Renderer& renderer, const SurfacePoints& points, const Lighting& lights) {
  Superposition s;
  s.together = renderer.illuminate(points, lights);
  s.a = renderer.illuminate(points, std::span<const Light>(&lights[0], 1));
  s.b = renderer.illuminate(points, std::span<const Light>(&lights[1], 1));
  s.sum.resize(s.a.size());
  for (size_t i = 0; i < s.a.size(); ++i) s.sum[i] = s.a[i] + s.b[i];
  return s;
}

const Lighting kTwoLights = {Light::point({1.2f, 2.2f, 1.1f}, Rgb(3.f, 2.f, 1.f)),
                             Light::spot({2.8f, 2.6f, 2.9f}, {0.2f, -1.f, -0.1f}, 40.f, Rgb(0.5f, 1.f, 4.f), 8.f)};

} // namespace

TEST_CASE("contract: every renderer is linear — A and B together equal A plus B", "[renderer][contract]") {
  for (const std::string& name : renderer_names()) {
    if (test::skip_without_renderer(name)) continue;
    INFO("renderer " << name);
    auto renderer = test::make_renderer(name, room(), {"bounces=0"});
    const Superposition s = superposition(*renderer, some_points(*room()), kTwoLights);
    require_close(s.together, s.sum, tolerance(name), largest(s.together));
    CHECK(largest(s.a) > 0.0);
    CHECK(largest(s.b) > 0.0);
  }
}

TEST_CASE("contract: every renderer's illuminate equals the sum of I times its unit responses", "[renderer][contract]") {
  for (const std::string& name : renderer_names()) {
    if (test::skip_without_renderer(name)) continue;
    INFO("renderer " << name);
    auto renderer = test::make_renderer(name, room(), {"bounces=0"});
    const SurfacePoints points = some_points(*room());
    auto phi = renderer->unit_responses(points, kTwoLights);
    REQUIRE(phi.size() == points.size() * kTwoLights.size());
    auto direct = renderer->illuminate(points, kTwoLights);
    std::vector<Rgb> sum(points.size(), Rgb(0.f));
    for (size_t j = 0; j < kTwoLights.size(); ++j)
      for (size_t i = 0; i < points.size(); ++i) sum[i] += kTwoLights[j].intensity * phi[j * points.size() + i];
    require_close(direct, sum, tolerance(name), largest(direct));
  }
}

TEST_CASE("contract: every renderer gives the same values when asked twice, and from a fresh instance",
          "[renderer][contract]") {
  for (const std::string& name : renderer_names()) {
    if (test::skip_without_renderer(name)) continue;
    INFO("renderer " << name);
    const SurfacePoints points = some_points(*room());
    auto first = test::make_renderer(name, room(), {"bounces=0"});
    auto once = first->illuminate(points, kTwoLights);
    auto twice = first->illuminate(points, kTwoLights);
    auto fresh = test::make_renderer(name, room(), {"bounces=0"})->illuminate(points, kTwoLights);
    CHECK(once == twice);
    CHECK(once == fresh);
  }
}

// A renderer may keep what it learnt of a place (Embree keeps which points
// see a light's place: renderers/embree/visibility_memo.hpp). Another light
// at the same place — a narrow spot after the bare lamp, the lamp after the
// spot, another aim, another intensity — must still be lit as a renderer
// that never saw the place lights it, to the bit.
TEST_CASE("contract: a light at a place already lit renders as a fresh instance renders it", "[renderer][contract]") {
  const Vec3 place{1.9f, 2.4f, 2.1f};
  const Lighting sequence = {Light::spot(place, {0.f, -1.f, 0.f}, 20.f, Rgb(1.f), 5.f), Light::point(place, Rgb(2.f, 1.f, 0.5f)),
                             Light::spot(place, {0.6f, -0.8f, 0.f}, 50.f, Rgb(0.3f, 1.f, 2.f), 10.f),
                             Light::spot(place, {-0.3f, 0.9f, 0.3f}, 35.f, Rgb(1.f), 0.f)};
  for (const std::string& name : renderer_names()) {
    if (test::skip_without_renderer(name)) continue;
    for (const char* bounces : {"bounces=0", "bounces=1"}) {
      // POV-Ray is a new run every call, and its radiosity's values are its
      // own each run (the determinism case holds it at bounces=0).
      if (name == "povray" && std::string(bounces) != "bounces=0") continue;
      INFO("renderer " << name << ", " << bounces);
      const SurfacePoints points = some_points(*room());
      std::unique_ptr<Renderer> seasoned;
      try {
        seasoned = test::make_renderer(name, room(), {bounces});
      } catch (const InputError& e) {
        // A renderer without a bounce (the example plugin) refuses bounces=1, naming it.
        CHECK_THAT(e.what(), Catch::Contains("bounces"));
        continue;
      }
      for (size_t k = 0; k < sequence.size(); ++k) {
        INFO("light " << k << " of the sequence");
        const std::span<const Light> one(&sequence[k], 1);
        const auto kept = seasoned->illuminate(points, one);
        CHECK(largest(kept) > 0);
        CHECK(kept == test::make_renderer(name, room(), {bounces})->illuminate(points, one));
        CHECK(seasoned->unit_responses(points, one, Transport::DirectOnly) ==
              test::make_renderer(name, room(), {bounces})->unit_responses(points, one, Transport::DirectOnly));
      }
    }
  }
}

TEST_CASE("contract: every renderer refuses a setting it does not know, naming it", "[renderer][contract][bad-input]") {
  for (const std::string& name : renderer_names()) {
    if (test::skip_without_renderer(name)) continue;
    INFO("renderer " << name);
    try {
      test::make_renderer(name, room(), {"no_such_setting=1"});
      FAIL("an unknown setting was accepted");
    } catch (const InputError& e) {
      CHECK(std::string(e.what()).find("no_such_setting") != std::string::npos);
    }
    CHECK_THROWS_AS(test::make_renderer(name, room(), {"bounces=-1"}), InputError);
    // No lights, no points: zeros and an empty answer, not an error.
    auto renderer = test::make_renderer(name, room(), {"bounces=0"});
    const SurfacePoints points = some_points(*room());
    auto dark = renderer->illuminate(points, std::span<const Light>());
    REQUIRE(dark.size() == points.size());
    CHECK(largest(dark) == 0.0);
    CHECK(renderer->illuminate(SurfacePoints{}, kTwoLights).empty());
  }
}

TEST_CASE("contract: every renderer gives the analytic point light on a plane", "[renderer][contract][analytic]") {
  auto plane = test::finish(builders::plane(6.f, Rgb(0.6f)), 0.5f);
  const Light light = Light::point({0.7f, 1.9f, -0.4f}, Rgb(5.f));
  const SurfacePoints points = SurfacePoints::from_vertices(*plane);
  for (const std::string& name : renderer_names()) {
    if (test::skip_without_renderer(name)) continue;
    INFO("renderer " << name);
    auto values = test::make_renderer(name, plane, {"bounces=0"})->illuminate(points, std::span<const Light>(&light, 1));
    double worst = 0;
    for (size_t i = 0; i < points.size(); ++i) {
      DVec3 d = DVec3(light.position) - DVec3(points.positions[i]);
      double expected = 0.6 / kPi * 5.0 * std::abs(glm::dot(DVec3(points.normals[i]), glm::normalize(d))) / glm::dot(d, d);
      worst = std::max(worst, std::abs(values[i].r - expected) / expected);
    }
    INFO("worst relative error " << worst);
    CHECK(worst < (name == "povray" ? 0.01 : 0.005));
  }
}

TEST_CASE("contract: every renderer's spotlight is dark outside its cone and the point light inside",
          "[renderer][contract][spot]") {
  auto plane = test::finish(builders::plane(10.f, Rgb(0.8f)), 0.4f);
  const float height = 3.f, cutoff = 25.f;
  const Light spot = Light::spot({0.f, height, 0.f}, {0.f, -1.f, 0.f}, cutoff, Rgb(5.f));
  const SurfacePoints points = SurfacePoints::from_vertices(*plane);
  const double edge = height * std::tan(cutoff * kPi / 180.0);
  for (const std::string& name : renderer_names()) {
    if (test::skip_without_renderer(name)) continue;
    INFO("renderer " << name);
    auto values = test::make_renderer(name, plane, {"bounces=0"})->illuminate(points, std::span<const Light>(&spot, 1));
    size_t inside = 0, outside = 0;
    for (size_t i = 0; i < points.size(); ++i) {
      const Vec3& p = points.positions[i];
      const double r = std::hypot(double(p.x), double(p.z));
      DVec3 d = DVec3(spot.position) - DVec3(p);
      double expected = 0.8 / kPi * 5.0 * (height / glm::length(d)) / glm::dot(d, d);
      if (r > 1.02 * edge) {
        ++outside;
        REQUIRE(values[i].r == 0.f);
      } else if (r < 0.98 * edge) {
        ++inside;
        REQUIRE(values[i].r == Approx(expected).epsilon(name == "povray" ? 0.01 : 0.005));
      }
    }
    CHECK(inside > 20);
    CHECK(outside > 20);
  }
}

TEST_CASE("contract: renderers with a first bounce stay linear in the lights", "[renderer][contract][bounce]") {
  // POV-Ray's radiosity adapts its sampling to the light it sees, so it is
  // linear only to within its own noise; the others are linear exactly.
  for (const std::string& name : renderer_names()) {
    if (name == "povray" || test::skip_without_renderer(name)) continue;
    INFO("renderer " << name);
    std::unique_ptr<Renderer> renderer;
    try {
      renderer = test::make_renderer(name, room(), {"bounces=1"});
    } catch (const InputError& e) {
      // A renderer without a bounce (the example plugin) refuses bounces=1, naming it.
      CHECK_THAT(e.what(), Catch::Contains("bounces"));
      continue;
    }
    const Superposition s = superposition(*renderer, some_points(*room()), kTwoLights);
    // Sums of hundreds of VPL or gather terms in float: rounding, not bias.
    require_close(s.together, s.sum, 1e-3, largest(s.together), 1e-4);
    // Every bounce, where a renderer carries it: the series stops per light.
    if (test::registry().renderer_traits(name).max_bounces != kAllBounces) continue;
    auto every = test::make_renderer(name, room(), {"bounces=all"});
    const Superposition all = superposition(*every, some_points(*room()), kTwoLights);
    require_close(all.together, all.sum, 1e-3, largest(all.together), 1e-4);
  }
}
