// Inverse lighting end to end through the real launcher: render known lights
// to a target, `hilight solve` it, and check that the lights come back — how
// many, of which type, where (paper's Table 1 criterion: mean position error
// ≤ 1.87% of the scene diagonal) and how well they reproduce the target (D̄).
// Also: robustness (noise, a physically infeasible target), the fixed light
// count, fine-tune and add modes, determinism, and refused / accepted targets.
//
// Scenes (b) and (c) are written as OBJ+MTL from code; every solve shares one
// light-cache folder (never wiped here), so a scene's cache is built once.
#include "hilight/io/lights_json.hpp"
#include "hilight/io/ply_reader.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/lighting.hpp"
#include "hilight/surface_points.hpp"
#include "support.hpp"

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using hilight::Light;
using hilight::Lighting;
using hilight::LightType;
using hilight::Rgb;
using hilight::Vec3;
using Catch::Matchers::Contains;

const std::string kRoom = HILIGHT_SOURCE_DIR "/scenes/room.obj";
const std::string kRoom4Lights = HILIGHT_SOURCE_DIR "/scenes/room-4lights.json";

/// Paper's Table 1 criterion for a recovered light position.
constexpr double kPositionTolerance = 0.0187;

// ---------------------------------------------------------------------------
// Scenes from code: axis-aligned rectangles, each with the normal it must have.

struct Rect {
  Vec3 lo, hi;  ///< bounds; degenerate along exactly one axis
  Vec3 normal;  ///< the wanted face normal (winding follows it)
  std::string material;
};

struct SceneDesc {
  std::vector<Rect> rects;
  std::map<std::string, Rgb> materials;
  std::vector<std::pair<Vec3, Vec3>> objects;  ///< boxes standing on the floor (footprints)

  void rect(const Rect& r) { rects.push_back(r); }
  /// A box as 6 quads; outward normals for objects, inward for a room.
  void box(const Vec3& lo, const Vec3& hi, const std::string& material, bool inward) {
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) {
        Vec3 a = lo, b = hi, n(0.f);
        a[axis] = b[axis] = side ? hi[axis] : lo[axis];
        n[axis] = (side ? 1.f : -1.f) * (inward ? -1.f : 1.f);
        rects.push_back({a, b, n, material});
      }
    if (!inward) objects.emplace_back(lo, hi);
  }

  /// Writes DIR/STEM.obj and DIR/STEM.mtl; returns the OBJ's path.
  fs::path write(const fs::path& dir, const std::string& stem) const {
    std::ostringstream obj, mtl;
    obj << std::setprecision(9) << "mtllib " << stem << ".mtl\n";
    for (const auto& [name, kd] : materials) mtl << "newmtl " << name << "\nKd " << kd.r << " " << kd.g << " " << kd.b << "\n\n";
    int next = 1;
    for (size_t i = 0; i < rects.size(); ++i) {
      const Rect& r = rects[i];
      int flat = r.lo.x == r.hi.x ? 0 : r.lo.y == r.hi.y ? 1 : 2;
      int u = (flat + 1) % 3, v = (flat + 2) % 3;
      std::array<Vec3, 4> c;
      for (int k = 0; k < 4; ++k) {
        c[k] = r.lo;
        if (k == 1 || k == 2) c[k][u] = r.hi[u];
        if (k == 2 || k == 3) c[k][v] = r.hi[v];
      }
      if (glm::dot(glm::cross(c[1] - c[0], c[2] - c[0]), r.normal) < 0.f) std::swap(c[1], c[3]);
      obj << "o rect" << i << "\nusemtl " << r.material << "\n";
      for (const auto& p : c) obj << "v " << p.x << " " << p.y << " " << p.z << "\n";
      obj << "f " << next << " " << next + 1 << " " << next + 2 << " " << next + 3 << "\n";
      next += 4;
    }
    test::write_text(dir / (stem + ".mtl"), mtl.str());
    test::write_text(dir / (stem + ".obj"), obj.str());
    return dir / (stem + ".obj");
  }

  /// Exact distance from p to the nearest rectangle (an oracle for "on the surface").
  double distance(const Vec3& p) const {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& r : rects) {
      Vec3 q = glm::clamp(p, r.lo, r.hi);
      best = std::min(best, double(glm::length(p - q)));
    }
    return best;
  }
  bool over_object(float x, float z, float margin) const {
    for (const auto& [lo, hi] : objects)
      if (x > lo.x - margin && x < hi.x + margin && z > lo.z - margin && z < hi.z + margin) return true;
    return false;
  }
};

/// (b) a 0.6 cube and a 0.4x1.0x0.4 column on a 6x4 floor before a 3 m back wall, open elsewhere.
SceneDesc two_objects_scene(bool with_objects = true) {
  SceneDesc s;
  s.materials = {{"floor", Rgb(0.7f, 0.7f, 0.7f)}, {"wall", Rgb(0.8f, 0.75f, 0.7f)},
                 {"cube", Rgb(0.6f, 0.35f, 0.3f)}, {"column", Rgb(0.3f, 0.5f, 0.6f)}};
  s.rect({Vec3(-3.f, 0.f, -2.f), Vec3(3.f, 0.f, 2.f), Vec3(0.f, 1.f, 0.f), "floor"});
  s.rect({Vec3(-3.f, 0.f, -2.f), Vec3(3.f, 3.f, -2.f), Vec3(0.f, 0.f, 1.f), "wall"});
  if (with_objects) {
    s.box(Vec3(-1.1f, 0.f, -0.3f), Vec3(-0.5f, 0.6f, 0.3f), "cube", false);
    s.box(Vec3(0.8f, 0.f, -0.7f), Vec3(1.2f, 1.f, -0.3f), "column", false);
  }
  return s;
}
/// Two coloured lights; each object shadows the floor and the wall.
const char* kTwoObjectsLights = R"({"lights":[
  {"type":"point","position":[-1.8,2.0,1.0],"intensity":[3.0,1.0,0.5]},
  {"type":"point","position":[1.9,1.8,0.9],"intensity":[0.5,1.5,3.0]}]})";

/// (c) a closed 5x3x4 room with a 0.8x1.0x0.8 pedestal.
SceneDesc spot_room_scene() {
  SceneDesc s;
  s.materials = {{"room", Rgb(0.75f, 0.75f, 0.72f)}, {"pedestal", Rgb(0.5f, 0.45f, 0.4f)}};
  s.box(Vec3(0.f), Vec3(5.f, 3.f, 4.f), "room", true);
  s.box(Vec3(1.6f, 0.f, 1.6f), Vec3(2.4f, 1.f, 2.4f), "pedestal", false);
  return s;
}
const Vec3 kSpotPosition(3.6f, 2.7f, 1.2f);
const Vec3 kSpotAim(3.0f, 0.f, 2.0f);  // the floor beside the pedestal; the cone grazes the pedestal
std::string spot_room_lights() {
  Vec3 d = glm::normalize(kSpotAim - kSpotPosition);
  std::ostringstream o;
  o << std::setprecision(9) << R"({"lights":[)"
    << R"({"type":"point","position":[1.0,2.5,3.0],"intensity":[1.5,1.5,1.5]},)"
    << R"({"type":"spot","position":[)" << kSpotPosition.x << "," << kSpotPosition.y << "," << kSpotPosition.z
    << "],\"direction\":[" << d.x << "," << d.y << "," << d.z
    << R"(],"cutoff_deg":25,"falloff_deg":5,"intensity":[4.0,3.5,3.0]}]})";
  return o.str();
}

// ---------------------------------------------------------------------------
// Running the launcher.

fs::path cache_dir() {
  fs::path dir = fs::path(HILIGHT_TEST_OUTPUT_DIR) / "solve-cache";
  fs::create_directories(dir);
  return dir;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double diagonal_of(const fs::path& scene) {
  auto r = test::run_hilight({"info", scene.string(), "--json"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  return json::parse(r.out).at("diagonal").get<double>();
}

void render(const fs::path& scene, const fs::path& lights, const fs::path& out, const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"render", scene.string(), "--lights", lights.string(), "-o", out.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  auto r = test::run_hilight(args);
  INFO("render " << scene << " " << lights << ": " << r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE(fs::exists(out));
}

struct Solved {
  Lighting lights;
  json report;
  fs::path lights_path;
  double seconds = 0;
};

Solved solve(const fs::path& scene, const fs::path& target, const fs::path& dir, const std::string& name,
             std::vector<std::string> extra = {}) {
  Solved s;
  s.lights_path = dir / (name + ".json");
  fs::path report = dir / (name + "-report.json");
  std::vector<std::string> args = {"solve", scene.string(), "--target", target.string(), "-o", s.lights_path.string(),
                                   "--report", report.string(), "--cache-dir", cache_dir().string()};
  args.insert(args.end(), extra.begin(), extra.end());
  auto t0 = std::chrono::steady_clock::now();
  auto r = test::run_hilight(args);
  s.seconds = seconds_since(t0);
  INFO("solve " << name << ": exit " << r.exit_code << ", stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  s.lights = hilight::read_lights_json(s.lights_path);
  std::ifstream in(report);
  s.report = json::parse(in);
  REQUIRE(s.report.at("lights").get<size_t>() == s.lights.size());
  return s;
}

size_t count_of(const Lighting& lights, LightType type) {
  return size_t(std::count_if(lights.begin(), lights.end(), [&](const Light& l) { return l.type == type; }));
}

/// Mean over the true lights of the distance to the nearest found light of the same type.
double mean_position_error(const Lighting& truth, const Lighting& found) {
  double sum = 0;
  for (const auto& t : truth) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& f : found)
      if (f.type == t.type) best = std::min(best, double(glm::length(f.position - t.position)));
    sum += best;
  }
  return sum / double(truth.size());
}

std::string describe(const Lighting& lights) {
  std::ostringstream o;
  o << std::setprecision(4);
  for (const auto& l : lights) {
    o << "  " << hilight::to_string(l.type) << " at (" << l.position.x << ", " << l.position.y << ", " << l.position.z
      << ") I=(" << l.intensity.r << ", " << l.intensity.g << ", " << l.intensity.b << ")";
    if (l.type == LightType::Spot)
      o << " dir=(" << l.direction.x << ", " << l.direction.y << ", " << l.direction.z << ") cutoff " << l.cutoff_deg
        << " falloff " << l.falloff_deg;
    o << "\n";
  }
  return o.str();
}

// ---------------------------------------------------------------------------
// Targets as data.

struct Points {
  std::vector<Vec3> position, normal;
  std::vector<Rgb> colour;
};

Points read_points(const fs::path& ply) {
  hilight::PlyVertices v = hilight::read_ply_vertices(ply);
  Points p;
  for (size_t i = 0; i < v.count; ++i) {
    p.position.emplace_back(v.properties["x"][i], v.properties["y"][i], v.properties["z"][i]);
    if (v.has("nx")) p.normal.emplace_back(v.properties["nx"][i], v.properties["ny"][i], v.properties["nz"][i]);
    p.colour.emplace_back(v.properties["red"][i], v.properties["green"][i], v.properties["blue"][i]);
  }
  return p;
}

/// ASCII PLY `float x y z [nx ny nz] red green blue`, values printed so they read back exactly.
void write_points(const fs::path& path, const Points& p) {
  std::ostringstream o;
  const bool normals = !p.normal.empty();
  o << "ply\nformat ascii 1.0\nelement vertex " << p.position.size() << "\n"
    << "property float x\nproperty float y\nproperty float z\n"
    << (normals ? "property float nx\nproperty float ny\nproperty float nz\n" : "")
    << "property float red\nproperty float green\nproperty float blue\nend_header\n";
  o << std::setprecision(9);
  for (size_t i = 0; i < p.position.size(); ++i) {
    o << p.position[i].x << " " << p.position[i].y << " " << p.position[i].z << " ";
    if (normals) o << p.normal[i].x << " " << p.normal[i].y << " " << p.normal[i].z << " ";
    o << p.colour[i].r << " " << p.colour[i].g << " " << p.colour[i].b << "\n";
  }
  test::write_text(path, o.str());
}

/// Renders `lights_json` on scene (b) or (c) written to `dir`, returns scene path and target path.
struct Case {
  fs::path scene, lights, target;
  Lighting truth;
  double diagonal = 0;
};
/// `render_extra`: options of the target's render (e.g. its bounces).
Case make_case(const fs::path& dir, const fs::path& scene, const std::string& lights_text,
               const std::vector<std::string>& render_extra = {}) {
  Case c;
  c.scene = scene;
  c.lights = dir / "true-lights.json";
  test::write_text(c.lights, lights_text);
  c.truth = hilight::read_lights_json(c.lights);
  c.target = dir / "target.ply";
  render(c.scene, c.lights, c.target, render_extra);
  c.diagonal = diagonal_of(c.scene);
  return c;
}
Case room_case(const fs::path& dir) {
  Case c;
  c.scene = kRoom;
  c.lights = kRoom4Lights;
  c.truth = hilight::read_lights_json(c.lights);
  c.target = dir / "target.ply";
  render(c.scene, c.lights, c.target);
  c.diagonal = diagonal_of(c.scene);
  return c;
}

/// The recovery criteria shared by scenes (a), (b), (c).
void check_recovery(const std::string& name, const Case& c, const Solved& s, bool check_dbar = true) {
  const double dbar_value = s.report.at("dbar").get<double>();
  const double err = mean_position_error(c.truth, s.lights);
  const double rel = err / c.diagonal;
  WARN(name << ": " << s.lights.size() << " lights (true " << c.truth.size() << "), D̄ " << dbar_value
            << ", mean position error " << err << " = " << 100 * rel << "% of diagonal " << c.diagonal << ", solve "
            << s.seconds << " s\nfound:\n"
            << describe(s.lights) << "true:\n"
            << describe(c.truth));
  CHECK(s.lights.size() == c.truth.size());
  CHECK(count_of(s.lights, LightType::Spot) == count_of(c.truth, LightType::Spot));
  CHECK(count_of(s.lights, LightType::Point) == count_of(c.truth, LightType::Point));
  if (check_dbar) CHECK(dbar_value <= 0.015);
  CHECK(rel <= kPositionTolerance);
}

} // namespace

// ---------------------------------------------------------------------------
// Recovery of known lights.

TEST_CASE("solve recovers the 4 point lights of the bundled room", "[solve][recovery]") {
  auto dir = test::output_dir("solve_recovery_room");
  Case c = room_case(dir);
  Solved s = solve(c.scene, c.target, dir, "found");
  check_recovery("room (a)", c, s);
}

TEST_CASE("solve recovers 2 coloured point lights that cast shadows in an open scene", "[solve][recovery]") {
  auto dir = test::output_dir("solve_recovery_two_objects");
  Case c = make_case(dir, two_objects_scene().write(dir, "two-objects"), kTwoObjectsLights);
  Solved s = solve(c.scene, c.target, dir, "found");
  check_recovery("two objects (b)", c, s, /*check_dbar=*/false);  // D̄ ≤ 1.5%: the next test
  // The colours come back too: the nearest found light has the true intensity within 10%.
  for (const auto& t : c.truth) {
    const Light* nearest = nullptr;
    for (const auto& f : s.lights)
      if (!nearest || glm::length(f.position - t.position) < glm::length(nearest->position - t.position)) nearest = &f;
    REQUIRE(nearest);
    CHECK(glm::length(nearest->intensity - t.intensity) <= 0.1f * glm::length(t.intensity));
  }
}

// D̄ is measured by the reference renderer as `hilight render` configures it
// (issue 18), so the true lights score 0 and the found ones 0.02% here (it
// was 1.5% while D̄ came from the solve's fast twin).
TEST_CASE("solve reproduces the open two-object scene's target within D̄ 1.5%", "[solve][recovery][dbar]") {
  auto dir = test::output_dir("solve_recovery_two_objects_dbar");
  Case c = make_case(dir, two_objects_scene().write(dir, "two-objects"), kTwoObjectsLights);
  Solved s = solve(c.scene, c.target, dir, "found");
  const double dbar_value = s.report.at("dbar").get<double>();
  WARN("two objects (b): D̄ " << dbar_value << " (dbar_samples " << s.report.at("dbar_samples").get<double>() << ")");
  CHECK(dbar_value <= 0.015);
}

TEST_CASE("solve with a spot hint recovers one spotlight and one point light", "[solve][recovery][spot]") {
  auto dir = test::output_dir("solve_recovery_spot");
  Case c = make_case(dir, spot_room_scene().write(dir, "spot-room"), spot_room_lights());
  const Light& spot = c.truth[1];
  REQUIRE(spot.type == LightType::Spot);
  // The hint: position off by 0.2, direction off by 5°, cutoff off by 3°; intensity ignored.
  Vec3 offset = glm::normalize(Vec3(0.6f, -0.5f, 0.6f)) * 0.2f;
  Vec3 side = glm::normalize(glm::cross(spot.direction, Vec3(1.f, 0.f, 0.f)));
  const float tilt = glm::radians(5.f);
  Vec3 hint_direction = glm::normalize(std::cos(tilt) * spot.direction + std::sin(tilt) * side);
  Lighting hints = {Light::spot(spot.position + offset, hint_direction, spot.cutoff_deg + 3.f, Rgb(1.f), spot.falloff_deg)};
  REQUIRE(std::abs(glm::degrees(std::acos(glm::dot(hint_direction, spot.direction))) - 5.f) < 0.01f);
  hilight::write_lights_json(dir / "hints.json", hints);

  Solved s = solve(c.scene, c.target, dir, "found", {"--spot-hints", (dir / "hints.json").string()});
  check_recovery("spot room (c)", c, s);
  REQUIRE(count_of(s.lights, LightType::Spot) == 1);
  REQUIRE(count_of(s.lights, LightType::Point) == 1);
  const Light& found = *std::find_if(s.lights.begin(), s.lights.end(), [](const Light& l) { return l.type == LightType::Spot; });
  double angle = glm::degrees(std::acos(std::clamp(double(glm::dot(found.direction, spot.direction)), -1.0, 1.0)));
  WARN("spot: position error " << glm::length(found.position - spot.position) << " (hint 0.2), direction error "
                               << angle << "° (hint 5°), cutoff " << found.cutoff_deg << "° (true 25°, hint 28°)");
  CHECK(glm::length(found.position - spot.position) < 0.2f);
  CHECK(angle < 5.0);
  CHECK(std::abs(found.cutoff_deg - spot.cutoff_deg) < 3.f);
}

// ---------------------------------------------------------------------------
// The same solves through the ism-vulkan renderer (lavapipe here): the target
// comes from Embree, the solve evaluates everything with ism-vulkan, and the
// found lights, rendered by Embree, must reproduce the target within D̄ 2%.

/// D̄ of Embree's rendering of `lights` against `target` (both per vertex).
double embree_dbar(const Case& c, const fs::path& lights, const fs::path& dir) {
  const fs::path rendered = dir / "found-by-embree.ply";
  render(c.scene, lights, rendered);
  return test::dbar(read_points(rendered).colour, read_points(c.target).colour);
}

TEST_CASE("a solve with --renderer ism-vulkan recovers the open scene's 2 lights", "[solve][recovery][ism][slow]") {
  if (test::skip_without_renderer("ism-vulkan")) return;
  auto dir = test::output_dir("solve_recovery_ism_two_objects");
  Case c = make_case(dir, two_objects_scene().write(dir, "two-objects"), kTwoObjectsLights);
  // Every Vulkan call of the solve runs under the validation layer; an error fails the solve.
  Solved s = solve(c.scene, c.target, dir, "found", {"--renderer", "ism-vulkan", "--set", "validation=true"});
  const double embree = embree_dbar(c, s.lights_path, dir);
  WARN("ism-vulkan solve: " << s.lights.size() << " lights in " << s.seconds << " s, D̄ " << s.report.at("dbar").get<double>()
                            << " (ism-vulkan), " << embree << " (Embree rendering of the result)\nfound:\n"
                            << describe(s.lights));
  CHECK(s.lights.size() == c.truth.size());
  CHECK(embree <= 0.02);
  CHECK(mean_position_error(c.truth, s.lights) / c.diagonal <= kPositionTolerance);
}

TEST_CASE("a solve with --renderer ism-vulkan and a spot hint recovers the spot room's lights", "[solve][recovery][ism][spot][slow]") {
  if (test::skip_without_renderer("ism-vulkan")) return;
  auto dir = test::output_dir("solve_recovery_ism_spot");
  // Direct light: the spot's cone and the point lamp as ism-vulkan draws
  // them. Its bounce in a solve is the open scene's case above (and CIE 171
  // in test_cie171_renderers.cpp): in this closed room its VPLs miss ~10% of
  // the bounce at the creases (docs/ism-vulkan.md), which left D̄ 3.7% on the
  // samples, so every count edit was tried and refused, two minutes on lavapipe.
  const std::vector<std::string> direct = {"--bounces", "0"};
  Case c = make_case(dir, spot_room_scene().write(dir, "spot-room"), spot_room_lights(), direct);
  const Light& spot = c.truth[1];
  Lighting hints = {Light::spot(spot.position + Vec3(0.1f, -0.1f, 0.1f), spot.direction, spot.cutoff_deg + 3.f, Rgb(1.f),
                                spot.falloff_deg)};
  hilight::write_lights_json(dir / "hints.json", hints);
  // No validation layer here (the open scene's solve above runs every Vulkan call under it).
  Solved s = solve(c.scene, c.target, dir, "found",
                   {"--renderer", "ism-vulkan", "--bounces", "0", "--spot-hints", (dir / "hints.json").string()});
  const fs::path rendered = dir / "found-by-embree.ply";
  render(c.scene, s.lights_path, rendered, direct);
  const double embree = test::dbar(read_points(rendered).colour, read_points(c.target).colour);
  WARN("ism-vulkan spot solve: " << s.lights.size() << " lights in " << s.seconds << " s, D̄ " << s.report.at("dbar").get<double>()
                                 << " (ism-vulkan), " << embree << " (Embree rendering of the result)\nfound:\n"
                                 << describe(s.lights));
  CHECK(count_of(s.lights, LightType::Spot) == 1);
  CHECK(count_of(s.lights, LightType::Point) == 1);
  CHECK(embree <= 0.02);
  CHECK(mean_position_error(c.truth, s.lights) / c.diagonal <= kPositionTolerance);
}

// ---------------------------------------------------------------------------
// Robustness.

TEST_CASE("an infeasible target (floor shadows removed) still gives the right number of lights", "[solve][recovery][infeasible]") {
  auto dir = test::output_dir("solve_infeasible");
  SceneDesc full = two_objects_scene();
  Case c = make_case(dir, full.write(dir, "two-objects"), kTwoObjectsLights);

  // The shadow-free floor: the same lights rendered on the scene without the
  // two objects, evaluated exactly at the target's floor vertices (in process,
  // so no dependence on how the floor is tessellated without the objects).
  // Each floor vertex (y = 0, normal up, outside the objects' footprints) gets
  // the channel-wise max of its target colour and its shadow-free colour: the
  // darkening the objects cause is removed, their bounce light is kept.
  // No lights can produce that: the objects stand there, so they must shadow.
  fs::path bare_path = two_objects_scene(false).write(dir, "floor-and-wall");
  const float max_edge = float(c.diagonal / 40.0);
  auto bare = std::make_shared<const hilight::Scene>(hilight::load_scene(bare_path, {max_edge}));
  auto renderer = test::make_renderer("embree", bare);

  Points target = read_points(c.target);
  REQUIRE(!target.normal.empty());
  std::vector<size_t> floor;
  hilight::SurfacePoints pts;
  for (size_t i = 0; i < target.position.size(); ++i) {
    const Vec3& p = target.position[i];
    if (std::abs(p.y) > 1e-5f || target.normal[i].y < 0.5f || full.over_object(p.x, p.z, 1e-4f)) continue;
    floor.push_back(i);
    pts.positions.push_back(p);
    pts.normals.push_back(Vec3(0.f, 1.f, 0.f));
    pts.albedo.push_back(full.materials.at("floor"));
  }
  REQUIRE(floor.size() > 1000);
  auto free_floor = renderer->illuminate(pts, c.truth);
  size_t shadowed = 0;
  for (size_t k = 0; k < floor.size(); ++k) {
    Rgb& t = target.colour[floor[k]];
    // A visible shadow: the shadow-free floor is at least 25% brighter in some channel.
    shadowed += glm::any(glm::greaterThan(free_floor[k], 1.25f * t + Rgb(1e-6f)));
    t = glm::max(t, free_floor[k]);
  }
  WARN("infeasible target: " << shadowed << " of " << floor.size() << " floor vertices lifted out of a shadow");
  REQUIRE(shadowed > 100);  // the objects do cast visible floor shadows
  fs::path edited = dir / "no-shadows.ply";
  write_points(edited, target);

  Solved s = solve(c.scene, edited, dir, "found");
  const double err = mean_position_error(c.truth, s.lights) / c.diagonal;
  WARN("infeasible: " << s.lights.size() << " lights, D̄ " << s.report.at("dbar").get<double>() << ", mean position error "
                      << 100 * err << "% of diagonal\n"
                      << describe(s.lights));
  CHECK(s.lights.size() == 2);
}

// The noise floor (≈5.8%) lifts cut 4's unrefined D̄ above ε_opt (0.15): a
// count walk that starts at the first cut below ε_opt and only adds lights
// returns 5 here (the 5th ≈ (0.054, 0, 0)), although refined cut 4 is as good
// as cut 5 (D̄ 0.0614 vs 0.0610). The walk must also go down.
TEST_CASE("±10% multiplicative noise on the room's target still gives 4 lights", "[solve][recovery][noise]") {
  auto dir = test::output_dir("solve_noise");
  Case c = room_case(dir);
  Points target = read_points(c.target);
  std::mt19937 rng(20240611u);  // mt19937's output is fixed by the standard
  auto factor = [&] { return float(0.9 + 0.2 * (double(rng()) / 4294967296.0)); };
  for (auto& col : target.colour) col *= Rgb(factor(), factor(), factor());
  fs::path noisy = dir / "noisy.ply";
  write_points(noisy, target);

  Solved s = solve(c.scene, noisy, dir, "found");
  const double err = mean_position_error(c.truth, s.lights) / c.diagonal;
  const double dbar_value = s.report.at("dbar").get<double>();
  WARN("noisy room: " << s.lights.size() << " lights, D̄ " << dbar_value << " (noise alone ≈ 0.058), mean position error "
                      << 100 * err << "% of diagonal\n"
                      << describe(s.lights));
  CHECK(s.lights.size() == 4);
  CHECK(dbar_value <= 0.08);
  CHECK(err <= kPositionTolerance);
}

// ---------------------------------------------------------------------------
// Options and modes.

TEST_CASE("solve --lights N gives exactly N lights", "[solve][lights-count]") {
  auto dir = test::output_dir("solve_fixed_count");
  Case c = room_case(dir);
  double previous = 0;
  for (unsigned n : {2u, 5u}) {
    Solved s = solve(c.scene, c.target, dir, "found-" + std::to_string(n), {"--lights", std::to_string(n)});
    const double dbar_value = s.report.at("dbar").get<double>();
    WARN("--lights " << n << ": " << s.lights.size() << " lights, D̄ " << dbar_value);
    CHECK(s.lights.size() == n);
    CHECK(count_of(s.lights, LightType::Point) == n);
    if (n == 5) CHECK(dbar_value < previous);  // more lights than 2 fit the 4-light target better
    previous = dbar_value;
  }
}

TEST_CASE("fine-tune re-optimizes found lights to a brightened target", "[solve][fine-tune]") {
  auto dir = test::output_dir("solve_fine_tune");
  Case c = room_case(dir);
  Solved first = solve(c.scene, c.target, dir, "found");
  REQUIRE(first.lights.size() == 4);

  // Brighten the right half of the room by 20%, in a way lights can do (so the
  // optimum is known): add 20% of what the two lights at x > 3 give. Rendering
  // is linear and repeatable, so target + render(0.2 x those lights) is the
  // render of the room with those two lights 20% brighter.
  Lighting extra;
  for (auto l : c.truth)
    if (l.position.x > 3.f) {
      l.intensity *= 0.2f;
      extra.push_back(l);
    }
  REQUIRE(extra.size() == 2);
  hilight::write_lights_json(dir / "extra.json", extra);
  render(c.scene, dir / "extra.json", dir / "extra.ply");
  Points target = read_points(c.target);
  Points added = read_points(dir / "extra.ply");
  REQUIRE(added.colour.size() == target.colour.size());
  for (size_t i = 0; i < target.colour.size(); ++i) target.colour[i] += added.colour[i];
  fs::path brighter = dir / "brighter.ply";
  write_points(brighter, target);

  // D̄ of the initial lights against the new target (rendered by the launcher).
  render(c.scene, first.lights_path, dir / "initial.ply");
  Points initial = read_points(dir / "initial.ply");
  REQUIRE(initial.colour.size() == target.colour.size());
  const double dbar_initial = test::dbar(initial.colour, target.colour);

  Solved tuned = solve(c.scene, brighter, dir, "tuned", {"--mode", "fine-tune", "--initial", first.lights_path.string()});
  const double dbar_tuned = tuned.report.at("dbar").get<double>();
  WARN("fine-tune: D̄ of the initial lights " << dbar_initial << " -> " << dbar_tuned << " after fine-tune\n"
                                             << describe(tuned.lights));
  CHECK(tuned.report.at("mode") == "fine-tune");
  CHECK(tuned.lights.size() == first.lights.size());
  CHECK(dbar_tuned < 0.75 * dbar_initial);
  CHECK(dbar_tuned <= 0.03);
  // Each true light's nearest tuned light has its intensity: x1.2 for the two at x > 3.
  for (const auto& t : c.truth) {
    const Light* nearest = &tuned.lights.front();
    for (const auto& f : tuned.lights)
      if (glm::length(f.position - t.position) < glm::length(nearest->position - t.position)) nearest = &f;
    const Rgb wanted = t.intensity * (t.position.x > 3.f ? 1.2f : 1.f);
    INFO("true light at x " << t.position.x << ": tuned intensity " << nearest->intensity.r << ", " << nearest->intensity.g
                            << ", " << nearest->intensity.b);
    CHECK(glm::length(nearest->intensity - wanted) <= 0.05f * glm::length(wanted));
  }
}

TEST_CASE("add keeps the given lights exactly and appends what they miss", "[solve][add]") {
  auto dir = test::output_dir("solve_add");
  Case c = room_case(dir);
  Lighting three(c.truth.begin(), c.truth.begin() + 3);
  const Light missing = c.truth[3];
  hilight::write_lights_json(dir / "three.json", three);
  Lighting initial = hilight::read_lights_json(dir / "three.json");

  Solved s = solve(c.scene, c.target, dir, "found", {"--mode", "add", "--initial", (dir / "three.json").string()});
  const double dbar_value = s.report.at("dbar").get<double>();
  double nearest = std::numeric_limits<double>::infinity();
  for (size_t j = 3; j < s.lights.size(); ++j) nearest = std::min(nearest, double(glm::length(s.lights[j].position - missing.position)));
  WARN("add: " << s.lights.size() << " lights, D̄ " << dbar_value << ", nearest added light " << nearest
               << " from the missing one\n"
               << describe(s.lights));
  CHECK(s.report.at("mode") == "add");
  REQUIRE(s.lights.size() > 3);
  for (size_t j = 0; j < 3; ++j) {
    INFO("light " << j);
    CHECK(s.lights[j].type == initial[j].type);
    CHECK(s.lights[j].position == initial[j].position);  // exact, not approximately
    CHECK(s.lights[j].intensity == initial[j].intensity);
  }
  CHECK(dbar_value <= 0.02);
}

TEST_CASE("the same solve with the same --seed writes byte-identical lights", "[solve][determinism]") {
  auto dir = test::output_dir("solve_determinism");
  Case c = make_case(dir, two_objects_scene().write(dir, "two-objects"), kTwoObjectsLights);
  Solved a = solve(c.scene, c.target, dir, "first", {"--seed", "7"});
  Solved b = solve(c.scene, c.target, dir, "second", {"--seed", "7"});
  auto bytes = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  REQUIRE(!bytes(a.lights_path).empty());
  CHECK(bytes(a.lights_path) == bytes(b.lights_path));
  CHECK(a.report.at("dbar") == b.report.at("dbar"));
}

// ---------------------------------------------------------------------------
// Targets refused and accepted.

namespace {

/// 25 points on scene (b)'s floor, in the open front-left corner, as ASCII PLY rows.
struct FloorGrid {
  std::vector<Vec3> points;
  FloorGrid() {
    for (int i = 0; i < 5; ++i)
      for (int k = 0; k < 5; ++k) points.emplace_back(-2.6f + 0.25f * float(i), 0.f, 0.8f + 0.25f * float(k));
  }
};

std::string ascii_ply(size_t n, const std::string& properties, const std::string& rows) {
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(n) + "\n" + properties + "end_header\n" + rows;
}
const std::string kXyz = "property float x\nproperty float y\nproperty float z\n";
const std::string kRgb = "property float red\nproperty float green\nproperty float blue\n";

/// Runs a solve that must be refused: exit 2, one stderr line naming the target, no lights written.
std::string refused(const fs::path& scene, const fs::path& target, const fs::path& dir) {
  fs::path out = dir / (target.stem().string() + "-lights.json");
  auto r = test::run_hilight({"solve", scene.string(), "--target", target.string(), "-o", out.string(), "--cache-dir",
                              cache_dir().string()});
  INFO("target " << target << ": exit " << r.exit_code << ", stderr: " << r.err);
  CHECK(r.exit_code == 2);
  CHECK(test::line_count(r.err) == 1);
  CHECK_THAT(r.err, Contains(target.string()));
  CHECK(!fs::exists(out));
  return r.err;
}

} // namespace

TEST_CASE("bad targets are refused with the file and the number of wrong points", "[solve][target][bad-input]") {
  auto dir = test::output_dir("solve_bad_targets");
  SceneDesc desc = two_objects_scene();
  fs::path scene = desc.write(dir, "two-objects");
  FloorGrid grid;
  const size_t n = grid.points.size();
  auto rows = [&](auto&& colour_of) {
    std::ostringstream o;
    for (size_t i = 0; i < n; ++i) o << grid.points[i].x << " " << grid.points[i].y << " " << grid.points[i].z << " " << colour_of(i) << "\n";
    return o.str();
  };

  SECTION("points off the surface: every vertex moved up by 0.5") {
    fs::path lights = dir / "lights.json";
    test::write_text(lights, kTwoObjectsLights);
    render(scene, lights, dir / "rendered.ply");
    Points p = read_points(dir / "rendered.ply");
    for (auto& pos : p.position) pos.y += 0.5f;
    // Oracle: a vertex moved up along a wall or a box side can still lie on the
    // surface; count exactly those farther than the tolerance (1e-3 x diagonal).
    const double tolerance = 1e-3 * diagonal_of(scene);
    size_t off = 0, borderline = 0;
    for (const auto& pos : p.position) {
      double d = desc.distance(pos);
      off += d > tolerance;
      borderline += std::abs(d - tolerance) < 1e-5;
    }
    REQUIRE(borderline == 0);
    REQUIRE(off > p.position.size() / 2);
    fs::path target = dir / "lifted.ply";
    write_points(target, p);
    std::string err = refused(scene, target, dir);
    CHECK_THAT(err, Contains(std::to_string(off) + " of " + std::to_string(p.position.size()) + " points"));
    CHECK_THAT(err, Contains("surface"));
  }
  SECTION("NaN colours") {
    fs::path target = dir / "nan.ply";
    test::write_text(target, ascii_ply(n, kXyz + kRgb, rows([](size_t i) { return i % 10 == 3 ? "nan 0.5 0.5" : "0.5 0.5 0.5"; })));
    std::string err = refused(scene, target, dir);
    CHECK_THAT(err, Contains("3 of 25 points"));
    CHECK_THAT(err, Contains("NaN"));
  }
  SECTION("negative colours") {
    fs::path target = dir / "negative.ply";
    test::write_text(target, ascii_ply(n, kXyz + kRgb, rows([](size_t i) { return i == 4 || i == 17 ? "0.5 -0.25 0.5" : "0.5 0.5 0.5"; })));
    std::string err = refused(scene, target, dir);
    CHECK_THAT(err, Contains("2 of 25 points"));
    CHECK_THAT(err, Contains("negative"));
  }
  SECTION("an empty target") {
    fs::path target = dir / "empty.ply";
    test::write_text(target, ascii_ply(0, kXyz + kRgb, ""));
    std::string err = refused(scene, target, dir);
    CHECK_THAT(err, Contains("no points"));
  }
  SECTION("every weight 0") {
    fs::path target = dir / "weightless.ply";
    test::write_text(target, ascii_ply(n, kXyz + kRgb + "property float weight\n", rows([](size_t) { return "0.5 0.5 0.5 0"; })));
    std::string err = refused(scene, target, dir);
    CHECK_THAT(err, Contains("weight 0"));
  }
  SECTION("no red property") {
    fs::path target = dir / "no-red.ply";
    test::write_text(target, ascii_ply(n, kXyz + "property float green\nproperty float blue\n", rows([](size_t) { return "0.5 0.5"; })));
    std::string err = refused(scene, target, dir);
    CHECK_THAT(err, Contains("red"));
  }
}

TEST_CASE("a target with uchar sRGB colours is accepted and read as its linear values", "[solve][target][srgb]") {
  auto dir = test::output_dir("solve_srgb_target");
  fs::path scene = two_objects_scene().write(dir, "two-objects");
  FloorGrid grid;
  // A warm pool of light on the floor: brighter toward the corner's centre.
  std::ostringstream srgb_rows, linear_rows;
  srgb_rows << std::setprecision(9);
  linear_rows << std::setprecision(9);
  for (const auto& p : grid.points) {
    float d = glm::length(Vec3(p.x + 2.1f, 0.f, p.z - 1.3f));
    int r = int(std::lround(230 - 80 * d)), g = int(std::lround(180 - 70 * d)), b = int(std::lround(140 - 60 * d));
    srgb_rows << p.x << " " << p.y << " " << p.z << " " << r << " " << g << " " << b << "\n";
    // The same colours decoded as the sRGB standard says, in float.
    auto decode = [](int v) {
      double e = v / 255.0;
      return float(e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4));
    };
    linear_rows << p.x << " " << p.y << " " << p.z << " " << decode(r) << " " << decode(g) << " " << decode(b) << "\n";
  }
  fs::path srgb = dir / "srgb.ply", linear = dir / "linear.ply";
  test::write_text(srgb, ascii_ply(grid.points.size(), kXyz + "property uchar red\nproperty uchar green\nproperty uchar blue\n", srgb_rows.str()));
  test::write_text(linear, ascii_ply(grid.points.size(), kXyz + kRgb, linear_rows.str()));

  Solved a = solve(scene, srgb, dir, "from-srgb", {"--lights", "1"});
  Solved b = solve(scene, linear, dir, "from-linear", {"--lights", "1"});
  REQUIRE(a.lights.size() == 1);
  // Identical linear values and seed: identical lights (sRGB decoded, not taken as linear or /255 only).
  CHECK(a.lights[0].position == b.lights[0].position);
  CHECK(a.lights[0].intensity == b.lights[0].intensity);
  CHECK(a.report.at("dbar") == b.report.at("dbar"));
}
