// The painter's §4.1 tools on constructed scenes: region adjustment changes
// only the light that lights the region, shadows drawn behind an occluder
// point back to the light, clicking a shadow finds the occluder–light pair
// that casts it, and a region's spotlight has the least cutoff that covers it.
#include "core/region.hpp"
#include "core/region_adjust.hpp"
#include "core/scene_objects.hpp"
#include "core/shadow_candidates.hpp"
#include "core/shadow_erase.hpp"
#include "core/spot_region.hpp"
#include "hilight/error.hpp"
#include "painter_fixtures.hpp"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

using namespace hilight;
using namespace hilight::painter;
using painter_test::floor_with_boxes;

namespace {

double angle_between_deg(const Vec3& a, const Vec3& b) {
  double c = glm::dot(glm::normalize(DVec3(a)), glm::normalize(DVec3(b)));
  return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / kPi;
}

/// Floor vertices the box (object `occluder`) shadows from `light`.
std::vector<Vec3> floor_shadow(const SceneObjects& objects, const RayScene& rays, uint32_t occluder, const Vec3& light) {
  const Scene& scene = rays.scene();
  std::vector<Vec3> points;
  for (size_t v = 0; v < scene.positions.size(); ++v) {
    const Vec3& p = scene.positions[v];
    if (p.y != 0.f || scene.normals[v].y < 0.9f || objects.object_of_vertex(v) == occluder) continue;
    Vec3 d = light - p;
    Hit hit = rays.intersect(p + 1e-3f * scene.normals[v], glm::normalize(d), glm::length(d));
    if (hit.valid() && objects.object_of_triangle(hit.triangle) == occluder) points.push_back(p);
  }
  return points;
}

} // namespace

TEST_CASE("painter: objects are connected pieces of one material", "[painter]") {
  auto world = floor_with_boxes({{{-0.5f, 0.f, -0.5f}, {0.5f, 1.f, 0.5f}}, {{2.f, 0.f, 2.f}, {3.f, 0.5f, 3.f}}});
  SceneObjects objects(*world.scene);
  REQUIRE(objects.count() == 3);  // the floor and two boxes
  CHECK(glm::length(objects.centre(1) - Vec3(0.f, 0.5f, 0.f)) < 1e-5f);
  CHECK(objects.name(2) == "box1");
  CHECK(objects.triangles(1).size() >= 12);
}

TEST_CASE("painter: adjusting a region changes only the light that lights it", "[painter]") {
  auto world = floor_with_boxes({});
  auto doc = world.document();
  auto renderer = test::make_renderer("embree", world.scene, {"bounce_samples=16"});
  const Lighting lights = {Light::point({-3.f, 2.f, 0.f}, Rgb(10.f)), Light::point({3.f, 2.f, 0.f}, Rgb(10.f))};
  doc->set_lights(lights, "lights");
  const auto region = region_vertices(*world.rays, {{3.f, 0.f, 0.f}}, 0.5f);
  REQUIRE(region.size() > 3);
  RegionAdjustSettings settings;
  settings.multiplier = Rgb(2.f, 1.5f, 1.f);
  RegionAdjustResult result = adjust_region(*doc, *renderer, region, settings);
  REQUIRE(result.changed_lights == std::vector<size_t>{1});
  CHECK(result.shares[1] > 0.9);
  CHECK(doc->state().lights[0].intensity == lights[0].intensity);
  CHECK(doc->state().lights[1].intensity == Rgb(20.f, 15.f, 10.f));
  // The region's target is what the new lights give there.
  std::vector<Rgb> now = renderer->illuminate(SurfacePoints::from_vertices(*world.scene), doc->state().lights);
  for (uint32_t v : region) {
    CHECK(doc->state().weight[v] == 1.f);
    CHECK(doc->state().psi[v].r == Approx(now[v].r).epsilon(1e-3));
    CHECK(doc->state().psi[v].b == Approx(now[v].b).epsilon(1e-3));
  }
  doc->undo();
  CHECK(doc->state().lights[1].intensity == lights[1].intensity);
  CHECK(doc->painted_count() == 0);
  CHECK_THROWS_AS(adjust_region(*doc, *renderer, {}, settings), InputError);
}

TEST_CASE("painter: a shadow drawn behind an occluder points to the light", "[painter]") {
  auto world = floor_with_boxes({{{-0.5f, 0.f, -0.5f}, {0.5f, 1.f, 0.5f}}});
  SceneObjects objects(*world.scene);
  const uint32_t box = 1;
  // Tolerance: the paper's cone axis runs from the shadow's centroid through
  // the occluder's centre, which for a box (whose shadow starts at its foot)
  // is 10-16° off the true light direction here; the estimate stays within
  // 18° of it and its own shadow covers most of the stroke. A solve refines it.
  const Vec3 truth(2.5f, 3.f, 1.f);
  for (const Vec3& light : {truth, Vec3(-1.f, 2.f, 2.f)}) {
    const std::vector<Vec3> shadow = floor_shadow(objects, *world.rays, box, light);
    REQUIRE(shadow.size() > 10);
    ShadowEstimate estimate = estimate_shadow_lights(objects, LightSpace(*world.rays), {{box, shadow}});
    REQUIRE(estimate.requests.size() == 1);
    const RequestCandidates& r = estimate.requests[0];
    CHECK(r.in_cone.size() >= 8);
    CHECK(r.cone_angle_deg >= 15.0);
    REQUIRE(estimate.lights.size() == 1);
    const Vec3 found = estimate.lights[0].position;
    const double error = angle_between_deg(found - objects.centre(box), light - objects.centre(box));
    INFO("found " << found.x << ", " << found.y << ", " << found.z << "; " << error << "°");
    CHECK(error < 18.0);
    CHECK(estimate.lights[0].intensity.r > 0.f);
    const std::vector<Vec3> own = floor_shadow(objects, *world.rays, box, found);
    size_t covered = 0;
    for (const Vec3& p : shadow) covered += std::find(own.begin(), own.end(), p) != own.end();
    CHECK(double(covered) >= 0.5 * double(shadow.size()));
  }

  // A second request from another occluder lit by the same light: the
  // candidate sets overlap and are reduced to their intersection (one light).
  auto two = floor_with_boxes({{{-0.5f, 0.f, -0.5f}, {0.5f, 1.f, 0.5f}}, {{-1.f, 0.f, 2.5f}, {0.f, 1.2f, 3.5f}}});
  SceneObjects objects2(*two.scene);
  ShadowEstimate both = estimate_shadow_lights(objects2, LightSpace(*two.rays),
                                               {{1, floor_shadow(objects2, *two.rays, 1, truth)},
                                                {2, floor_shadow(objects2, *two.rays, 2, truth)}});
  REQUIRE(both.lights.size() == 1);
  CHECK(both.kept_sets[0].size() <= std::min(both.requests[0].in_cone.size(), both.requests[1].in_cone.size()));
  CHECK(angle_between_deg(both.lights[0].position - objects2.centre(1), truth - objects2.centre(1)) < 18.0);

  CHECK_THROWS_AS(estimate_shadow_lights(objects, LightSpace(*world.rays), {{7, {Vec3(0.f)}}}), InputError);
  CHECK_THROWS_AS(estimate_shadow_lights(objects, LightSpace(*world.rays), {{box, {}}}), InputError);
}

TEST_CASE("painter: clicking a shadow finds and erases the right occluder-light pair", "[painter]") {
  // Box 1 (left) shadows the click from light 0 (left, low); box 2 (right)
  // is too low to shadow it from light 1 (right, high).
  auto world = floor_with_boxes({{{-2.5f, 0.f, -0.5f}, {-1.5f, 1.5f, 0.5f}}, {{1.5f, 0.f, -0.5f}, {2.5f, 1.5f, 0.5f}}});
  SceneObjects objects(*world.scene);
  auto doc = world.document();
  const Lighting lights = {Light::point({-4.f, 3.f, 0.f}, Rgb(10.f)), Light::point({4.f, 4.f, 0.f}, Rgb(10.f))};
  doc->set_lights(lights, "lights");
  auto click = pick_near(*world.rays, {-0.8f, 0.f, 0.f});
  REQUIRE(click);
  std::vector<ShadowPair> pairs = find_shadow_pairs(objects, *world.rays, lights, *click);
  REQUIRE(pairs.size() == 1);
  CHECK(pairs[0].occluder == 1);
  CHECK(pairs[0].light == 0);
  CHECK(pairs[0].blocked_at.x == Approx(-1.5f).margin(1e-3));

  // Where both boxes shadow the floor from their lights: two pairs to pick from.
  Lighting low = {lights[0], Light::point({4.f, 3.f, 0.f}, Rgb(10.f))};
  auto both = find_shadow_pairs(objects, *world.rays, low, *pick_near(*world.rays, {-0.8f, 0.f, 0.f}));
  REQUIRE(both.size() == 2);
  CHECK(both[1].occluder == 2);
  CHECK(both[1].light == 1);

  // Erase: the pair's whole shadow is raised in the target by light 0's
  // unshadowed direct light; nothing else is painted.
  auto renderer = test::make_renderer("embree", world.scene, {"bounce_samples=16"});
  const std::vector<Rgb> before = renderer->illuminate(SurfacePoints::from_vertices(*world.scene), lights);
  std::vector<uint32_t> changed = erase_shadow(*doc, objects, *renderer, pairs[0]);
  REQUIRE(changed.size() > 5);
  CHECK(changed == shadowed_vertices(objects, *world.rays, lights, pairs[0]));
  CHECK(doc->painted_count() == changed.size());
  const Scene& scene = *world.scene;
  for (uint32_t v : changed) {
    const Vec3 p = scene.positions[v];
    const Vec3 d = lights[0].position - p;
    const float direct = 0.7f / float(kPi) * 10.f * std::abs(glm::normalize(d).y) / glm::dot(d, d);
    if (p.y == 0.f) CHECK(doc->state().psi[v].g == Approx(before[v].g + direct).epsilon(0.02));
  }
  // After the erase, the clicked point's target is what light 0 would give unblocked.
  CHECK(doc->undo_label() == "erase shadow");
}

TEST_CASE("painter: the region's spotlight has the least cutoff that covers it", "[painter]") {
  const Vec3 eye(0.f, 3.f, 3.f);
  const Vec3 direction = glm::normalize(Vec3(0.f, -3.f, -3.f));
  const std::vector<Vec3> region = {{0.3f, 0.f, 0.f}, {-0.5f, 0.f, 0.4f}, {0.2f, 0.f, -0.7f}, {0.9f, 0.f, 0.1f}};
  for (float falloff : {0.f, 4.f}) {
    SpotRegionSettings settings;
    settings.falloff_deg = falloff;
    const Light spot = spot_for_region(eye, direction, region, settings);
    CHECK(spot.type == LightType::Spot);
    CHECK(spot.position == eye);
    CHECK(glm::length(spot.direction - direction) < 1e-6f);
    CHECK(spot.falloff_deg == falloff);
    // Every point inside the full-intensity part, and a cone 0.01° narrower leaves one out.
    const double widest = max_angle_deg(eye, direction, region);
    size_t outside_narrower = 0;
    for (const Vec3& p : region) {
      const double a = angle_between_deg(p - eye, direction);
      CHECK(a <= double(spot.cutoff_deg - spot.falloff_deg));
      outside_narrower += a > double(spot.cutoff_deg - spot.falloff_deg) - 0.01;
    }
    CHECK(outside_narrower == 1);
    CHECK(double(spot.cutoff_deg) == Approx(widest + falloff).margin(2e-3));
  }
  CHECK_THROWS_AS(spot_for_region(eye, direction, {}), InputError);
  CHECK_THROWS_AS(spot_for_region(eye, direction, {{0.f, 3.f, 6.f}}), InputError);  // behind the eye
}

TEST_CASE("painter: a spotlight from a camera outside the room moves inside", "[painter]") {
  auto world = painter_test::make_world(builders::box_room({4.f, 3.f, 4.f}), 0.5f);
  const std::vector<Vec3> region = {{2.f, 0.f, 2.f}, {2.4f, 0.f, 2.3f}, {1.7f, 0.f, 2.2f}};
  const Vec3 eye(2.f, 2.f, 7.f);  // behind the wall z = 4
  const Vec3 direction = glm::normalize(Vec3(2.f, 0.f, 2.1f) - eye);
  const Light spot = spot_for_region_in_scene(LightSpace(*world.rays), eye, direction, region);
  INFO(spot.position.x << ", " << spot.position.y << ", " << spot.position.z);
  CHECK(spot.position.z < 4.f);
  CHECK(world.scene->light_bounds().contains(spot.position));
  CHECK_FALSE(world.rays->inside_solid(spot.position));
  CHECK(glm::length(spot.direction - direction) < 1e-6f);
  // Still the least cutoff that covers the region, now from the new apex.
  CHECK(double(spot.cutoff_deg) == Approx(max_angle_deg(spot.position, direction, region)).margin(2e-3));
  // A camera already inside stays where it is.
  const Vec3 inside(2.f, 2.5f, 3.5f);
  CHECK(spot_for_region_in_scene(LightSpace(*world.rays), inside, Vec3(0.f, -1.f, -0.5f), region).position == inside);
}
