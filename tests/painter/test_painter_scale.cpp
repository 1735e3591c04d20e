// The painter at any scale (issue 19): the same floor and box in metres,
// scaled by 1000 and by 1/1000, driven by the same session scaled (world
// points × k). The default brush, strokes, the shadow tool's estimate and a
// spotlight for a region come out the same: the same vertices painted with
// the same weights, lights at the same places scaled. Every length the
// painter's core uses is a share of the scene's size (the camera, markers
// and brush limits too: docs/painter.md).
#include "core/session.hpp"
#include "core/session_player.hpp"
#include "painter_fixtures.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

using namespace hilight;
using namespace hilight::painter;

namespace {

struct Outcome {
  float diagonal = 0.f, brush_radius = 0.f;
  std::vector<float> weight;
  Light shadow_light, spot;
};

nlohmann::json scaled(const std::vector<std::array<double, 3>>& points, double k) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : points) out.push_back({p[0] * k, p[1] * k, p[2] * k});
  return out;
}

Outcome play_at_scale(double k) {
  Scene raw = builders::plane(5.f, Rgb(0.7f));
  builders::add_box(raw, {-0.5f, 0.f, -0.5f}, {0.5f, 1.f, 0.5f}, Rgb(0.6f), false, "box");
  for (auto& p : raw.positions) p = Vec3(DVec3(p) * k);
  const auto world = painter_test::make_world(std::move(raw), float(0.4 * k));
  auto doc = world.document();
  SolveJob job(test::registry(), world.scene, world.rays, painter_test::quick_options());
  SessionPlayer player(*doc, job, {}, {});
  Outcome out;
  out.diagonal = world.scene->diagonal();
  out.brush_radius = player.brush().radius;
  // A stroke with the default brush over the floor in front of the box.
  player.apply({"stroke", {{"world", scaled({{1.5, 0, 1.5}, {2.0, 0, 1.8}, {2.5, 0, 2.2}}, k)}}}, 0);
  out.weight = doc->state().weight;
  // A shadow stroked behind the box: a light estimated on the other side.
  player.apply({"shadow", {{"pairs", {{{"occluder", scaled({{0.5, 0.5, 0.0}}, k)[0]},
                                        {"world", scaled({{-1.0, 0, 0}, {-1.4, 0, 0.2}, {-1.2, 0, -0.2}, {-0.8, 0, 0.1}}, k)}}}}}},
               1);
  REQUIRE(doc->state().lights.size() == 1);
  out.shadow_light = doc->state().lights[0];
  player.apply({"spot_region", {{"world", scaled({{2.0, 0, 2.0}, {2.5, 0, 2.4}}, k)},
                                {"eye", scaled({{2.0, 2.5, 0.0}}, k)[0]},
                                {"direction", {0.1, -1.0, 0.8}}}},
               2);
  REQUIRE(doc->state().lights.size() == 2);
  out.spot = doc->state().lights[1];
  return out;
}

} // namespace

TEST_CASE("painter: the same session on the scene scaled by 1000 and by 1/1000 paints and places the same, scaled",
          "[painter][invariance][scale]") {
  const Outcome home = play_at_scale(1.0);
  REQUIRE(std::count_if(home.weight.begin(), home.weight.end(), [](float w) { return w > 0.f; }) > 0);
  for (double k : {1000.0, 0.001}) {
    INFO("k " << k);
    const Outcome o = play_at_scale(k);
    CHECK(o.diagonal == Approx(home.diagonal * k).epsilon(1e-6));
    CHECK(o.brush_radius == Approx(home.brush_radius * k).epsilon(1e-6));
    REQUIRE(o.weight.size() == home.weight.size());  // the same tessellation
    size_t differing = 0;
    for (size_t v = 0; v < o.weight.size(); ++v) differing += std::abs(o.weight[v] - home.weight[v]) > 1e-4f;
    CHECK(differing == 0);
    const double tolerance = 1e-5 * home.diagonal;
    CHECK(glm::length(DVec3(o.shadow_light.position) / k - DVec3(home.shadow_light.position)) <= tolerance);
    CHECK(o.shadow_light.intensity.g / (k * k) == Approx(home.shadow_light.intensity.g).epsilon(1e-4));
    CHECK(glm::length(DVec3(o.spot.position) / k - DVec3(home.spot.position)) <= tolerance);
    CHECK(o.spot.cutoff_deg == Approx(home.spot.cutoff_deg).epsilon(1e-4));
  }
}
