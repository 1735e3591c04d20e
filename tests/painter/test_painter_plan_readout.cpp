// The plan view's lux readout (core/plan_readout.hpp): under a point light
// over a floor, the lux the readout gives from the renderer's per-vertex
// radiance is the inverse-square law's 683 · I / h².
#include "core/plan_readout.hpp"
#include "hilight/surface_points.hpp"
#include "painter_fixtures.hpp"

#include <catch2/catch.hpp>

using namespace hilight;
using namespace hilight::painter;

TEST_CASE("painter plan readout: the lux below a light over a floor is 683 I / h squared", "[painter][plan]") {
  const auto world = painter_test::make_world(builders::plane(5.f, Rgb(0.6f, 0.7f, 0.8f)), 0.1f);
  const Scene& scene = *world.scene;
  Light light;
  light.position = Vec3(0.3f, 2.f, -0.2f);
  light.intensity = Rgb(4.f);
  auto renderer = test::make_renderer("embree", world.scene, {"bounces=0"});
  const std::vector<Rgb> radiance = renderer->illuminate(SurfacePoints::from_vertices(scene), Lighting{light});
  const std::vector<Rgb> albedo = scene.vertex_albedo();
  const auto lux = lux_below(*world.rays, radiance, albedo, light.position);
  REQUIRE(lux);
  CHECK(*lux == Approx(683.0 * 4.0 / (2.0 * 2.0)).epsilon(0.01));  // the nearest vertex is within 0.07 of straight below
  // Nothing below, or no result yet: no readout.
  CHECK_FALSE(lux_below(*world.rays, radiance, albedo, Vec3(0.f, -1.f, 0.f)));
  CHECK_FALSE(lux_below(*world.rays, {}, albedo, light.position));
}
