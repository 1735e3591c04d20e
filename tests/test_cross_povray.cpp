// Cross-validation: the Embree renderer against the real POV-Ray 3.7 on the
// same scenes and lights, and POV-Ray against the analytic answer. Skipped,
// with the reason printed as "SKIPPED: …" (ctest reports it), where there is
// no povray program.
#include "hilight/io/image_io.hpp"
#include "hilight/io/lights_json.hpp"
#include "hilight/io/ply.hpp"
#include "hilight/ray_scene.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "random_lights.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iostream>
#include <random>

using namespace hilight;

namespace {

double analytic(const Vec3& p, const Vec3& n, const Light& l, float albedo) {
  DVec3 d = DVec3(l.position) - DVec3(p);
  double d2 = glm::dot(d, d);
  return albedo / kPi * l.intensity.r * std::abs(glm::dot(DVec3(n), d / std::sqrt(d2))) / d2;
}

/// Worst relative difference over points brighter than 1% of the brightest.
double worst_relative(const std::vector<Rgb>& a, const std::vector<Rgb>& b, size_t* compared = nullptr, size_t* where = nullptr) {
  float brightest = 0.f;
  for (const auto& v : b) brightest = std::max(brightest, v.r);
  double worst = 0;
  size_t n = 0;
  for (size_t i = 0; i < a.size(); ++i)
    if (b[i].r > 0.01f * brightest) {
      double rel = std::abs(double(a[i].r) - b[i].r) / b[i].r;
      if (rel > worst && where) *where = i;
      worst = std::max(worst, rel);
      ++n;
    }
  if (compared) *compared = n;
  return worst;
}

/// A floor with a floating blocker (nothing touches: no contact corners,
/// where illumination is discontinuous and two renderers may sample either side).
std::shared_ptr<const Scene> shadow_scene() {
  Scene raw = builders::plane(5.f, Rgb(0.7f));
  builders::add_box(raw, {-0.6f, 1.f, -0.4f}, {0.5f, 1.1f, 0.6f}, Rgb(0.5f, 0.4f, 0.3f), false, "blocker");
  return test::finish(std::move(raw), 0.3f);
}

} // namespace

TEST_CASE("POV-Ray matches the analytic point light on a plane within 1%", "[povray][cross][analytic]") {
  if (test::skip_without_renderer("povray")) return;
  auto scene = test::finish(builders::plane(5.f, Rgb(0.6f)), 0.5f);
  auto pov = test::make_renderer("povray", scene, {"bounces=0"});
  auto points = SurfacePoints::from_vertices(*scene);
  Light light = Light::point({0.4f, 2.f, -0.3f}, Rgb(3.f));
  auto result = pov->illuminate(points, std::span<const Light>(&light, 1));
  std::vector<Rgb> expected;
  for (size_t i = 0; i < points.size(); ++i) expected.push_back(Rgb(float(analytic(points.positions[i], points.normals[i], light, 0.6f))));
  size_t n = 0;
  double worst = worst_relative(result, expected, &n);
  INFO("worst relative difference " << worst << " over " << n << " points");
  CHECK(n > 300);
  CHECK(worst < 0.01);
}

TEST_CASE("Embree and POV-Ray agree per point on direct light with shadows within 1%", "[povray][cross][shadow]") {
  if (test::skip_without_renderer("povray")) return;
  auto scene = shadow_scene();
  auto points = SurfacePoints::from_vertices(*scene);
  Lighting lights = {Light::point({0.5f, 3.f, 0.2f}, Rgb(4.f, 3.f, 2.f)), Light::point({-2.f, 2.f, 1.f}, Rgb(1.f, 1.5f, 2.f))};
  auto embree = test::make_renderer("embree", scene, {"bounces=0"})->illuminate(points, lights);
  auto pov = test::make_renderer("povray", scene, {"bounces=0"})->illuminate(points, lights);
  size_t n = 0, at = 0;
  double worst = worst_relative(pov, embree, &n, &at);
  const Vec3 p = points.positions[at], nrm = points.normals[at];
  INFO("worst relative difference " << worst << " over " << n << " points, at (" << p.x << ", " << p.y << ", " << p.z
                                    << ") normal (" << nrm.x << ", " << nrm.y << ", " << nrm.z << "): Embree " << embree[at].r
                                    << ", POV-Ray " << pov[at].r);
  CHECK(n > 1000);
  CHECK(worst < 0.01);
  // Both see the same umbra: the floor under the blocker is dark in both.
  size_t dark_both = 0;
  for (size_t i = 0; i < points.size(); ++i)
    if (points.positions[i].y == 0.f && std::abs(points.positions[i].x) < 0.2f && std::abs(points.positions[i].z) < 0.2f)
      dark_both += embree[i].r < 0.6f * glm::length(Rgb(1.f)) && pov[i].r == Approx(embree[i].r).epsilon(0.01);
  CHECK(dark_both > 0);
}

TEST_CASE("Embree and POV-Ray agree on a spotlight within 1%, zero outside the cone in both", "[povray][cross][spot]") {
  if (test::skip_without_renderer("povray")) return;
  auto scene = test::finish(builders::plane(5.f, Rgb(0.8f)), 0.25f);
  auto points = SurfacePoints::from_vertices(*scene);
  Light spot = Light::spot({0.3f, 2.5f, -0.2f}, {0.2f, -1.f, 0.1f}, 27.f, Rgb(5.f));
  auto embree = test::make_renderer("embree", scene, {"bounces=0"})->illuminate(points, std::span<const Light>(&spot, 1));
  auto pov = test::make_renderer("povray", scene, {"bounces=0"})->illuminate(points, std::span<const Light>(&spot, 1));
  size_t n = 0, dark = 0, disagree_dark = 0;
  double worst = worst_relative(pov, embree, &n);
  for (size_t i = 0; i < points.size(); ++i)
    if (embree[i].r == 0.f) {
      ++dark;
      disagree_dark += pov[i].r != 0.f;
    }
  INFO("worst relative difference " << worst << " over " << n << " lit points; " << disagree_dark << " of " << dark << " dark points lit by POV-Ray");
  CHECK(n > 100);
  CHECK(dark > 1000);
  CHECK(worst < 0.01);
  // A vertex can sit a hair from the cone's edge; allow a handful of those.
  CHECK(disagree_dark <= 3);
}

TEST_CASE("the first bounce of a closed room: Embree and POV-Ray agree within 5% D-bar", "[povray][cross][bounce]") {
  if (test::skip_without_renderer("povray")) return;
  Scene raw = builders::box_room({4.f, 3.f, 5.f}, Rgb(0.7f, 0.6f, 0.5f));
  builders::add_box(raw, {1.5f, 0.8f, 2.f}, {2.5f, 1.f, 3.f}, Rgb(0.3f, 0.5f, 0.7f), false, "floating slab");
  auto scene = test::finish(std::move(raw), 0.4f);
  auto points = SurfacePoints::from_vertices(*scene);
  Light light = Light::point({1.f, 2.4f, 1.2f}, Rgb(4.f));
  // Stated sample counts: Embree 1024 gather rays per point; POV-Ray
  // radiosity count 800, error_bound 0.15, pretrace_end 0.005 (the defaults).
  auto embree_direct = test::make_renderer("embree", scene, {"bounces=0"})->illuminate(points, std::span<const Light>(&light, 1));
  auto embree = test::make_renderer("embree", scene, {"bounce_samples=1024"})->illuminate(points, std::span<const Light>(&light, 1));
  auto pov = test::make_renderer("povray", scene, {"error_bound=0.05", "radiosity_count=1600", "pretrace_end=0.002"})
                 ->illuminate(points, std::span<const Light>(&light, 1));
  std::vector<Rgb> embree_indirect(points.size()), pov_indirect(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    embree_indirect[i] = embree[i] - embree_direct[i];
    pov_indirect[i] = pov[i] - embree_direct[i];
  }
  double total = test::dbar(pov, embree), bounce_only = test::dbar(pov_indirect, embree_indirect);
  double sum_pov = 0, sum_embree = 0;
  for (size_t i = 0; i < points.size(); ++i) sum_pov += pov_indirect[i].r, sum_embree += embree_indirect[i].r;
  if (const char* dump = std::getenv("HILIGHT_DUMP_BOUNCE")) {
    std::ofstream out(dump);
    for (size_t i = 0; i < points.size(); ++i)
      out << points.positions[i].x << ' ' << points.positions[i].y << ' ' << points.positions[i].z << ' ' << points.normals[i].x << ' '
          << points.normals[i].y << ' ' << points.normals[i].z << ' ' << embree_indirect[i].r << ' ' << pov_indirect[i].r << '\n';
  }
  INFO("D-bar of the total " << total << ", of the bounce alone " << bounce_only << "; bounce POV-Ray/Embree " << sum_pov / sum_embree);
  CHECK(total < 0.05);
  CHECK(bounce_only < 0.15);
}

TEST_CASE("the same camera in Embree and POV-Ray gives matching images", "[povray][cross][image]") {
  if (test::skip_without_renderer("povray")) return;
  auto scene = shadow_scene();
  Lighting lights = {Light::point({0.5f, 3.f, 0.2f}, Rgb(4.f)), Light::spot({-1.5f, 2.5f, 1.5f}, {0.3f, -1.f, -0.2f}, 30.f, Rgb(6.f, 4.f, 2.f))};
  Camera cam = Camera::parse("4,3.5,5,0,0.3,0,45");
  const int w = 160, h = 120;
  Image a = test::make_renderer("embree", scene, {"bounces=0"})->render_image(cam, lights, w, h);
  Image b = test::make_renderer("povray", scene, {"bounces=0"})->render_image(cam, lights, w, h);
  double sum = 0, ref = 0;
  size_t coverage_mismatch = 0;
  Image diff(w, h);
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    coverage_mismatch += a.covered[i] != b.covered[i];
    Rgb d = glm::abs(a.pixels[i] - b.pixels[i]);
    diff.pixels[i] = d;
    diff.covered[i] = 1;
    sum += d.r + d.g + d.b;
    ref += a.pixels[i].r + a.pixels[i].g + a.pixels[i].b;
  }
  double mean_relative = sum / ref;
  INFO("mean relative difference " << mean_relative << ", pixels covered by one renderer only: " << coverage_mismatch);
  // Stated tolerance: 2% mean relative difference (edge pixels: one sample
  // each, at different sub-pixel positions), silhouettes within 2% of pixels.
  bool ok = mean_relative < 0.02 && coverage_mismatch < size_t(0.02 * w * h);
  if (!ok) {
    auto dir = test::output_dir("cross_povray_image");
    write_image(dir / "embree.png", a, 0.f);
    write_image(dir / "povray.png", b, 0.f);
    write_image(dir / "difference.png", diff, 0.f);
    WARN("images written to " << dir);
  }
  CHECK(mean_relative < 0.02);
  CHECK(coverage_mismatch < size_t(0.02 * w * h));
}

TEST_CASE("a POV-Ray target solved with Embree gives back the known lights", "[povray][cross][solve]") {
  if (test::skip_without_renderer("povray")) return;
  auto dir = test::output_dir("cross_povray_solve");
  Scene raw = builders::box_room({5.f, 3.f, 4.f}, Rgb(0.75f));
  builders::add_box(raw, {2.f, 0.9f, 1.5f}, {3.f, 1.f, 2.5f}, Rgb(0.4f, 0.5f, 0.6f), false, "floating slab");
  auto scene = test::finish(std::move(raw), 0.25f);
  Lighting truth = {Light::point({1.2f, 2.4f, 1.f}, Rgb(2.f, 1.8f, 1.5f)), Light::point({3.8f, 2.2f, 3.f}, Rgb(1.f, 1.5f, 2.f))};
  auto pov = test::make_renderer("povray", scene, {});
  write_illuminated_ply(dir / "target.ply", *scene, pov->illuminate(SurfacePoints::from_vertices(*scene), truth));
  // The same mesh for the solve: write it as OBJ with the builder's materials.
  std::ofstream obj(dir / "scene.obj");
  std::ofstream mtl(dir / "scene.mtl");
  obj << "mtllib scene.mtl\n";
  for (size_t k = 0; k < scene->materials.size(); ++k)
    mtl << "newmtl m" << k << "\nKd " << scene->materials[k].albedo.r << ' ' << scene->materials[k].albedo.g << ' ' << scene->materials[k].albedo.b << "\n";
  for (size_t v = 0; v < scene->positions.size(); ++v)
    obj << "v " << scene->positions[v].x << ' ' << scene->positions[v].y << ' ' << scene->positions[v].z << "\nvn " << scene->normals[v].x
        << ' ' << scene->normals[v].y << ' ' << scene->normals[v].z << "\n";
  for (size_t t = 0; t < scene->triangles.size(); ++t) {
    const auto& tri = scene->triangles[t];
    obj << "usemtl m" << scene->triangle_material[t] << "\nf " << tri[0] + 1 << "//" << tri[0] + 1 << ' ' << tri[1] + 1 << "//" << tri[1] + 1
        << ' ' << tri[2] + 1 << "//" << tri[2] + 1 << "\n";
  }
  obj.close();
  mtl.close();
  auto r = test::run_hilight({"solve", (dir / "scene.obj").string(), "--target", (dir / "target.ply").string(), "-o",
                              (dir / "found.json").string(), "--max-edge", "0.25", "--cache-dir", (dir / "cache").string(), "-q",
                              "--bounces", "1"});  // the target's bounce model (POV-Ray's first bounce)
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  Lighting found = read_lights_json(dir / "found.json");
  REQUIRE(found.size() == truth.size());
  const float diag = scene->diagonal();
  for (const auto& t : truth) {
    float best = 1e9f;
    for (const auto& f : found) best = std::min(best, glm::length(f.position - t.position));
    INFO("position error " << best / diag << " of the diagonal");
    CHECK(best <= 0.02f * diag);
  }
}

TEST_CASE("a soft-edged spotlight: Embree and POV-Ray agree within 1% across the edge", "[povray][cross][spot]") {
  if (test::skip_without_renderer("povray")) return;
  auto scene = test::finish(builders::plane(5.f, Rgb(0.8f)), 0.15f);
  auto points = SurfacePoints::from_vertices(*scene);
  Light spot = Light::spot({0.f, 2.f, 0.f}, {0.f, -1.f, 0.f}, 40.f, Rgb(2.f), 20.f);
  auto embree = test::make_renderer("embree", scene, {"bounces=0"})->illuminate(points, std::span<const Light>(&spot, 1));
  auto pov = test::make_renderer("povray", scene, {"bounces=0"})->illuminate(points, std::span<const Light>(&spot, 1));
  size_t n = 0, in_band = 0;
  double worst = worst_relative(pov, embree, &n);
  for (const auto& p : points.positions) {
    double angle = std::atan2(std::hypot(p.x, p.z), 2.0) * 180.0 / kPi;
    in_band += angle > 21 && angle < 39;
  }
  INFO("worst relative difference " << worst << " over " << n << " points, " << in_band << " in the soft edge");
  CHECK(in_band > 200);
  CHECK(worst < 0.01);
}

TEST_CASE("POV-Ray failures are reported, not hidden: time limit and POV-Ray's own error", "[povray][bad-input]") {
  if (test::skip_without_renderer("povray")) return;
  auto scene = test::finish(builders::furnished_room(), 0.3f);
  auto points = SurfacePoints::from_vertices(*scene);
  Light light = Light::point({3.f, 2.f, 2.f}, Rgb(1.f));
  auto slow = test::make_renderer("povray", scene, {"timeout=0.01"});
  CHECK_THROWS_WITH(slow->illuminate(points, std::span<const Light>(&light, 1)), Catch::Contains("time limit"));
  // Through the CLI: one line, exit code != 0, no output file.
  auto dir = test::output_dir("povray_failure");
  test::write_text(dir / "l.json", R"({"lights":[{"type":"point","position":[3,2,2],"intensity":[1,1,1]}]})");
  auto r = test::run_hilight({"render", std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj", "--lights", (dir / "l.json").string(),
                              "--renderer", "povray", "--set", "timeout=0.01", "-o", (dir / "out.ply").string()});
  CHECK(r.exit_code != 0);
  CHECK(test::line_count(r.err) == 1);
  CHECK_THAT(r.err, Catch::Contains("povray"));
  CHECK_FALSE(std::filesystem::exists(dir / "out.ply"));
}

TEST_CASE("hilight export writes a POV-Ray scene that POV-Ray renders like hilight", "[povray][cross][export]") {
  if (test::skip_without_renderer("povray")) return;
  auto dir = test::output_dir("povray_export");
  const std::string room = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
  const std::string lights = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room-lights.json";
  const std::string camera = "5.6,2.6,4.7,2,0.6,1.5,70";
  auto e = test::run_hilight({"export", room, "--lights", lights, "-o", (dir / "room.pov").string(), "--bounces", "0", "--camera",
                              camera, "--width", "120", "--height", "90"});
  REQUIRE(e.exit_code == 0);
  // Render the exported file with POV-Ray itself, as a user would.
  int rc = std::system(("cd '" + dir.string() + "' && povray -D -V -A +W120 +H90 +FE +Opov.exr room.pov >/dev/null 2>&1").c_str());
  REQUIRE(rc == 0);
  auto h = test::run_hilight({"render", room, "--lights", lights, "--bounces", "0", "--camera", camera, "--width", "120", "--height",
                              "90", "-o", (dir / "hilight.exr").string()});
  REQUIRE(h.exit_code == 0);
  Image a = read_exr(dir / "hilight.exr"), b = read_exr(dir / "pov.exr");
  REQUIRE(a.width == b.width);
  REQUIRE(a.height == b.height);
  double sum = 0, ref = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    if (!a.covered[i] || b.pixels[i].r < 0) continue;
    sum += std::abs(a.pixels[i].r - b.pixels[i].r);
    ref += a.pixels[i].r;
  }
  INFO("mean relative difference " << sum / ref);
  CHECK(sum / ref < 0.02);
}

TEST_CASE("the first bounce on real curved models: Embree and POV-Ray agree within a stated tolerance",
          "[povray][cross][bounce][real]") {
  if (test::skip_without_renderer("povray")) return;
  // The Wuson and the spider on a floor before a wall (Debian's
  // assimp-testmodels), one seeded random light; every 4th vertex, so that
  // POV-Ray's radiosity runs stay short.
  auto scene = std::make_shared<const Scene>(finish_scene(builders::curved_models_on_floor(), {}));
  RayScene rays(*scene);
  std::mt19937_64 rng(1102);
  const Lighting light = test::random_free_lights(rays, rng, 1, 0.05f);
  const SurfacePoints all = SurfacePoints::from_vertices(*scene);
  SurfacePoints points;
  for (size_t i = 0; i < all.size(); i += 4) {
    points.positions.push_back(all.positions[i]);
    points.normals.push_back(all.normals[i]);
    points.albedo.push_back(all.albedo[i]);
  }
  auto direct = test::make_renderer("embree", scene, {"bounces=0"})->illuminate(points, light);
  auto embree = test::make_renderer("embree", scene, {"bounce_samples=1024"})->illuminate(points, light);
  auto pov = test::make_renderer("povray", scene, {"error_bound=0.05", "radiosity_count=1600", "pretrace_end=0.002"})
                 ->illuminate(points, light);
  std::vector<Rgb> embree_indirect(points.size()), pov_indirect(points.size());
  double sum_pov = 0, sum_embree = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    embree_indirect[i] = embree[i] - direct[i];
    pov_indirect[i] = pov[i] - direct[i];
    sum_pov += pov_indirect[i].g, sum_embree += embree_indirect[i].g;
  }
  const double total = test::dbar(pov, embree), bounce_only = test::dbar(pov_indirect, embree_indirect);
  std::printf("first bounce on curved models (%zu points): D-bar of the total %.2f%%, of the bounce alone %.1f%%, "
              "bounce POV-Ray/Embree %.3f\n", points.size(), 100 * total, 100 * bounce_only, sum_pov / sum_embree);
  // Stated tolerance (measured: 9.5%, 38%, 0.999). The bounce's total agrees;
  // point by point it does not: on the wall within 6%, on the floor 23% and
  // on the models 41%, while Embree at 1024 rays is within 2% of 4096 and
  // POV-Ray barely moves with error_bound 0.01 or 0.5: POV-Ray's irradiance
  // cache interpolates across the models' small curved parts and their
  // contact shadows on the floor (docs/povray.md).
  CHECK(total < 0.12);
  CHECK(bounce_only < 0.45);
  CHECK(std::abs(sum_pov / sum_embree - 1) < 0.05);
}
