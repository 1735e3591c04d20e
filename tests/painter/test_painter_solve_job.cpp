// The painter's background solve: the shared Solver in a worker thread.
// Fine-tune keeps the count, add keeps the old lights exactly, the count
// control moves along the hierarchy without a solve, and cancel stops promptly.
#include "core/solve_job.hpp"
#include "hilight/surface_points.hpp"
#include "painter_fixtures.hpp"

#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <thread>

using namespace hilight;
using namespace hilight::painter;

namespace {

/// A 4 x 3 x 4 room lit by `truth`, as a target over every vertex.
struct RoomCase {
  painter_test::World world;
  Target target;
};

RoomCase room_case(const Lighting& truth) {
  RoomCase c{painter_test::make_world(builders::box_room({4.f, 3.f, 4.f}), 0.5f), {}};
  auto renderer = test::make_renderer("embree", c.world.scene, {"bounce_samples=16"});
  std::vector<Rgb> values = renderer->illuminate(SurfacePoints::from_vertices(*c.world.scene), truth);
  std::vector<float> weights(values.size(), 1.f);
  c.target = bind_target("room", c.world.scene->positions, values, weights, *c.world.scene, *c.world.rays,
                         c.world.scene->normals);
  return c;
}

JobResult finished(SolveJob& job) {
  std::optional<JobResult> result = job.wait();
  REQUIRE(result);
  INFO(result->error);
  REQUIRE(result->outcome == JobOutcome::Done);
  return *result;
}

} // namespace

TEST_CASE("painter: background solve, fine-tune, add lights and the count control", "[painter]") {
  const Lighting truth = {Light::point({1.f, 2.5f, 1.f}, Rgb(4.f)), Light::point({3.f, 2.5f, 3.f}, Rgb(3.f, 2.5f, 2.f))};
  RoomCase c = room_case(truth);
  SolveJob job(test::registry(), c.world.scene, c.world.rays, painter_test::quick_options());
  CHECK_FALSE(job.busy());
  CHECK(job.cut_count() == 0);
  CHECK_THROWS_AS(job.cut_lights(1), std::logic_error);
  // The window wakes its event loop from this callback (no polling thread).
  std::atomic<int> finished_calls{0};
  job.set_on_finished([&] { ++finished_calls; });

  job.start_solve(c.target);
  // The window evaluates with its own renderer while the job runs.
  auto display = job.make_renderer();
  CHECK(display->illuminate(SurfacePoints::from_vertices(*c.world.scene), truth).size() == c.world.scene->positions.size());
  JobResult solved = finished(job);
  CHECK(solved.kind == JobKind::Solve);
  REQUIRE(solved.lights.size() == 2);
  CHECK(solved.report.dbar < 0.05);
  CHECK_FALSE(job.take_result());  // taken once
  CHECK(finished_calls == 1);

  // Count control: cuts without a new solve.
  REQUIRE(job.cut_count() >= 2);
  CHECK(job.cut_lights(1).size() == 1);
  CHECK(job.cut_lights(2).size() == 2);
  CHECK(job.cut_base_count() == 0);

  // Fine-tune from moved lights: same count, back near the truth.
  Lighting moved = solved.lights;
  moved[0].position += Vec3(0.2f, -0.2f, 0.1f);
  job.start_fine_tune(c.target, moved);
  JobResult tuned = finished(job);
  CHECK(tuned.lights.size() == moved.size());
  CHECK(tuned.report.dbar < 0.05);
  CHECK(job.cut_count() >= 2);  // fine-tune leaves the last solve's cuts

  // Add lights from one of the two: the given light comes back unchanged.
  const Lighting one = {solved.lights[0]};
  job.start_add_lights(c.target, one);
  JobResult added = finished(job);
  REQUIRE(added.lights.size() >= 2);
  CHECK(added.lights[0].position == one[0].position);
  CHECK(added.lights[0].intensity == one[0].intensity);
  CHECK(added.lights[0].type == one[0].type);
  // After an add, a cut keeps the old lights first.
  REQUIRE(job.cut_count() >= 1);
  Lighting cut = job.cut_lights(1);
  REQUIRE(cut.size() == 2);
  CHECK(cut[0].position == one[0].position);
  // The light-count slider shows totals base + k: each total is what the cut gives.
  CHECK(job.cut_base_count() == 1);
  for (size_t total = job.cut_base_count() + 1; total <= job.cut_base_count() + job.cut_count(); ++total)
    CHECK(job.cut_lights(total - job.cut_base_count()).size() == total);
  CHECK(finished_calls == 3);
}

TEST_CASE("painter: cancel stops a running solve promptly", "[painter]") {
  RoomCase c = room_case({Light::point({2.f, 2.5f, 2.f}, Rgb(4.f))});
  SolveJob job(test::registry(), c.world.scene, c.world.rays, painter_test::quick_options());
  job.start_solve(c.target);
  job.cancel();
  const auto t0 = std::chrono::steady_clock::now();
  std::optional<JobResult> result = job.wait();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  REQUIRE(result);
  CHECK(result->outcome == JobOutcome::Cancelled);
  CHECK(seconds < 2.0);
  CHECK_FALSE(job.busy());
  CHECK(job.cut_count() == 0);

  // Cancelled in the middle: wait for a later stage, then cancel; the job
  // ends (cancelled, or done if it won the race) and the next solve works.
  job.start_solve(c.target);
  for (int i = 0; i < 2000 && job.busy() && job.progress().find("seeding") == std::string::npos; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  const auto t1 = std::chrono::steady_clock::now();
  job.cancel();
  result = job.wait();
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count() < 1.0);
  REQUIRE(result);
  CHECK(result->outcome != JobOutcome::Failed);
  job.start_solve(c.target);
  CHECK(finished(job).lights.size() == 1);

  // Destroying a job while it runs cancels and joins it.
  {
    SolveJob doomed(test::registry(), c.world.scene, c.world.rays, painter_test::quick_options());
    doomed.start_solve(c.target);
  }
}
