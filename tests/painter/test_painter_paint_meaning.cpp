// What the brush's colour means (core/paint_meaning.hpp): by default the
// lamp's colour, the surface's own colour kept and its luminance the
// paint's, so white paint on the bundled room's warm table top asks for a
// white lamp; "reflected" (the paint is the reflected light) asks for a
// bluish one there.
#include "core/brush.hpp"
#include "core/solve_job.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/units.hpp"
#include "painter_fixtures.hpp"

#include <catch2/catch.hpp>
#include <random>

using namespace hilight;
using namespace hilight::painter;

namespace {

painter_test::World bundled_room() {
  painter_test::World w;
  w.scene = std::make_shared<const Scene>(load_scene(std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj", {0.2f}));
  w.rays = std::make_shared<const RayScene>(*w.scene);
  return w;
}

/// Blue over red of the one lamp the solve finds for white paint on the table top.
double lamp_blue_over_red(const painter_test::World& world, PaintMeaning meaning) {
  auto document = world.document();
  BrushSettings brush;
  brush.radius = 0.35f;
  brush.hardness = 1.f;
  brush.meaning = meaning;
  paint_stroke(*document, brush, BrushMode::Paint, std::vector<Vec3>{{1.7f, 0.78f, 1.9f}, {2.3f, 0.78f, 1.9f}});
  SolveJobOptions options = painter_test::quick_options();
  options.settings.fixed_count = 1;
  options.settings.placement.add("ceiling:0.2");
  SolveJob job(test::registry(), world.scene, world.rays, options);
  job.start_solve(document->target());
  std::optional<JobResult> result = job.wait();
  REQUIRE(result);
  INFO(result->error);
  REQUIRE(result->outcome == JobOutcome::Done);
  REQUIRE(result->lights.size() == 1);
  const Rgb I = result->lights[0].intensity;
  INFO("lamp " << I.r << " " << I.g << " " << I.b);
  REQUIRE(I.r > 0.f);
  return double(I.b) / double(I.r);
}

} // namespace

TEST_CASE("painter: lamp-colour paint keeps the surface's chroma at the paint's luminance", "[painter][paint-meaning]") {
  const painter_test::World world = bundled_room();
  const std::vector<Rgb>& albedo = world.document()->albedo();
  std::mt19937 random(36);
  std::uniform_real_distribution<float> unit(0.f, 1.f);
  for (int i = 0; i < 50; ++i) {
    const Rgb rho = albedo[std::uniform_int_distribution<size_t>(0, albedo.size() - 1)(random)];
    const Rgb paint(unit(random), unit(random), unit(random));
    const Rgb psi = painted_radiance(paint * 3.f, rho, PaintMeaning::LampColour);
    CHECK(luminance(psi) == Approx(luminance(paint * 3.f)).epsilon(1e-5));
    // The chroma of a lamp of that colour on that surface: Ψ ∝ paint ⊙ ρ.
    const Rgb reflected = paint * rho;
    CHECK(psi.r * reflected.g == Approx(psi.g * reflected.r).epsilon(1e-4));
    CHECK(psi.b * reflected.g == Approx(psi.g * reflected.b).epsilon(1e-4));
    CHECK(painted_radiance(paint, rho, PaintMeaning::Reflected) == paint);
  }
  // A grey surface shows the paint itself, as in either meaning.
  const Rgb grey = painted_radiance(Rgb(0.9f, 0.5f, 0.2f), Rgb(0.5f), PaintMeaning::LampColour);
  CHECK(grey.r == Approx(0.9f));
  CHECK(grey.g == Approx(0.5f));
  CHECK(grey.b == Approx(0.2f));
  // A surface that reflects none of the lamp's colour takes the paint as it is.
  CHECK(painted_radiance(Rgb(0.f, 0.f, 1.f), Rgb(0.8f, 0.f, 0.f), PaintMeaning::LampColour) == Rgb(0.f, 0.f, 1.f));
}

TEST_CASE("painter: white paint on the warm table top asks for a white lamp, or a bluish one as reflected light", "[painter][paint-meaning]") {
  const painter_test::World world = bundled_room();
  // The table top's albedo is (0.55, 0.35, 0.2): reflected white asks for
  // about 0.55/0.2 more blue than red; lamp colour for as much of each
  // (the warm walls' bounce aside).
  const double lamp = lamp_blue_over_red(world, PaintMeaning::LampColour);
  const double reflected = lamp_blue_over_red(world, PaintMeaning::Reflected);
  CHECK(lamp == Approx(1.0).margin(0.08));
  CHECK(reflected > 2.0);
}
