// Area and line sources across renderers: the 16-part expansion that POV-Ray
// and ism-vulkan draw (area_light_elements) against Embree's integration, and
// each of those renderers against Embree on the same area-lit scene. Skipped
// ("SKIPPED: …") where POV-Ray or a Vulkan device is missing.
#include "hilight/fixtures/scene_builders.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <cmath>

using namespace hilight;

namespace {

/// A floor and a back wall with a floating blocker (nothing touches), lit by
/// a tilted panel, a disk downlight and a strip on the wall.
std::shared_ptr<const Scene> area_scene() {
  Scene raw = builders::plane(4.f, Rgb(0.7f));
  builders::add_box(raw, {-4.f, 0.f, -4.2f}, {4.f, 3.f, -4.f}, Rgb(0.6f), false, "back wall");
  builders::add_box(raw, {-0.6f, 0.9f, -0.4f}, {0.4f, 1.f, 0.5f}, Rgb(0.5f, 0.4f, 0.3f), false, "blocker");
  return test::finish(std::move(raw), 0.2f);
}

Lighting area_lights() {
  return {Light::area(LightType::Rectangle, {0.f, 2.2f, 0.f}, glm::normalize(Vec3(0.2f, -1.f, 0.f)), {0.f, 0.f, 1.f}, {1.2f, 0.6f}, Rgb(3.f)),
          Light::area(LightType::Disk, {2.f, 1.8f, 1.5f}, {0.f, -1.f, 0.f}, {1.f, 0.f, 0.f}, {0.4f, 0.f}, Rgb(1.5f, 1.2f, 1.f)),
          Light::area(LightType::Line, {-1.5f, 1.2f, -3.9f}, {0.f, 0.f, 1.f}, {1.f, 0.f, 0.f}, {1.6f, 0.f}, Rgb(1.f, 1.f, 1.4f))};
}

Lighting as_elements(const Lighting& lights) {
  Lighting out;
  for (const Light& l : lights)
    for (const Light& part : area_light_elements(l, 16)) out.push_back(part);
  return out;
}

} // namespace

TEST_CASE("Embree: an area source's 16 cosine luminaires (what POV-Ray and ism-vulkan draw) render as the source", "[renderer][area]") {
  auto scene = area_scene();
  auto points = SurfacePoints::from_vertices(*scene);
  auto embree = test::make_renderer("embree", scene, {"bounces=0"});
  const Lighting lights = area_lights();
  const auto exact = embree->illuminate(points, lights);
  const auto parts = embree->illuminate(points, as_elements(lights));
  const double d = test::dbar(parts, exact);
  WARN("16 parts against the integrated sources: D-bar " << d << " over " << points.size() << " points");
  CHECK(d < 0.02);
  // Each part carries an equal share of the light and the cosine: far away
  // they add up to I0 cos. (A 2:1 panel: 6 × 2 square cells.)
  const Lighting one = {lights[0]};
  const Lighting split = as_elements(one);
  REQUIRE(split.size() == 12);
  Rgb sum(0.f);
  for (const Light& l : split) sum += l.intensity;
  CHECK(sum.r == Approx(3.f).epsilon(1e-5));
}

TEST_CASE("POV-Ray: area and line sources match Embree (direct light)", "[povray][cross][area]") {
  if (test::skip_without_renderer("povray")) return;
  auto scene = area_scene();
  auto points = SurfacePoints::from_vertices(*scene);
  const Lighting lights = area_lights();
  const auto embree = test::make_renderer("embree", scene, {"bounces=0"})->illuminate(points, lights);
  const auto pov = test::make_renderer("povray", scene, {"bounces=0"})->illuminate(points, lights);
  const double d = test::dbar(pov, embree);
  WARN("POV-Ray against Embree, area sources: D-bar " << d << " over " << points.size() << " points");
  CHECK(d < 0.03);
}

TEST_CASE("ism-vulkan: area and line sources match Embree (direct light)", "[ism][cross][area]") {
  if (test::skip_without_renderer("ism-vulkan")) return;
  auto scene = area_scene();
  auto points = SurfacePoints::from_vertices(*scene);
  const Lighting lights = area_lights();
  const auto embree = test::make_renderer("embree", scene, {"bounces=0"})->illuminate(points, lights);
  const auto gpu = test::make_renderer("ism-vulkan", scene, {"bounces=0", "validation=true"})->illuminate(points, lights);
  const double d = test::dbar(gpu, embree);
  WARN("ism-vulkan against Embree, area sources: D-bar " << d << " over " << points.size() << " points");
  CHECK(d < 0.03);
}
