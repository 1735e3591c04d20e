// Superposition: illumination is linear in the lights' intensities, per
// channel, so render(A + B) = render(A) + render(B) and render = Σ l_j φ_j.
#include "hilight/fixtures/scene_builders.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

using namespace hilight;

TEST_CASE("rendering lights A and B together equals the sum of rendering each", "[renderer][superposition]") {
  auto scene = test::finish(builders::furnished_room(), 0.6f);
  auto renderer = test::make_renderer("embree", scene, {"bounces=1", "bounce_samples=32"});
  auto points = SurfacePoints::from_vertices(*scene);
  Lighting both = {Light::point({1.5f, 2.5f, 1.2f}, Rgb(3.f, 2.f, 1.f)),
                   Light::spot({4.f, 2.8f, 3.5f}, {0.2f, -1.f, 0.1f}, 35.f, Rgb(0.5f, 1.f, 4.f), 5.f)};
  auto ab = renderer->illuminate(points, both);
  auto a = renderer->illuminate(points, std::span<const Light>(&both[0], 1));
  auto b = renderer->illuminate(points, std::span<const Light>(&both[1], 1));
  size_t nonzero = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    Rgb sum = a[i] + b[i];
    for (int c = 0; c < 3; ++c) REQUIRE(ab[i][c] == Approx(sum[c]).epsilon(1e-5).margin(1e-9));
    nonzero += ab[i].r > 0.f;
  }
  CHECK(nonzero > points.size() / 2);
}

TEST_CASE("illuminate equals the intensity-weighted sum of unit responses (phi)", "[renderer][superposition][phi]") {
  auto scene = test::finish(builders::furnished_room(), 0.6f);
  auto renderer = test::make_renderer("embree", scene, {"bounces=1", "bounce_samples=16"});
  auto points = SurfacePoints::from_vertices(*scene);
  Lighting lights = {Light::point({1.f, 2.f, 1.f}, Rgb(2.f, 0.5f, 1.f)), Light::point({5.f, 1.5f, 4.f}, Rgb(0.1f, 3.f, 0.f)),
                     Light::spot({3.f, 2.9f, 2.5f}, {0.f, -1.f, 0.f}, 20.f, Rgb(1.f, 1.f, 2.f))};
  auto phi = renderer->unit_responses(points, lights);
  REQUIRE(phi.size() == points.size() * lights.size());
  auto direct = renderer->illuminate(points, lights);
  const size_t m = points.size();
  for (size_t i = 0; i < m; ++i) {
    Rgb sum(0.f);
    for (size_t j = 0; j < lights.size(); ++j) sum += lights[j].intensity * phi[j * m + i];
    for (int c = 0; c < 3; ++c) REQUIRE(direct[i][c] == Approx(sum[c]).epsilon(1e-5).margin(1e-9));
  }
  // Unit responses ignore the light's own intensity.
  Lighting scaled = lights;
  for (auto& l : scaled) l.intensity *= 7.f;
  CHECK(renderer->unit_responses(points, scaled) == phi);
}

TEST_CASE("channels are independent: a red light leaves green and blue dark", "[renderer][superposition]") {
  auto scene = test::finish(builders::furnished_room(), 0.8f);
  auto renderer = test::make_renderer("embree", scene, {"bounces=1", "bounce_samples=16"});
  auto points = SurfacePoints::from_vertices(*scene);
  Light red = Light::point({3.f, 2.f, 2.5f}, Rgb(5.f, 0.f, 0.f));
  auto result = renderer->illuminate(points, std::span<const Light>(&red, 1));
  float max_red = 0.f;
  for (const auto& c : result) {
    REQUIRE(c.g == 0.f);
    REQUIRE(c.b == 0.f);
    max_red = std::max(max_red, c.r);
  }
  CHECK(max_red > 0.f);
}
