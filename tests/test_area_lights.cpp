// Area and line sources (docs/rendering-model.md "Area and line sources"):
// the lights file, and Embree's direct light against closed-form
// configuration factors derived here (CIE 171 case 5.3 style), from 0.1× to
// 10× the source's size away, shadows, and the far-field limit.
#include "cie171_cases.hpp"
#include "hilight/error.hpp"
#include "hilight/io/gltf.hpp"
#include "hilight/io/lights_json.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "hilight/scene_origin.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

using namespace hilight;

namespace {

using cie171::rectangle_irradiance;  // CIE 171 case 5.3's closed form (tests/cie171_cases.hpp)

/// Irradiance from a Lambertian disk of radius R facing down at height h, on
/// a floor point a off its axis: the factor to a parallel disk,
/// F = ½ (1 − (Z − 2R²)/√(Z² − 4a²R²)), Z = h² + a² + R² (R²/(h² + R²) on the axis).
double disk_irradiance(double a, double R, double h, double i0) {
  const double Z = h * h + a * a + R * R;
  const double F = 0.5 * (1 - (Z - 2 * R * R) / std::sqrt(Z * Z - 4 * a * a * R * R));
  return kPi * i0 / (kPi * R * R) * F;
}

/// A Lambertian strip along x from −l to l at height h facing down, per unit
/// length I0/2l, at a floor point (px, pz): both cosines are h/r, so
/// E = I0/2l · h² ∫ dx / ((x − px)² + ρ²)², ρ² = h² + pz², in closed form.
double line_irradiance(double px, double pz, double l, double h, double i0) {
  const double r2 = h * h + pz * pz, r = std::sqrt(r2);
  auto F = [&](double s) { return s / (2 * r2 * (s * s + r2)) + std::atan(s / r) / (2 * r2 * r); };
  return i0 / (2 * l) * h * h * (F(l - px) - F(-l - px));
}

/// Unit irradiance (E for I0 = 1) at floor points from one light, through
/// Embree's direct light: L = ρ/π E with ρ = 1.
std::vector<double> embree_irradiance(std::shared_ptr<const Scene> scene, const Light& light,
                                      const std::vector<std::pair<float, float>>& at) {
  auto renderer = test::make_renderer("embree", scene, {"bounces=0"});
  SurfacePoints points;
  for (auto [x, z] : at) {
    points.positions.push_back({x, 0.f, z});
    points.normals.push_back({0.f, 1.f, 0.f});
    points.albedo.push_back(Rgb(1.f));
  }
  const auto r = renderer->unit_responses(points, std::span<const Light>(&light, 1), Transport::All);
  std::vector<double> out;
  for (const Rgb& v : r) out.push_back(double(v.r) * kPi);
  return out;
}

/// Floor points under, at the edge of and beside a source of size s.
std::vector<std::pair<float, float>> probe_points(float s) {
  return {{0.f, 0.f}, {0.25f * s, 0.1f * s}, {0.5f * s, 0.f}, {0.5f * s, 0.5f * s}, {1.2f * s, -0.3f * s}, {3.f * s, 2.f * s}};
}

const std::vector<float> kHeights = {0.1f, 0.2f, 0.5f, 1.f, 2.f, 5.f, 10.f};  // × the size

} // namespace

TEST_CASE("area and line sources survive a lights-file round trip", "[lights][area]") {
  Lighting lights = {Light::area(LightType::Rectangle, {1.f, 2.f, 3.f}, {0.f, -1.f, 0.f}, {1.f, 0.f, 0.f}, {0.6f, 0.3f}, Rgb(2.f)),
                     Light::area(LightType::Disk, {0.f, 2.5f, 0.f}, {0.f, 0.f, 1.f}, {0.f, 1.f, 0.f}, {0.4f, 0.f}, Rgb(1.f, 2.f, 3.f)),
                     Light::area(LightType::Line, {0.f, 2.f, 1.f}, {0.f, -1.f, 0.f}, {0.f, 0.f, 1.f}, {1.5f, 0.f}, Rgb(0.5f))};
  auto dir = test::output_dir("area_lights_roundtrip");
  write_lights_json(dir / "l.json", lights);
  const Lighting back = read_lights_json(dir / "l.json");
  REQUIRE(back.size() == 3);
  for (size_t i = 0; i < 3; ++i) {
    CAPTURE(i);
    CHECK(back[i].type == lights[i].type);
    CHECK(back[i].position == lights[i].position);
    CHECK(back[i].direction == lights[i].direction);
    CHECK(back[i].up == lights[i].up);
    CHECK(back[i].size == lights[i].size);
    CHECK(back[i].intensity == lights[i].intensity);
  }
  CHECK(test::read_file(dir / "l.json").find("\"size\": [\n        1.5\n      ]") != std::string::npos);  // a line has [length]
}

TEST_CASE("malformed area and line sources are refused naming the file and the light", "[lights][area][bad-input]") {
  auto bad = [](const std::string& light) { return parse_lights_json(R"({"lights":[{"type":"point","position":[0,0,0],"intensity":[1,1,1]},)" + light + "]}", "L.json"); };
  const std::string head = R"({"type":"rectangle","position":[0,2,0],"intensity":[1,1,1],)";
  CHECK_NOTHROW(bad(head + R"("direction":[0,-1,0],"up":[1,0,0],"size":[0.6,0.6]})"));
  CHECK_THROWS_WITH(bad(head + R"("direction":[0,-1,0],"up":[1,0,0],"size":[0,0.6]})"), Catch::Contains("L.json: light 1: \"size\" must be positive"));
  CHECK_THROWS_WITH(bad(head + R"("direction":[0,-1,0],"up":[1,0,0],"size":[0.6,-1]})"), Catch::Contains("light 1: \"size\" must be positive"));
  CHECK_THROWS_WITH(bad(head + R"("direction":[0,-2,0],"up":[1,0,0],"size":[0.6,0.6]})"), Catch::Contains("light 1: \"direction\" must be a unit vector"));
  CHECK_THROWS_WITH(bad(head + R"("direction":[0,0,0],"up":[1,0,0],"size":[0.6,0.6]})"), Catch::Contains("light 1: \"direction\" must be a unit vector"));
  CHECK_THROWS_WITH(bad(head + R"("direction":[0,-1,0],"up":[0,3,0],"size":[0.6,0.6]})"), Catch::Contains("light 1: \"up\" must not be parallel"));
  CHECK_THROWS_WITH(bad(head + R"("direction":[0,-1,0],"up":[1,0,0],"size":[0.6]})"), Catch::Contains("light 1: \"size\" must be [width, height]"));
  CHECK_THROWS_WITH(bad(R"({"type":"disk","position":[0,2,0],"intensity":[1,1,1],"direction":[0,-1,0],"size":[0.3,0.3]})"), Catch::Contains("[diameter]"));
  CHECK_THROWS_WITH(bad(R"({"type":"line","position":[0,2,0],"intensity":[1,1,1],"direction":[0,-1,0],"size":[1]})"), Catch::Contains("light 1: missing \"up\""));
  CHECK_THROWS_WITH(bad(R"({"type":"panel","position":[0,2,0],"intensity":[1,1,1]})"), Catch::Contains("light 1: unknown light type \"panel\""));
  CHECK_THROWS_WITH(bad(R"({"type":"point","position":[0,2,0],"intensity":[1,1,1],"size":[1]})"), Catch::Contains("light 1: up and size belong"));
  // NaN cannot be written in JSON; a number beyond a float is refused as not finite.
  CHECK_THROWS_WITH(bad(head + R"("direction":[0,-1,0],"up":[1,0,0],"size":[1e39,0.6]})"), Catch::Contains("light 1"));
}

/// Embree's irradiance from a downward source of `type` and `extent`, centred
/// height × `size` above a plane for each of kHeights, against
/// `closed_form(x, z, height above the plane)` at the probe points: each within
/// 1%; returns the worst relative error.
template <class ClosedForm>
double check_against_closed_form(LightType type, glm::vec2 extent, float size, ClosedForm&& closed_form) {
  auto scene = test::finish(builders::plane(80.f, Rgb(1.f)), 20.f);
  double worst = 0;
  for (float height : kHeights) {
    const float c = height * size;
    const Light light = Light::area(type, {0.f, c, 0.f}, {0.f, -1.f, 0.f}, {1.f, 0.f, 0.f}, extent, Rgb(1.f));
    const auto at = probe_points(size);
    const auto e = embree_irradiance(scene, light, at);
    for (size_t k = 0; k < at.size(); ++k) {
      const double want = closed_form(at[k].first, at[k].second, c);
      CAPTURE(height, k, e[k], want);
      CHECK(std::abs(e[k] - want) <= 0.01 * want);
      worst = std::max(worst, std::abs(e[k] - want) / want);
    }
  }
  return worst;
}

TEST_CASE("Embree: a Lambertian rectangle matches its closed-form configuration factor from 0.1x to 10x its size", "[renderer][area][analytic]") {
  const float w = 0.6f, h = 0.4f;
  WARN("rectangle: worst relative error " << check_against_closed_form(LightType::Rectangle, {w, h}, 0.6f, [&](double x, double z, double c) {
         return rectangle_irradiance(x, z, -w / 2, w / 2, -h / 2, h / 2, c, 1.0);
       }));
}

TEST_CASE("Embree: a Lambertian disk matches its closed-form configuration factor from 0.1x to 10x its size", "[renderer][area][analytic]") {
  const float d = 0.5f;
  WARN("disk: worst relative error " << check_against_closed_form(LightType::Disk, {d, 0.f}, d, [&](double x, double z, double c) {
         return disk_irradiance(std::hypot(x, z), d / 2, c, 1.0);
       }));
}

TEST_CASE("Embree: a Lambertian line source matches its closed form from 0.1x to 10x its length", "[renderer][area][analytic]") {
  const float len = 1.2f;
  WARN("line: worst relative error " << check_against_closed_form(LightType::Line, {len, 0.f}, len, [&](double x, double z, double c) {
         return line_irradiance(x, z, len / 2, c, 1.0);
       }));
}

TEST_CASE("Embree: far away an area or line source is a point light of intensity I0 cos", "[renderer][area][analytic]") {
  auto scene = test::finish(builders::plane(200.f, Rgb(1.f)), 50.f);
  // Tilted 30° about z, so the emission angle differs from the receiver's.
  const Vec3 normal = glm::normalize(Vec3(std::sin(0.5236f), -std::cos(0.5236f), 0.f));
  const Vec3 centre(0.f, 30.f, 0.f);
  for (LightType type : {LightType::Rectangle, LightType::Disk, LightType::Line}) {
    const Light light = Light::area(type, centre, normal, {0.f, 0.f, 1.f}, {0.5f, 0.3f}, Rgb(2.f));
    const std::vector<std::pair<float, float>> at = {{0.f, 0.f}, {10.f, 5.f}, {25.f, -10.f}};
    const auto e = embree_irradiance(scene, light, at);
    for (size_t k = 0; k < at.size(); ++k) {
      const Vec3 p(at[k].first, 0.f, at[k].second), d = centre - p;
      const double dist = glm::length(d), cos_r = d.y / dist, cos_e = glm::dot(normal, -d) / dist;
      const double want = cos_e * cos_r / (dist * dist);  // per unit I0
      CAPTURE(to_string(type), k, e[k], want);
      CHECK(std::abs(e[k] - want) <= 0.002 * want);
    }
  }
}

TEST_CASE("Embree: an area source lights only its front side, and a blocker over half of it halves the light", "[renderer][area]") {
  // A thin slab just under the panel covers its x < 0 half as the point below its centre sees it.
  Scene raw = builders::plane(20.f, Rgb(1.f));
  builders::add_box(raw, {-3.f, 1.90f, -3.f}, {0.f, 1.91f, 3.f}, Rgb(0.f), false, "blocker");
  auto scene = test::finish(std::move(raw), 0.5f);
  Light down = Light::area(LightType::Rectangle, {0.f, 2.f, 0.f}, {0.f, -1.f, 0.f}, {1.f, 0.f, 0.f}, {0.6f, 0.6f}, Rgb(1.f));
  Light up = down;
  up.direction = {0.f, 1.f, 0.f};
  const std::vector<std::pair<float, float>> at = {{0.f, 0.f}};
  const double half = embree_irradiance(scene, down, at)[0];
  const double full = rectangle_irradiance(0, 0, -0.3, 0.3, -0.3, 0.3, 2.0, 1.0);
  CHECK(half == Approx(0.5 * full).epsilon(0.005));
  CHECK(embree_irradiance(scene, up, at)[0] == 0.0);
}

TEST_CASE("Embree: area sources add up like any light (render = sum of I_j phi_j)", "[renderer][area][linearity]") {
  auto scene = test::finish(builders::box_room({4.f, 3.f, 5.f}, Rgb(0.6f)), 0.5f);
  auto renderer = test::make_renderer("embree", scene, {"bounces=1", "bounce_samples=64"});
  const Lighting lights = {Light::area(LightType::Rectangle, {2.f, 2.9f, 2.5f}, {0.f, -1.f, 0.f}, {1.f, 0.f, 0.f}, {0.6f, 0.6f}, Rgb(3.f, 2.f, 1.f)),
                           Light::area(LightType::Line, {1.f, 2.5f, 1.f}, {0.f, 0.f, 1.f}, {1.f, 0.f, 0.f}, {1.5f, 0.f}, Rgb(1.f)),
                           Light::area(LightType::Disk, {3.f, 1.f, 4.f}, {0.f, 1.f, 0.f}, {1.f, 0.f, 0.f}, {0.4f, 0.f}, Rgb(2.f))};
  const auto points = SurfacePoints::from_vertices(*scene);
  const auto all = renderer->illuminate(points, lights);
  const auto phi = renderer->unit_responses(points, lights, Transport::All);
  double lit = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    Rgb sum(0.f);
    for (size_t j = 0; j < lights.size(); ++j) sum += lights[j].intensity * phi[j * points.size() + i];
    REQUIRE(all[i].r == Approx(sum.r).epsilon(1e-4).margin(1e-7));
    REQUIRE(all[i].b == Approx(sum.b).epsilon(1e-4).margin(1e-7));
    lit += all[i].r;
  }
  CHECK(lit > 0);
}

TEST_CASE("glTF: an area or line source goes out as a hemisphere spot with its shape in extras, and comes back", "[area][gltf]") {
  const Lighting lights = {Light::area(LightType::Rectangle, {1.f, 2.f, 3.f}, glm::normalize(Vec3(0.3f, -1.f, 0.f)), {0.f, 0.f, 1.f}, {0.6f, 0.3f}, Rgb(2.f, 1.f, 0.5f)),
                           Light::area(LightType::Disk, {0.f, 2.5f, 0.f}, {0.f, -1.f, 0.f}, {1.f, 0.f, 0.f}, {0.4f, 0.f}, Rgb(1.f)),
                           Light::area(LightType::Line, {0.f, 2.f, 1.f}, {0.f, 0.f, 1.f}, {1.f, 0.f, 0.f}, {1.5f, 0.f}, Rgb(0.5f))};
  auto dir = test::output_dir("area_lights_gltf");
  write_gltf(dir / "l.gltf", GltfExport{nullptr, lights});
  // What Blender's importer reads: a spot of the source's peak candela, a 90° cone.
  const auto doc = nlohmann::json::parse(test::read_file(dir / "l.gltf"));
  const auto& first = doc["extensions"]["KHR_lights_punctual"]["lights"][0];
  CHECK(first["type"] == "spot");
  CHECK(first["spot"]["outerConeAngle"].get<double>() == Approx(kPi / 2));
  CHECK(first["intensity"].get<double>() == Approx(2.0 * kCandelaPerWattPerSr));
  CHECK(first["extras"]["hilight"]["type"] == "rectangle");
  const Lighting back = read_gltf_lights(dir / "l.gltf");
  REQUIRE(back.size() == 3);
  for (size_t i = 0; i < 3; ++i) {
    CAPTURE(i);
    CHECK(back[i].type == lights[i].type);
    CHECK(glm::length(back[i].position - lights[i].position) < 1e-5f);
    CHECK(glm::length(back[i].direction - lights[i].direction) < 1e-5f);
    CHECK(glm::length(back[i].up - lights[i].up) < 1e-5f);
    CHECK(back[i].size == lights[i].size);
    CHECK(glm::length(back[i].intensity - lights[i].intensity) < 1e-5f);
  }
}

TEST_CASE("an area source's size is a length in the scene's unit, like its position", "[area][units]") {
  SceneFrame mm;
  mm.scale = 0.001;
  mm.unit = "mm";
  const Lighting in = {Light::area(LightType::Rectangle, {1000.f, 2500.f, 0.f}, {0.f, -1.f, 0.f}, {1.f, 0.f, 0.f}, {600.f, 300.f}, Rgb(1.f))};
  const Lighting local = parse_lights_json(lights_to_json(in, "mm"), "mm.json", &mm);
  CHECK(local[0].size[0] == Approx(0.6f));
  CHECK(local[0].size[1] == Approx(0.3f));
  CHECK(local[0].position.y == Approx(2.5f));
  const Lighting back = parse_lights_json(lights_to_json(local, "mm", &mm), "back.json");
  CHECK(back[0].size[0] == Approx(600.f));
  CHECK(back[0].position.y == Approx(2500.f));
}

TEST_CASE("hilight render refuses a malformed area source in one line, exit 2, and writes nothing", "[area][bad-input][cli]") {
  const auto dir = test::output_dir("area_lights_bad_cli");
  const std::string scene = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"("size":[0.6,0.6],"direction":[0,-1,0],"up":[0,1,0])", "\"up\" must not be parallel"},
      {R"("size":[-0.6,0.6],"direction":[0,-1,0],"up":[1,0,0])", "\"size\" must be positive"},
      {R"("size":[0.6,0.6],"direction":[0,-0.5,0],"up":[1,0,0])", "\"direction\" must be a unit vector"}};
  for (const auto& [fields, mention] : cases) {
    test::write_text(dir / "bad.json", R"({"lights":[{"type":"point","position":[1,2,1],"intensity":[1,1,1]},{"type":"rectangle","position":[3,2.5,2],"intensity":[1,1,1],)" + fields + "}]}");
    const auto r = test::run_hilight({"render", scene, "--lights", (dir / "bad.json").string(), "-o", (dir / "out.ply").string()});
    CAPTURE(r.err);
    CHECK(r.exit_code == 2);
    CHECK(test::line_count(r.err) == 1);
    CHECK(r.err.find((dir / "bad.json").string() + ": light 1: " + mention) != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir / "out.ply"));
  }
}
