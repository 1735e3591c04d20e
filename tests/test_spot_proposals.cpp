// Spotlights without hints, piece by piece on the built stage: the
// refinement finds a spot from a start off along its valley (distance
// traded against cutoff), the screening finds one and two spots from nothing.
#include "hilight/fixtures/built_scenes.hpp"
#include "hilight/io/ply.hpp"
#include "hilight/solve/solve_renderers.hpp"
#include "hilight/solve/spot_proposals.hpp"
#include "hilight/solve/spot_refinement.hpp"
#include "hilight/solve/spot_screening.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdio>

using namespace hilight;

namespace {

struct Stage {
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const RayScene> rays;
  std::unique_ptr<Renderer> reference;
  std::unique_ptr<LightSpace> space;

  Stage() {
    builders::BuiltScene built = builders::stage();
    scene = std::make_shared<const Scene>(finish_scene(built.scene, {}));
    rays = std::make_shared<const RayScene>(*scene);
    reference = test::make_renderer("embree", scene, reference_renderer_settings({}, 1));
    space = std::make_unique<LightSpace>(*rays);
  }

  /// Samples of the target `truth` paints (bounce included), as a solve draws them.
  SampleSet samples_of(const Lighting& truth, const std::string& name) {
    const auto dir = test::output_dir(name);
    write_illuminated_ply(dir / "target.ply", *scene, reference->illuminate(SurfacePoints::from_vertices(*scene), truth));
    const Target target = read_target(dir / "target.ply", *scene, *rays);
    auto sampler = test::registry().create_sampler("importance", {});
    return sampler->draw(target, {4000, 0.05f, 1});
  }
};

float nearest(const Light& l, const Lighting& lights) {
  float best = 1e30f;
  for (const auto& o : lights) best = std::min(best, glm::length(o.position - l.position));
  return best;
}

} // namespace

TEST_CASE("spot refinement: a spot started 60 cm off along its axis, cutoff widened to match, comes back", "[spot-proposals]") {
  Stage stage;
  const Light truth = Light::spot(Vec3(1.9f, 4.4f, 3.4f), glm::normalize(Vec3(-0.23f, -0.76f, -0.61f)), 18.f, Rgb(70.f, 60.f, 65.f), 4.f);
  const SampleSet samples = stage.samples_of({truth}, "spot_refinement_valley");
  Light start = truth;
  start.position -= 0.6f * truth.direction;  // nearer the pool...
  start.cutoff_deg = 21.f;                    // ...with a cone that still covers it
  start.falloff_deg = 2.f;
  double dbar = 1.0;
  Lighting found = {start};
  for (int round = 0; round < 4; ++round) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<Rgb> bounce = stage.reference->unit_responses(samples.points, found, Transport::IndirectOnly);
    const auto t1 = std::chrono::steady_clock::now();
    const Fit refined = refine_spots(found, bounce, samples, *stage.space, *stage.reference, {}, 0);
    found = refined.lights, dbar = refined.dbar;
    const auto t2 = std::chrono::steady_clock::now();
    std::printf("round %d: bounce %.3f s, LM %.3f s, D̄ %.5f, off %.4f\n", round, std::chrono::duration<double>(t1 - t0).count(),
                std::chrono::duration<double>(t2 - t1).count(), dbar, glm::length(found[0].position - truth.position));
  }
  REQUIRE(found.size() == 1);
  INFO("found at " << found[0].position.x << ", " << found[0].position.y << ", " << found[0].position.z << ", cutoff "
                   << found[0].cutoff_deg << ", falloff " << found[0].falloff_deg << ", D̄ " << dbar);
  // The bounce is held at the start's: close, not exact.
  CHECK(glm::length(found[0].position - truth.position) < 0.05f);
  CHECK(std::abs(found[0].cutoff_deg - truth.cutoff_deg) < 0.5f);
  CHECK(dbar < 0.01);
}

TEST_CASE("spot screening: two overlapping pools get two cones near their lamps", "[spot-proposals]") {
  Stage stage;
  const Lighting truth = {
      Light::spot(Vec3(-0.3f, 4.7f, -0.3f), glm::normalize(Vec3(0.4f, -0.9f, -0.2f)), 24.f, Rgb(60.f), 4.f),
      Light::spot(Vec3(1.5f, 4.6f, -0.7f), glm::normalize(Vec3(-0.73f, -0.68f, 0.04f)), 20.f, Rgb(100.f, 90.f, 80.f), 4.f)};
  const SampleSet samples = stage.samples_of(truth, "spot_screening_overlap");
  const Fit proposed = propose_spots(samples, *stage.space, *stage.reference, *stage.reference, {});
  const Lighting& found = proposed.lights;
  const double dbar = proposed.dbar;
  REQUIRE(found.size() == 2);
  for (const auto& l : found) CHECK(nearest(l, truth) < 0.1f);
  CHECK(dbar < 0.01);
}

