// Renderers that cast the same first-bounce gather rays (a solve's reference
// and its fast twin: the same count and seed over the same scene) share one
// gather per point set (renderers/embree/shared_gathers.hpp): the second
// casts none of its own, and every renderer's light is what it was alone.
#include "hilight/fixtures/scene_builders.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

using namespace hilight;

TEST_CASE("embree: renderers with the same gather share it, and light as they did alone", "[renderer][bounce][memory]") {
  auto scene = test::finish(builders::furnished_room(), 0.3f);
  const SurfacePoints points = SurfacePoints::from_vertices(*scene);
  const Lighting lamps = {Light::point({1.5f, 2.4f, 1.2f}, Rgb(2.f)), Light::point({4.f, 2.2f, 3.5f}, Rgb(1.f, 1.5f, 2.f))};
  const uint64_t gather_rays = uint64_t(points.size()) * 128;

  // Alone: a first call gathers (then its shadow rays, its patches' rays).
  auto reference = test::make_renderer("embree", scene, {"bounces=1"});
  const auto alone = reference->unit_responses(points, lamps);
  const uint64_t alone_rays = reference->rays_cast();
  REQUIRE(alone_rays > gather_rays);

  // The fast twin reads its hits otherwise (interpolated direct light), but
  // casts the same gather: it takes the reference's and casts none. A twin
  // over another copy of the scene (nothing to share) lights the same.
  auto twin = test::make_renderer("embree", scene, {"bounces=1", "bounce_direct=vertex", "hot_spots=off"});
  const auto twin_lit = twin->unit_responses(points, lamps);
  auto copy = test::finish(builders::furnished_room(), 0.3f);
  auto lone_twin = test::make_renderer("embree", copy, {"bounces=1", "bounce_direct=vertex", "hot_spots=off"});
  CHECK(lone_twin->unit_responses(SurfacePoints::from_vertices(*copy), lamps) == twin_lit);
  CHECK(twin->rays_cast() + gather_rays == lone_twin->rays_cast());

  // Another count of rays is another gather.
  auto coarse = test::make_renderer("embree", scene, {"bounces=1", "bounce_samples=64"});
  coarse->unit_responses(points, lamps);
  CHECK(coarse->rays_cast() >= uint64_t(points.size()) * 64);

  // The gather outlives the renderer that made it while another holds it: a
  // second reference lights as the first did alone, with all of its rays but
  // the gather's.
  reference.reset();
  auto again = test::make_renderer("embree", scene, {"bounces=1"});
  CHECK(again->unit_responses(points, lamps) == alone);
  CHECK(again->rays_cast() + gather_rays == alone_rays);
}
