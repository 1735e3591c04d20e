// Cross-validation of the ism-vulkan renderer against Embree on the same
// scenes and lights. Skipped ("SKIPPED: …") where no Vulkan device exists.
// Validation layers are on for every ism-vulkan renderer these tests make:
// any validation error fails the call that caused it.
#include "hilight/camera.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "hilight/ray_scene.hpp"
#include "random_lights.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <iostream>

using namespace hilight;

namespace {

std::unique_ptr<Renderer> ism(std::shared_ptr<const Scene> scene, std::vector<std::string> settings = {}) {
  settings.push_back("validation=true");
  return test::make_renderer("ism-vulkan", std::move(scene), settings);
}

/// The bundled demo room (furniture on a floor: shadows, contact corners), at
/// the tessellation `hilight solve` uses by default.
std::shared_ptr<const Scene> furnished_room() {
  Scene raw = builders::furnished_room();
  raw.update_bounds();
  const float max_edge = raw.diagonal() / 40.f;
  return test::finish(std::move(raw), max_edge);
}

/// A closed room with a floating slab: every light path stays inside.
std::shared_ptr<const Scene> closed_room() {
  Scene raw = builders::box_room({4.f, 3.f, 5.f}, Rgb(0.7f, 0.6f, 0.5f));
  builders::add_box(raw, {1.5f, 0.8f, 2.f}, {2.5f, 1.f, 3.f}, Rgb(0.3f, 0.5f, 0.7f), false, "floating slab");
  return test::finish(std::move(raw), 0.25f);
}

} // namespace

TEST_CASE("ism-vulkan: direct light with shadows matches Embree within 2% D-bar", "[ism][cross][shadow]") {
  if (test::skip_without_renderer("ism-vulkan")) return;
  auto scene = furnished_room();
  auto points = SurfacePoints::from_vertices(*scene);
  Lighting lights = {Light::point({1.5f, 2.5f, 1.1f}, Rgb(2.f)), Light::point({4.6f, 2.4f, 1.4f}, Rgb(2.f, 1.9f, 1.7f)),
                     Light::point({2.3f, 1.6f, 3.9f}, Rgb(1.6f, 1.7f, 2.f))};
  auto embree = test::make_renderer("embree", scene, {"bounces=0"})->illuminate(points, lights);
  auto gpu = ism(scene, {"bounces=0"})->illuminate(points, lights);
  double d = test::dbar(gpu, embree);
  INFO("D-bar " << d << " over " << points.size() << " points");
  CHECK(d < 0.02);
}

TEST_CASE("ism-vulkan: a spotlight matches Embree within 2% D-bar, dark outside its cone", "[ism][cross][spot]") {
  if (test::skip_without_renderer("ism-vulkan")) return;
  auto scene = furnished_room();
  auto points = SurfacePoints::from_vertices(*scene);
  Lighting lights = {Light::spot({3.f, 2.8f, 1.5f}, {-0.3f, -1.f, 0.4f}, 35.f, Rgb(6.f), 8.f),
                     Light::spot({5.f, 2.f, 4.f}, {-1.f, -0.6f, -0.2f}, 20.f, Rgb(3.f))};
  auto embree = test::make_renderer("embree", scene, {"bounces=0"})->illuminate(points, lights);
  auto gpu = ism(scene, {"bounces=0"})->illuminate(points, lights);
  double d = test::dbar(gpu, embree);
  size_t lit_outside = 0;
  for (size_t i = 0; i < points.size(); ++i) lit_outside += embree[i].r == 0.f && gpu[i].r > 0.f;
  INFO("D-bar " << d << "; points lit by ism-vulkan but dark in Embree: " << lit_outside);
  CHECK(d < 0.02);
  CHECK(lit_outside < points.size() / 200);
}

TEST_CASE("ism-vulkan: the first bounce of a closed room matches Embree, closer with more VPLs", "[ism][cross][bounce]") {
  if (test::skip_without_renderer("ism-vulkan")) return;
  auto scene = closed_room();
  auto points = SurfacePoints::from_vertices(*scene);
  Lighting lights = {Light::point({1.f, 2.4f, 1.2f}, Rgb(4.f))};
  auto embree = test::make_renderer("embree", scene, {"bounce_samples=1024"})->illuminate(points, lights);
  auto embree_direct = test::make_renderer("embree", scene, {"bounces=0"})->illuminate(points, lights);
  auto bounce_of = [&](const std::vector<Rgb>& total) {
    std::vector<Rgb> out(total.size());
    for (size_t i = 0; i < total.size(); ++i) out[i] = total[i] - embree_direct[i];
    return out;
  };
  auto gpu = ism(scene)->illuminate(points, lights);
  auto few = ism(scene, {"vpls=16"})->illuminate(points, lights);
  double total = test::dbar(gpu, embree);
  double bounce = test::dbar(bounce_of(gpu), bounce_of(embree)), bounce_few = test::dbar(bounce_of(few), bounce_of(embree));
  double sum_gpu = 0, sum_embree = 0;
  for (size_t i = 0; i < points.size(); ++i) sum_gpu += gpu[i].r - embree_direct[i].r, sum_embree += embree[i].r - embree_direct[i].r;
  INFO("bounce energy ism/embree " << sum_gpu / sum_embree);
  INFO("D-bar of the total " << total << "; of the bounce alone " << bounce << " (256 VPLs) vs " << bounce_few << " (16 VPLs)");
  // Stated tolerance: 8% D̄ of the total (measured 6.8%); the bounce alone is
  // further off (24%), mostly at concave creases, where the clamped VPLs
  // miss the strong near-field bounce (docs/ism-vulkan.md).
  CHECK(total < 0.08);
  CHECK(bounce < bounce_few);
}

TEST_CASE("ism-vulkan: every bounce in the furnished room matches Embree's every bounce", "[ism][cross][bounce]") {
  if (test::skip_without_renderer("ism-vulkan")) return;
  auto scene = furnished_room();
  auto points = SurfacePoints::from_vertices(*scene);
  RayScene rays(*scene);
  std::mt19937_64 rng(32);
  const Lighting lights = test::random_ceiling_lamps(rays, rng, 3);
  auto embree = test::make_renderer("embree", scene, {"bounces=all", "bounce_samples=256"})->illuminate(points, lights);
  auto gpu_renderer = ism(scene, {"bounces=all"});
  auto gpu = gpu_renderer->illuminate(points, lights);
  auto gpu_one = ism(scene, {"bounces=1"})->illuminate(points, lights);
  double sum_gpu = 0, sum_embree = 0, sum_one = 0;
  for (size_t i = 0; i < points.size(); ++i) sum_gpu += gpu[i].g, sum_embree += embree[i].g, sum_one += gpu_one[i].g;
  const double d = test::dbar(gpu, embree), d_one = test::dbar(gpu_one, embree);
  INFO("D-bar against Embree's every bounce: " << d << " (ism-vulkan's one bounce: " << d_one << "); light ism/embree "
                                               << sum_gpu / sum_embree << " (one bounce " << sum_one / sum_embree << ")");
  // Measured (lavapipe): D̄ 6.6% with every bounce, 38% with one bounce;
  // the light in all 6.5% low, mostly the first bounce's (the VPLs') known
  // deficit at creases, 9% of it (docs/ism-vulkan.md).
  CHECK(d < 0.09);
  CHECK(d < 0.25 * d_one);
  CHECK(std::abs(sum_gpu / sum_embree - 1.0) < 0.09);
  // Still Σ I_j φ_j with every bounce.
  const auto unit = gpu_renderer->unit_responses(points, lights);
  double worst = 0, scale = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    Rgb sum(0.f);
    for (size_t j = 0; j < lights.size(); ++j) sum += lights[j].intensity * unit[j * points.size() + i];
    for (int c = 0; c < 3; ++c) worst = std::max(worst, double(std::abs(sum[c] - gpu[i][c]))), scale = std::max(scale, double(gpu[i][c]));
  }
  CHECK(worst <= 1e-4 * scale);
}

TEST_CASE("ism-vulkan: an every-bounce image of the furnished room matches Embree's", "[ism][cross][bounce][image]") {
  if (test::skip_without_renderer("ism-vulkan")) return;
  Scene raw = builders::furnished_room();
  raw.update_bounds();
  auto scene = test::finish(std::move(raw), raw.diagonal() / 20.f);
  RayScene rays(*scene);
  std::mt19937_64 rng(321);
  const Lighting lights = test::random_ceiling_lamps(rays, rng, 2);
  // From a corner at eye height toward the room's centre.
  const Vec3 lo = scene->bounds.lo, hi = scene->bounds.hi, centre = 0.5f * (lo + hi);
  const Vec3 eye = lo + Vec3(0.1f, 0.55f, 0.1f) * (hi - lo);
  Camera cam;
  cam.eye = eye;
  cam.target = Vec3(centre.x, 0.3f * centre.y, centre.z);
  cam.fov_deg = 70.f;
  const int w = 96, h = 72;
  const Image embree = test::make_renderer("embree", scene, {"bounces=all", "bounce_samples=256"})->render_image(cam, lights, w, h);
  const Image every = ism(scene, {"bounces=all"})->render_image(cam, lights, w, h);
  const Image one = ism(scene, {"bounces=1"})->render_image(cam, lights, w, h);
  auto mean_relative = [&](const Image& a) {
    double sum = 0, ref = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
      if (!a.covered[i] || !embree.covered[i]) continue;
      const Rgb d = glm::abs(a.pixels[i] - embree.pixels[i]);
      sum += d.r + d.g + d.b;
      ref += embree.pixels[i].r + embree.pixels[i].g + embree.pixels[i].b;
    }
    return sum / ref;
  };
  const double d = mean_relative(every), d_one = mean_relative(one);
  size_t covered = 0;
  for (size_t i = 0; i < every.pixels.size(); ++i) covered += every.covered[i] && embree.covered[i];
  INFO("mean relative difference to Embree's every bounce: " << d << " (ism-vulkan's one bounce: " << d_one << ") over "
                                                               << covered << " pixels");
  // Measured (lavapipe): 6.0%, one bounce 52%. The image's later bounces come
  // from the vertices (ism_image.cpp), the rest from each pixel.
  CHECK(covered > size_t(w * h) / 2);
  CHECK(d < 0.08);
  CHECK(d < 0.2 * d_one);
}
