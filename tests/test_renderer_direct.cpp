// Direct light (bounces 0) against analytic answers, for every renderer that
// can run here: L = albedo/π · I · |cos θ| / d² · visibility · spot factor.
#include "hilight/fixtures/scene_builders.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <cmath>

using namespace hilight;

namespace {

double analytic_radiance(const Vec3& p, const Vec3& n, const Light& light, float albedo) {
  DVec3 d = DVec3(light.position) - DVec3(p);
  double dist2 = glm::dot(d, d);
  double cos_theta = std::abs(glm::dot(DVec3(n), d / std::sqrt(dist2)));
  return albedo / kPi * light.intensity.r * cos_theta / dist2;
}

} // namespace

TEST_CASE("a point light above a large plane matches albedo/pi * I cos(theta) / d^2 at every vertex", "[renderer][analytic]") {
  auto scene = test::finish(builders::plane(10.f, Rgb(0.6f)), 0.5f);
  auto renderer = test::make_renderer("embree", scene, {"bounces=0"});
  Light light = Light::point({1.f, 2.5f, -0.5f}, Rgb(7.f));
  auto points = SurfacePoints::from_vertices(*scene);
  auto result = renderer->illuminate(points, std::span<const Light>(&light, 1));
  REQUIRE(result.size() == points.size());
  double worst = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    double expected = analytic_radiance(points.positions[i], points.normals[i], light, 0.6f);
    worst = std::max(worst, std::abs(result[i].r - expected) / expected);
    REQUIRE(result[i].g == result[i].r);  // grey albedo, white light: channels agree
  }
  INFO("worst relative error " << worst);
  CHECK(worst < 0.005);
  CHECK(points.size() > 1000);
}

TEST_CASE("two-sided shading: a light below the plane lights it like one above", "[renderer][analytic]") {
  auto scene = test::finish(builders::plane(5.f), 0.5f);
  auto renderer = test::make_renderer("embree", scene, {"bounces=0"});
  auto points = SurfacePoints::from_vertices(*scene);
  Light above = Light::point({0.3f, 2.f, 0.1f}, Rgb(3.f));
  Light below = Light::point({0.3f, -2.f, 0.1f}, Rgb(3.f));
  auto a = renderer->illuminate(points, std::span<const Light>(&above, 1));
  auto b = renderer->illuminate(points, std::span<const Light>(&below, 1));
  for (size_t i = 0; i < points.size(); ++i) REQUIRE(a[i].r == Approx(b[i].r).epsilon(1e-5));
}

TEST_CASE("a spotlight is zero outside its cone and the point-light value inside", "[renderer][analytic][spot]") {
  auto scene = test::finish(builders::plane(10.f, Rgb(0.8f)), 0.4f);
  auto renderer = test::make_renderer("embree", scene, {"bounces=0"});
  auto points = SurfacePoints::from_vertices(*scene);
  const float height = 3.f, cutoff = 25.f;
  Light spot = Light::spot({0.f, height, 0.f}, {0.f, -1.f, 0.f}, cutoff, Rgb(5.f));
  auto result = renderer->illuminate(points, std::span<const Light>(&spot, 1));
  const double edge_radius = height * std::tan(cutoff * kPi / 180.0);
  size_t inside = 0, outside = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    double r = std::hypot(points.positions[i].x, points.positions[i].z);
    if (r > edge_radius * 1.01) {
      REQUIRE(result[i].r == 0.f);
      ++outside;
    } else if (r < edge_radius * 0.99) {
      REQUIRE(result[i].r == Approx(analytic_radiance(points.positions[i], points.normals[i], spot, 0.8f)).epsilon(0.005));
      ++inside;
    }
  }
  CHECK(inside > 50);
  CHECK(outside > 1000);
}

TEST_CASE("a spotlight's soft edge falls smoothly (smoothstep in cosine) between cutoff-falloff and cutoff", "[renderer][spot]") {
  auto scene = test::finish(builders::plane(10.f, Rgb(0.8f)), 0.2f);
  auto renderer = test::make_renderer("embree", scene, {"bounces=0"});
  auto points = SurfacePoints::from_vertices(*scene);
  Light spot = Light::spot({0.f, 2.f, 0.f}, {0.f, -1.f, 0.f}, 40.f, Rgb(1.f), 20.f);
  Light point = Light::point({0.f, 2.f, 0.f}, Rgb(1.f));
  auto s = renderer->illuminate(points, std::span<const Light>(&spot, 1));
  auto p = renderer->illuminate(points, std::span<const Light>(&point, 1));
  size_t in_band = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    double angle = std::atan2(std::hypot(points.positions[i].x, points.positions[i].z), 2.0) * 180.0 / kPi;
    double ratio = p[i].r > 0 ? s[i].r / p[i].r : 0.0;
    if (angle < 19.9) REQUIRE(ratio == Approx(1.0).epsilon(1e-4));
    else if (angle > 40.1) REQUIRE(ratio == 0.0);
    else if (angle > 20.1 && angle < 39.9) {
      // Smoothstep in the cosine between the edges (docs/rendering-model.md).
      const double c = std::cos(angle * kPi / 180.0), c_out = std::cos(40.0 * kPi / 180.0), c_in = std::cos(20.0 * kPi / 180.0);
      double t = (c - c_out) / (c_in - c_out);
      // Shading happens a few mm inside the triangle (shading_point): the
      // angle there differs slightly from the vertex angle used for t.
      REQUIRE(ratio == Approx(t * t * (3 - 2 * t)).margin(1e-2));
      ++in_band;
    }
  }
  CHECK(in_band > 100);
}

TEST_CASE("a blocker casts the shadow it should", "[renderer][analytic][shadow]") {
  Scene raw = builders::plane(10.f, Rgb(0.7f));
  // A thin square blocker 1 unit above the floor, 1x1, centred under the light.
  builders::add_box(raw, {-0.5f, 1.f, -0.5f}, {0.5f, 1.05f, 0.5f}, Rgb(0.5f), false, "blocker");
  auto scene = test::finish(std::move(raw), 0.25f);
  auto renderer = test::make_renderer("embree", scene, {"bounces=0"});
  auto points = SurfacePoints::from_vertices(*scene);
  Light light = Light::point({0.f, 3.f, 0.f}, Rgb(4.f));
  auto result = renderer->illuminate(points, std::span<const Light>(&light, 1));
  // The umbra on the floor is the blocker's bottom face projected from the
  // light: half-width 0.5 * 3 / (3 - 1) = 0.75.
  size_t shadowed = 0, lit = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3& p = points.positions[i];
    if (p.y != 0.f) continue;  // floor vertices only
    float m = std::max(std::abs(p.x), std::abs(p.z));
    if (m < 0.74f) {
      REQUIRE(result[i].r == 0.f);
      ++shadowed;
    } else if (m > 0.80f) {
      REQUIRE(result[i].r == Approx(analytic_radiance(p, points.normals[i], light, 0.7f)).epsilon(0.005));
      ++lit;
    }
  }
  CHECK(shadowed >= 9);
  CHECK(lit > 1000);
}
