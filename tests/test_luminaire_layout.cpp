// Layouts a designer can build (issue 34): luminaires with a size that never
// overlap, a minimum spacing and a spacing-to-height ratio; regular arrays
// (aligned with the room, or on a ceiling grid) against free layouts; the
// count asked for; a margin on the whole grid; the maintenance factor;
// UGR; W/m² and LENI; the luminaire schedule (CSV) and glTF of a
// luminaire result; and bad input.
#include "hilight/illuminance_criteria.hpp"
#include "hilight/io/criteria_file.hpp"
#include "hilight/io/gltf.hpp"
#include "hilight/io/lights_file.hpp"
#include "hilight/io/photometry_io.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/light_space.hpp"
#include "hilight/solve/illuminance_design.hpp"
#include "hilight/ray_scene.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "hilight/scene_origin.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "hilight/units.hpp"
#include "photometry_files.hpp"
#ifdef HILIGHT_HAVE_IFCPP
#include "../frontends/cli/ifc_luminaires.hpp"
#endif
#include "support.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

using namespace hilight;

namespace {

const std::string kRoom = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";

/// A 600 × 600 mm LED panel (LM-63, opening 0.6 × 0.6 m): Lambertian
/// below, dark above, 3600 lm, 36 W.
std::string panel_text() {
  std::string text = test::ies_text(test::angles(0, 90, 5), {0.0}, [](double, double g) {
    return 3600.0 / kPi * std::cos(g * kPi / 180.0);
  }, 1, "TILT=NONE", 1, 1, 3600, 36);
  const std::string opening = "2 0.1 0.2 0.05";
  text.replace(text.find(opening), opening.size(), "2 0.6 0.6 0.0");
  text.replace(text.find("[MANUFAC] hilight tests"), 23, "[MANUFAC] hilight tests\n[LUMINAIRE] Panel 600, 3600 lm\n[LUMCAT] HT-600");
  return text;
}

std::filesystem::path panel(const std::filesystem::path& dir) {
  const auto path = dir / "panel.ies";
  test::write_text(path, panel_text());
  return path;
}

/// The same panel with no opening (a point source).
std::filesystem::path point_panel(const std::filesystem::path& dir) {
  std::string text = panel_text();
  text.replace(text.find("2 0.6 0.6 0.0"), 13, "2 0 0 0");
  const auto path = dir / "point.ies";
  test::write_text(path, text);
  return path;
}

std::filesystem::path criteria_file(const std::filesystem::path& dir, std::vector<std::string> args = {}) {
  const auto path = dir / "criteria.json";
  std::vector<std::string> make = {"target", "workplane", kRoom, "-o", path.string(), "--lux", "500", "--u0", "0.6"};
  make.insert(make.end(), args.begin(), args.end());
  const auto r = test::run_hilight(make);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  return path;
}

struct Solved {
  test::RunResult run;
  Lighting lights;
  nlohmann::json report;
};

Solved solve(const std::filesystem::path& dir, const std::filesystem::path& criteria, const std::filesystem::path& luminaire,
             std::vector<std::string> args, const std::string& out = "lights.json") {
  std::vector<std::string> cmd = {"solve", kRoom, "--target", criteria.string(), "--luminaire", luminaire.string(), "-o",
                                  (dir / out).string(), "--report", (dir / "report.json").string()};
  cmd.insert(cmd.end(), args.begin(), args.end());
  std::filesystem::remove(dir / out);
  std::filesystem::remove(dir / "report.json");
  Solved s;
  s.run = test::run_hilight(cmd);
  if (std::filesystem::exists(dir / "report.json")) s.report = nlohmann::json::parse(test::read_file(dir / "report.json"));
  if (std::filesystem::exists(dir / out) && out.size() > 5 && out.substr(out.size() - 5) == ".json") s.lights = read_lights_file(dir / out);
  return s;
}

/// Every pair of luminaires (axis-aligned squares of `side`) apart.
void check_no_overlap(const Lighting& lights, float side) {
  for (size_t a = 0; a < lights.size(); ++a)
    for (size_t b = a + 1; b < lights.size(); ++b) {
      const Vec3 d = lights[a].position - lights[b].position;
      INFO("luminaires " << a << " and " << b << " at " << d.x << ", " << d.z);
      CHECK(std::max(std::abs(d.x), std::abs(d.z)) >= side - 1e-3f);
    }
}

/// Positions that make a full nx × nz array of equal steps: the counts.
std::pair<size_t, size_t> array_shape(const Lighting& lights) {
  std::set<long> xs, zs;
  for (const Light& l : lights) {
    xs.insert(std::lround(l.position.x * 1000.0));
    zs.insert(std::lround(l.position.z * 1000.0));
  }
  if (xs.size() * zs.size() != lights.size()) return {0, 0};
  const auto equal_steps = [](const std::set<long>& v) {
    std::vector<long> a(v.begin(), v.end());
    for (size_t i = 2; i < a.size(); ++i)
      if (std::abs((a[i] - a[i - 1]) - (a[1] - a[0])) > 2) return false;
    return true;
  };
  if (!equal_steps(xs) || !equal_steps(zs)) return {0, 0};
  return {xs.size(), zs.size()};
}

std::vector<double> measure(const std::shared_ptr<const Scene>& scene, const SurfacePoints& points, const Lighting& lights, double mf) {
  auto renderer = test::make_renderer("embree", scene);
  std::vector<double> lux = lux_from_radiance(renderer->illuminate(points, lights));
  for (double& v : lux) v *= mf;
  return lux;
}

/// Ē over a grid's `points` (the first of `lux`) and Emin over all of `lux`
/// (the points and those between them).
std::pair<double, double> mean_and_low(const std::vector<double>& lux, size_t points) {
  double mean = 0, low = 1e30;
  for (size_t i = 0; i < points; ++i) mean += lux[i];
  for (double v : lux) low = std::min(low, v);
  return {mean / double(points), low};
}

} // namespace

TEST_CASE("the position index and UGR follow CIE 117's formula", "[lux][ugr]") {
  CHECK(guth_position_index(0, 0) == Approx(1.0));
  CHECK(guth_position_index(0, 45) > guth_position_index(0, 20));
  CHECK(guth_position_index(0, 30) > guth_position_index(60, 30));  // above the line of sight glares less than to the side (the brow)
  // Luckiesh–Guth's table: a source 45° above the line of sight straight ahead has p ≈ 7.
  CHECK(guth_position_index(0, 45) == Approx(7.0).epsilon(0.05));
  // Dimming every luminaire to half: L² halves twice, Lb once: UGR falls by 8·log10(2).
  CHECK(unified_glare_rating(100.0, 50.0) - unified_glare_rating(25.0, 25.0) == Approx(8.0 * std::log10(2.0)));
  CHECK(std::isnan(unified_glare_rating(0.0, 50.0)));
}

TEST_CASE("luminaires keep their size and spacing: no two overlap, --min-spacing and the spacing-to-height ratio hold", "[lux][layout][cli]") {
  const auto dir = test::output_dir("layout_spacing");
  const auto criteria = criteria_file(dir);
  const auto ies = panel(dir);
  for (const std::string layout : {"free", "auto"}) {
    const Solved s = solve(dir, criteria, ies, {"--layout", layout});
    INFO(layout << ": " << s.run.err);
    REQUIRE(s.run.exit_code == 0);
    REQUIRE(s.lights.size() >= 2);
    check_no_overlap(s.lights, 0.6f);
    CHECK(s.report["luminaire_size_m"][0] == Approx(0.6));
    CHECK(s.report["met"] == true);
  }
  const Solved spaced = solve(dir, criteria, ies, {"--layout", "free", "--min-spacing", "1.8"});
  INFO(spaced.run.err);
  REQUIRE(spaced.run.exit_code == 0);
  for (size_t a = 0; a < spaced.lights.size(); ++a)
    for (size_t b = a + 1; b < spaced.lights.size(); ++b) {
      const Vec3 d = spaced.lights[a].position - spaced.lights[b].position;
      CHECK(std::hypot(d.x, d.z) >= 1.8f - 1e-3f);
    }
  // The spacing-to-height ratio: the nearest neighbour within R × the height over the work plane.
  const Solved ratio = solve(dir, criteria, ies, {"--layout", "free", "--max-spacing-ratio", "1.0", "--mount", "ceiling", "--offset", "0.1"});
  INFO(ratio.run.err);
  REQUIRE(ratio.run.exit_code == 0);
  REQUIRE(ratio.lights.size() >= 2);
  for (size_t a = 0; a < ratio.lights.size(); ++a) {
    float nearest = 1e9f;
    for (size_t b = 0; b < ratio.lights.size(); ++b)
      if (a != b) nearest = std::min(nearest, std::hypot(ratio.lights[a].position.x - ratio.lights[b].position.x,
                                                         ratio.lights[a].position.z - ratio.lights[b].position.z));
    CHECK(nearest <= 1.0f * (ratio.lights[a].position.y - 0.75f) + 1e-3f);
  }
  // --luminaire-size W,L: the outline given (and the panel integrated over it).
  const Solved sized = solve(dir, criteria, point_panel(dir), {"--luminaire-size", "1.2,0.3", "--layout", "free"});
  INFO(sized.run.err);
  REQUIRE(sized.run.exit_code == 0);
  CHECK(sized.report["luminaire_size_m"][0] == Approx(0.3));  // along C0: L
  CHECK(sized.report["luminaire_size_m"][1] == Approx(1.2));
  CHECK(sized.run.err.find("gives the luminaire no size") == std::string::npos);
  // A file that gives no size, and none given: said, once.
  const Solved sizeless = solve(dir, criteria, point_panel(dir), {"--layout", "free"});
  INFO(sizeless.run.err);
  REQUIRE(sizeless.run.exit_code == 0);
  REQUIRE(sizeless.lights.size() >= 2);
  CHECK(sizeless.run.err.find("hilight: warning: point.ies gives the luminaire no size") != std::string::npos);
}

TEST_CASE("lux: --lights N with criteria is honoured: exactly N, or exit 3 with the fewest that can", "[lux][layout][cli]") {
  const auto dir = test::output_dir("layout_count");
  const auto criteria = criteria_file(dir);
  const auto ies = panel(dir);
  const Solved automatic = solve(dir, criteria, ies, {});
  REQUIRE(automatic.run.exit_code == 0);
  const size_t m = automatic.lights.size();
  for (size_t n : {m + 2, m + 5}) {
    const Solved s = solve(dir, criteria, ies, {"--lights", std::to_string(n)});
    INFO(n << ": " << s.run.err);
    REQUIRE(s.run.exit_code == 0);
    CHECK(s.lights.size() == n);
    CHECK(s.report["lights_asked"] == n);
    CHECK(s.report["met"] == true);
    check_no_overlap(s.lights, 0.6f);
    for (const auto& d : s.report["dimming"]) CHECK(d.get<double>() >= 0.1 - 1e-9);  // every one lit
  }
  const Solved few = solve(dir, criteria, ies, {"--lights", "1"});
  INFO(few.run.err);
  CHECK(few.run.exit_code == 3);
  CHECK(few.lights.size() == 1);
  CHECK(few.run.err.find("--lights 1") != std::string::npos);
  CHECK(few.report["lights_asked"] == 1);
  // More than fit the room with the spacing asked for: refused, nothing written.
  const Solved many = solve(dir, criteria, ies, {"--lights", "60", "--min-spacing", "1.5", "--layout", "free"});
  CHECK(many.run.exit_code == 2);
  CHECK(test::line_count(many.run.err) == 1);
  CHECK(many.run.err.find("--lights 60") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "lights.json"));
}

TEST_CASE("lux: --margin 0.05 keeps Ē and U0 5% clear of their limits, U0 also between the grid's points", "[lux][layout][cli]") {
  const auto dir = test::output_dir("layout_margin");
  const auto criteria = criteria_file(dir);
  const Solved s = solve(dir, criteria, panel(dir), {"--margin", "0.05", "--maintenance-factor", "0.8"});
  INFO(s.run.err);
  REQUIRE(s.run.exit_code == 0);
  CHECK(s.report["margin"] == Approx(0.05));
  // Measured here: Ē at the points, Emin at the points and halfway between them and on the cells' corners.
  auto scene = std::make_shared<const Scene>(load_scene(kRoom, {}));
  const IlluminanceCriteria c = read_criteria(criteria);
  const CriterionGrid& g = c.grids.front();
  const RayScene rays(*scene);
  // The cells: the smallest steps between the points in x and in z.
  float cx = 1e9f, cz = 1e9f;
  for (const Vec3& p : g.points)
    for (const Vec3& q : g.points) {
      if (std::abs(p.z - q.z) < 1e-4f && std::abs(p.x - q.x) > 1e-4f) cx = std::min(cx, std::abs(p.x - q.x));
      if (std::abs(p.x - q.x) < 1e-4f && std::abs(p.z - q.z) > 1e-4f) cz = std::min(cz, std::abs(p.z - q.z));
    }
  SurfacePoints pts;
  pts.positions = g.points;
  const Vec3 lift(0.f, 1e-3f, 0.f);
  for (const Vec3& p : g.points)
    for (int a = -1; a <= 1; ++a)
      for (int b = -1; b <= 1; ++b) {
        const Vec3 q = p + Vec3(0.5f * float(a) * cx, 0.f, 0.5f * float(b) * cz);
        const Vec3 d = q - p;
        // Between points, in the room (not through a table's edge, not inside one).
        if ((a || b) && !rays.occluded(p + lift, glm::normalize(d), glm::length(d)) && !rays.inside_solid(q + lift))
          pts.positions.push_back(q);
      }
  pts.normals.assign(pts.positions.size(), Vec3(0.f, 1.f, 0.f));
  pts.albedo.assign(pts.positions.size(), Rgb(1.f));
  const auto [mean, low] = mean_and_low(measure(scene, pts, s.lights, 0.8), g.points.size());
  INFO("Ē " << mean << ", Emin over the whole grid " << low);
  CHECK(mean >= 1.05 * 500 * (1 - 2e-3));
  CHECK(low / mean >= 1.05 * 0.6 * (1 - 1e-2));
  CHECK(s.report["grids"][0]["u0_whole_grid"].get<double>() >= 1.05 * 0.6 * (1 - 1e-3));
}

TEST_CASE("lux: --margin 0.05 holds on the walls too, between their points", "[lux][layout][cli]") {
  const auto dir = test::output_dir("layout_margin_walls");
  const auto criteria = criteria_file(dir, {"--walls", "150", "--surface-u0", "0.25"});
  const Solved s = solve(dir, criteria, panel(dir), {"--margin", "0.05", "--layout", "free"});
  INFO(s.run.err);
  REQUIRE(s.run.exit_code == 0);
  const IlluminanceCriteria c = read_criteria(criteria);
  REQUIRE(c.grids.size() == 2);
  const CriterionGrid& walls = c.grids[1];
  REQUIRE(walls.kind == CriterionGrid::Kind::Walls);
  // Measured here: the walls' points, and halfway between each two
  // neighbours on the same wall where the wall runs on between them.
  auto scene = std::make_shared<const Scene>(load_scene(kRoom, {}));
  const RayScene rays(*scene);
  SurfacePoints pts;
  pts.positions = walls.points;
  pts.normals = walls.normals;
  for (size_t i = 0; i < walls.points.size(); ++i)
    for (size_t j = i + 1; j < walls.points.size(); ++j) {
      const Vec3 d = walls.points[j] - walls.points[i], n = walls.normals[i];
      const float len = glm::length(d);
      if (len > 1.5f * float(walls.spacing) || glm::dot(n, walls.normals[j]) < 0.999f || std::abs(glm::dot(n, d)) > 1e-3f) continue;
      const Vec3 q = walls.points[i] + 0.5f * d;
      if (rays.occluded(walls.points[i] + 1e-3f * n, d / len, len)) continue;
      const Hit under = rays.intersect(q + 1e-3f * n, -n, 2e-3f);
      if (!under.valid()) continue;  // a window or a doorway between them
      pts.positions.push_back(q);
      pts.normals.push_back(n);
    }
  REQUIRE(pts.positions.size() > walls.points.size());
  pts.albedo.assign(pts.positions.size(), Rgb(1.f));
  const auto [mean, low] = mean_and_low(measure(scene, pts, s.lights, 0.8), walls.points.size());
  INFO("walls: Ē " << mean << ", Emin with the points between " << low << " over " << pts.positions.size() << " points");
  CHECK(mean >= 1.05 * 150 * (1 - 2e-3));
  CHECK(low / mean >= 1.05 * 0.25 * (1 - 1e-2));
  CHECK(s.report["grids"][1]["u0_whole_grid"].get<double>() >= 1.05 * 0.25 * (1 - 1e-3));
}

TEST_CASE("an EULUMDAT body larger than its luminous opening keeps luminaires that far apart", "[lux][layout][cli]") {
  const auto dir = test::output_dir("layout_ldt_body");
  const auto criteria = criteria_file(dir);
  // A downlight whose opening the file leaves at 0 (a point source) in a 600 × 600 mm body.
  const std::vector<double> gammas = test::angles(0, 180, 10);
  std::vector<double> plane;
  for (double g : gammas) plane.push_back(g <= 90 ? 400.0 * std::cos(g * kPi / 180.0) : 0.0);
  std::string text = test::ldt_text(1, {0}, gammas, {plane}, 3600, 36);
  const std::string dated = "2026-11-24\n";
  std::string dimensions;
  for (int k = 0; k < 9; ++k) dimensions += "100\n";
  text.replace(text.find(dated) + dated.size(), dimensions.size(), "600\n600\n80\n0\n0\n0\n0\n0\n0\n");
  const auto ldt = dir / "body.ldt";
  test::write_text(ldt, text);
  const Photometry p = read_photometry(ldt);
  CHECK(p.body_length == Approx(0.6));
  CHECK(p.body_width == Approx(0.6));
  CHECK(p.opening_length == 0.0);
  const Solved s = solve(dir, criteria, ldt, {"--layout", "free"});
  INFO(s.run.err);
  REQUIRE(s.run.exit_code == 0);
  REQUIRE(s.lights.size() >= 2);
  CHECK(s.report["luminaire_size_m"][0] == Approx(0.6));
  CHECK(s.report["luminaire_size_m"][1] == Approx(0.6));
  check_no_overlap(s.lights, 0.6f);
}

TEST_CASE("the maintenance factor: maintained Ē = MF × new, stated, MF 0.8 needs 1/0.8 of the flux of MF 1", "[lux][layout][cli]") {
  const auto dir = test::output_dir("layout_mf");
  const auto criteria = criteria_file(dir);
  const auto ies = panel(dir);
  const Solved one = solve(dir, criteria, ies, {"--maintenance-factor", "1", "--layout", "free"});
  REQUIRE(one.run.exit_code == 0);
  const Solved eight = solve(dir, criteria, ies, {"--layout", "free"});
  INFO(eight.run.err);
  REQUIRE(eight.run.exit_code == 0);
  CHECK(eight.report["maintenance_factor"] == Approx(0.8));
  CHECK(eight.run.err.find("MF 0.80") != std::string::npos);
  CHECK(eight.run.err.find("maintained Ē") != std::string::npos);
  // The least flux any layout needs: 1/MF of MF 1's, or a little more where a luminaire at full output
  // would need more than full (the program is linear but each dimming is at most 1).
  const double least1 = one.report["least_luminous_flux_lm"].get<double>(), least8 = eight.report["least_luminous_flux_lm"].get<double>();
  CHECK(least8 >= least1 / 0.8 * (1 - 1e-6));
  CHECK(least8 <= least1 / 0.8 * 1.02);
  auto scene = std::make_shared<const Scene>(load_scene(kRoom, {}));
  const IlluminanceCriteria c = read_criteria(criteria);
  const std::vector<double> lux = measure(scene, c.points(), eight.lights, 0.8);
  double mean = 0;
  for (double v : lux) mean += v;
  CHECK(mean / double(lux.size()) >= 500 * (1 - 1e-3));
  CHECK(mean / double(lux.size()) == Approx(eight.report["grids"][0]["mean_lux"].get<double>()).epsilon(1e-4));
}

TEST_CASE("arrays: --layout array gives rows × columns aligned with the room or on a ceiling grid, auto reports both", "[lux][layout][cli]") {
  const auto dir = test::output_dir("layout_array");
  const auto criteria = criteria_file(dir);
  const auto ies = panel(dir);
  const Solved array = solve(dir, criteria, ies, {"--layout", "array"});
  INFO(array.run.err);
  REQUIRE(array.run.exit_code == 0);
  const auto [nx, nz] = array_shape(array.lights);
  CHECK(nx * nz == array.lights.size());
  CHECK(array.report["layout"]["chosen"] == "array");
  for (const auto& d : array.report["dimming"]) CHECK(d.get<double>() == Approx(array.report["dimming"][0].get<double>()));  // all alike
  // On a 0.6 m ceiling grid from the origin: every centre in the middle of a tile.
  const Solved grid = solve(dir, criteria, ies, {"--layout", "array", "--ceiling-grid", "0.6", "--ceiling-grid-origin", "0,0"});
  INFO(grid.run.err);
  REQUIRE(grid.run.exit_code == 0);
  CHECK(array_shape(grid.lights).first > 0);
  for (const Light& l : grid.lights)
    for (float v : {l.position.x, l.position.z}) {
      const float t = v / 0.6f - 0.5f;
      CHECK(std::abs(t - std::round(t)) < 1e-3f);
    }
  // Auto: both tried, each with its count and watts, the choice said.
  const Solved both = solve(dir, criteria, ies, {});
  INFO(both.run.err);
  REQUIRE(both.run.exit_code == 0);
  for (const char* kind : {"array", "free"}) {
    INFO(kind);
    CHECK(both.report["layout"][kind]["found"] == true);
    CHECK(both.report["layout"][kind]["luminaires"].get<size_t>() >= 1);
    CHECK(both.report["layout"][kind]["power_w"].get<double>() > 0);
  }
  CHECK(both.run.err.find("layouts: array") != std::string::npos);
  // The array is kept when it costs nothing: no more luminaires, flux within the tolerance.
  const auto& a = both.report["layout"]["array"];
  const auto& f = both.report["layout"]["free"];
  if (both.report["layout"]["chosen"] == "array") {
    CHECK(a["luminaires"].get<size_t>() <= f["luminaires"].get<size_t>());
  } else {
    CHECK((a["met"] == false || a["luminaires"].get<size_t>() > f["luminaires"].get<size_t>() ||
           a["luminous_flux_lm"].get<double>() > f["luminous_flux_lm"].get<double>()));
  }
}

namespace {
/// The test panel (panel_text) as a luminaire template.
Light panel_luminaire() {
  Light luminaire;
  luminaire.type = LightType::Luminaire;
  luminaire.profile = std::make_shared<const Photometry>(parse_ies(panel_text(), "panel.ies"));
  luminaire.profile_path = "panel.ies";
  return luminaire;
}

/// Panels 0.1 m under a 3 m ceiling at the centres of 3 m cells (i, k),
/// dimmed to 80%.
Lighting panels_in_cells(const Light& luminaire, const std::vector<std::pair<int, int>>& cells) {
  Lighting made;
  for (const auto& [i, k] : cells) {
    Light l = luminaire;
    l.position = Vec3(1.5f + 3.f * float(i), 2.9f, 1.5f + 3.f * float(k));
    l.intensity = Rgb(float(0.8 * luminaire.profile->peak() / kLumensPerWatt));
    made.push_back(l);
  }
  return made;
}

/// The work plane's criteria: what `made` gives there, a hair below.
IlluminanceCriteria criteria_met_by(const RayScene& rays, const Regions& regions, Renderer& renderer, const Lighting& made) {
  IlluminanceCriteria c;
  c.grids.push_back(make_work_plane(rays, regions, {}, 0.75f, 1.0, 0.0));
  const std::vector<double> lux = lux_from_radiance(renderer.illuminate(c.points(), made));
  const GridFigures f = grid_figures(c.grids.front(), lux);
  c.grids.front().lux = 0.99 * f.mean;
  c.grids.front().u0 = 0.99 * f.u0;
  return c;
}

/// The design gave back `made`: each panel within 1 cm, all dimmed to 80%.
void check_gives_back(const Lighting& made, const Lighting& lights, const DesignReport& report) {
  CHECK(report.met);
  REQUIRE(lights.size() == made.size());
  for (const Light& m : made) {
    float nearest = 1e9f;
    for (const Light& l : lights) nearest = std::min(nearest, glm::length(l.position - m.position));
    CHECK(nearest < 0.01f);
  }
  for (double d : report.dimming) CHECK(d == Approx(0.8).epsilon(0.02));
}
} // namespace

TEST_CASE("a target made from a 3 × 4 array of panels comes back as that array", "[lux][layout]") {
  // A 9 m × 12 m room, panels 0.1 m under its 3 m ceiling at the centres of 3 × 4 cells.
  auto scene = test::finish(builders::box_room(Vec3(9.f, 3.f, 12.f)), 0.5f);
  const RayScene rays(*scene);
  const Regions regions(rays);
  const Light luminaire = panel_luminaire();
  std::vector<std::pair<int, int>> cells;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 4; ++k) cells.emplace_back(i, k);
  const Lighting made = panels_in_cells(luminaire, cells);
  auto renderer = test::make_renderer("embree", scene);
  const IlluminanceCriteria c = criteria_met_by(rays, regions, *renderer, made);
  PlacementRules rules;
  rules.add("ceiling:0.1");
  const LightSpace space(rays, rules);
  for (double tile : {0.0, 0.6}) {
    INFO("ceiling grid " << tile);
    DesignSettings settings;
    settings.maintenance_factor = 1;
    settings.layout = LayoutChoice::Array;
    settings.ceiling_grid = tile;
    if (tile > 0) settings.grid_origin = glm::dvec2(0.0, 0.0);
    DesignReport report;
    const Lighting lights = design_for_illuminance(*renderer, space, luminaire, c, settings, report);
    INFO(report.array.shape << ", U0 wanted " << c.grids.front().u0);
    check_gives_back(made, lights, report);
  }
  // With the default (--layout auto) the array set beside the free layout
  // is that one too. The free layout that auto keeps meets the same
  // criteria with fewer luminaires: an array that costs more is not kept.
  DesignSettings settings;
  settings.maintenance_factor = 1;
  DesignReport report;
  const Lighting lights = design_for_illuminance(*renderer, space, luminaire, c, settings, report);
  INFO(report.array.shape << "; free " << report.free.count << "; kept " << report.chosen << " (" << report.why << ")");
  CHECK(report.array.tried);
  CHECK(report.array.met);
  CHECK(report.array.count == 12);
  CHECK((report.array.shape.rfind("3 × 4", 0) == 0 || report.array.shape.rfind("4 × 3", 0) == 0));
  CHECK(report.met);
  CHECK(lights.size() <= 12);
}

namespace {
/// An L-shaped room, 3 m high: 9 m × 9 m with the corner x, z in [6, 9]
/// cut away (slabs and walls 0.2 m thick, as a modelled building's).
Scene l_shaped_room() {
  Scene s;
  const float t = 0.2f, h = 3.f;
  const Rgb wall(0.7f), floor(0.4f);
  for (float y : {-t, h}) {  // floor and ceiling slabs, both legs
    const Rgb& r = y < 0.f ? floor : wall;
    builders::add_box(s, Vec3(-t, y, -t), Vec3(9.f + t, y + t, 6.f), r, false, y < 0.f ? "floor" : "ceiling");
    builders::add_box(s, Vec3(-t, y, 6.f), Vec3(6.f, y + t, 9.f + t), r, false, y < 0.f ? "floor" : "ceiling");
  }
  builders::add_box(s, Vec3(-t, 0.f, -t), Vec3(9.f + t, h, 0.f), wall, false, "wall");          // south
  builders::add_box(s, Vec3(-t, 0.f, 0.f), Vec3(0.f, h, 9.f + t), wall, false, "wall");          // west
  builders::add_box(s, Vec3(9.f, 0.f, 0.f), Vec3(9.f + t, h, 6.f + t), wall, false, "wall");     // east
  builders::add_box(s, Vec3(0.f, 0.f, 9.f), Vec3(6.f + t, h, 9.f + t), wall, false, "wall");     // north
  builders::add_box(s, Vec3(6.f, 0.f, 6.f), Vec3(9.f, h, 6.f + t), wall, false, "wall");         // the inner corner, along x
  builders::add_box(s, Vec3(6.f, 0.f, 6.f + t), Vec3(6.f + t, h, 9.f), wall, false, "wall");     // and along z
  return s;
}
} // namespace

// Issue 34: a grid over an L-shaped room's rectangle, the places outside
// the room left out, as a designer draws it (DIALux and Relux place grids
// in rectangles only). Before, every place of an array had to fit: no array
// of 8 stood in this room.
TEST_CASE("an L-shaped room gets one regular grid clipped to its outline: a target made from it comes back as it", "[lux][layout]") {
  auto scene = test::finish(l_shaped_room(), 0.5f);
  const RayScene rays(*scene);
  const Regions regions(rays);
  const Light luminaire = panel_luminaire();
  // A 3 × 3 grid of 3 m cells over the 9 m square; the corner cell's centre (7.5, 7.5) is outside.
  std::vector<std::pair<int, int>> cells;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      if (i != 2 || k != 2) cells.emplace_back(i, k);
  const Lighting made = panels_in_cells(luminaire, cells);
  auto renderer = test::make_renderer("embree", scene);
  const IlluminanceCriteria c = criteria_met_by(rays, regions, *renderer, made);
  PlacementRules rules;
  rules.add("ceiling:0.1");
  const LightSpace space(rays, rules);
  DesignSettings settings;
  settings.maintenance_factor = 1;
  settings.layout = LayoutChoice::Array;
  DesignReport report;
  const Lighting lights = design_for_illuminance(*renderer, space, luminaire, c, settings, report);
  INFO(report.array.shape << ", Ē wanted " << c.grids.front().lux << ", U0 wanted " << c.grids.front().u0);
  CHECK_THAT(report.array.shape, Catch::Contains("3 × 3") && Catch::Contains("8 in the room"));
  check_gives_back(made, lights, report);
}

TEST_CASE("UGR at the standard observers: reported, and a limit with --ugr-max", "[lux][ugr][cli]") {
  const auto dir = test::output_dir("layout_ugr");
  const auto criteria = criteria_file(dir);
  const auto ies = panel(dir);
  const Solved s = solve(dir, criteria, ies, {});
  INFO(s.run.err);
  REQUIRE(s.run.exit_code == 0);
  REQUIRE(s.report["ugr"]["observers"].size() == 4);
  const double ugr = s.report["ugr"]["max"].get<double>();
  CHECK(ugr > 5);
  CHECK(ugr < 35);
  CHECK(s.report["ugr"]["luminous_area_m2"] == Approx(0.36));
  CHECK(s.run.err.find("UGR") != std::string::npos);
  // A limit above it holds; one no layout can keep is said, exit 3.
  const Solved limited = solve(dir, criteria, ies, {"--ugr-max", std::to_string(std::ceil(ugr) + 1)});
  INFO(limited.run.err);
  CHECK(limited.run.exit_code == 0);
  CHECK(limited.report["ugr"]["max"].get<double>() <= std::ceil(ugr) + 1);
  const Solved strict = solve(dir, criteria, ies, {"--ugr-max", "1"});
  CHECK(strict.run.exit_code == 3);
  CHECK(strict.run.err.find("UGR") != std::string::npos);
}

// EN 12464-1's two postures: seated people's eyes and cylindrical
// illuminance at 1.2 m, standing people's at 1.6 m (--posture, issue 34).
TEST_CASE("posture: --posture standing puts the UGR observers' eyes and the cylindrical illuminance at 1.6 m, seated at 1.2 m", "[lux][ugr][cli]") {
  const auto dir = test::output_dir("layout_posture");
  const auto criteria = criteria_file(dir);
  const auto ies = panel(dir);
  const Solved seated = solve(dir, criteria, ies, {});
  const Solved standing = solve(dir, criteria, ies, {"--posture", "standing"});
  INFO(seated.run.err << standing.run.err);
  REQUIRE(seated.run.exit_code == 0);
  REQUIRE(standing.run.exit_code == 0);
  // The bundled room's floor is at y = 0.
  for (const auto& [s, height] : {std::pair<const Solved*, double>{&seated, 1.2}, {&standing, 1.6}}) {
    CHECK(s->report["posture"] == (height > 1.4 ? "standing" : "seated"));
    CHECK(s->report["cylindrical"]["height_m"].get<double>() == Approx(height));
    REQUIRE(s->report["ugr"]["observers"].size() == 4);
    for (const auto& o : s->report["ugr"]["observers"]) CHECK(o["eye"][1].get<double>() == Approx(height).margin(1e-4));
  }
  // Standing eyes are nearer the luminaires: more of them in view, their
  // glare and the walls' vertical light otherwise.
  CHECK(standing.report["cylindrical"]["mean_lux"].get<double>() != Approx(seated.report["cylindrical"]["mean_lux"].get<double>()));
  CHECK(standing.run.err.find("at 1.6 m") != std::string::npos);
  const test::RunResult bad = test::run_hilight({"solve", kRoom, "--target", criteria.string(), "--luminaire", ies.string(), "--posture",
                                                 "lying", "-o", (dir / "bad.json").string()});
  CHECK(bad.exit_code == 2);
  CHECK(test::line_count(bad.err) == 1);
  CHECK(bad.err.find("--posture") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "bad.json"));
}

// EN 12464-1's Ēz as a criterion: a row of the program as Ē's, so the
// layout meets it at least flux (issue 34).
TEST_CASE("cylindrical illuminance as a criterion: --cylindrical-min is met at least flux, or exit 3 when nothing can", "[lux][cli]") {
  const auto dir = test::output_dir("layout_cylindrical");
  const auto criteria = criteria_file(dir);
  const auto ies = panel(dir);
  const Solved free = solve(dir, criteria, ies, {});
  INFO(free.run.err);
  REQUIRE(free.run.exit_code == 0);
  const double ez = free.report["cylindrical"]["mean_lux"].get<double>();
  REQUIRE(ez > 0);
  CHECK(free.report["cylindrical"]["min_mean_lux_wanted"].is_null());
  // Asked 30% more Ēz than the lux criteria alone give: met, with more flux.
  const double wanted = std::round(1.3 * ez);
  const Solved asked = solve(dir, criteria, ies, {"--cylindrical-min", std::to_string(wanted)});
  INFO(asked.run.err);
  REQUIRE(asked.run.exit_code == 0);
  CHECK(asked.report["cylindrical"]["mean_lux"].get<double>() >= wanted * (1 - 1e-3));
  CHECK(asked.report["cylindrical"]["met"] == true);
  CHECK(asked.report["cylindrical"]["min_mean_lux_wanted"].get<double>() == wanted);
  CHECK(asked.report["total_luminous_flux_lm"].get<double>() > free.report["total_luminous_flux_lm"].get<double>());
  CHECK(asked.run.err.find("wanted Ēz ≥") != std::string::npos);
  // The work plane is still met.
  REQUIRE(asked.report["grids"].size() >= 1);
  for (const auto& g : asked.report["grids"]) CHECK(g["met"] == true);
  // More than every place at full output can give: the best written, exit 3.
  const Solved impossible = solve(dir, criteria, ies, {"--cylindrical-min", "1000000"});
  CHECK(impossible.run.exit_code == 3);
  CHECK(impossible.report["cylindrical"]["met"] == false);
}

TEST_CASE("energy: W/m² and LENI (EN 15193-1) from the power, the floor and the hours", "[lux][cli]") {
  const auto dir = test::output_dir("layout_energy");
  const auto criteria = criteria_file(dir);
  const Solved s = solve(dir, criteria, panel(dir), {"--operating-hours", "2000,500", "--leni-factors", "0.9,1,0.8", "--parasitic-power", "5"});
  INFO(s.run.err);
  REQUIRE(s.run.exit_code == 0);
  const auto& e = s.report["energy"];
  CHECK(e["floor_area_m2"].get<double>() == Approx(30.0).epsilon(0.05));  // the bundled room: 6 m × 5 m
  const double p = s.report["electrical_power_w"].get<double>(), a = e["floor_area_m2"].get<double>();
  CHECK(e["power_density_w_m2"].get<double>() == Approx(p / a));
  CHECK(e["leni_kwh_m2_a"].get<double>() == Approx((p * 0.9 * (2000 * 1 * 0.8 + 500 * 1) + 5 * (8760 - 2500)) / 1000 / a));
  CHECK(e["installed_power_w"].get<double>() == Approx(36.0 * double(s.lights.size())));
  // EN 15193-1's Pn: every luminaire installed at full power.
  CHECK(e["installed_leni_kwh_m2_a"].get<double>() ==
        Approx((36.0 * double(s.lights.size()) * 0.9 * (2000 * 1 * 0.8 + 500 * 1) + 5 * (8760 - 2500)) / 1000 / a));
  CHECK(s.run.err.find("W/m²") != std::string::npos);
  CHECK(s.run.err.find("LENI") != std::string::npos);
  // Cylindrical illuminance at 1.2 m and the modelling, measured again here at one point.
  const auto& cyl = s.report["cylindrical"];
  REQUIRE(cyl["points"].get<size_t>() > 0);
  CHECK(cyl["mean_lux"].get<double>() > 0);
  CHECK(cyl["modelling"].get<double>() > 0.1);
  CHECK(cyl["modelling"].get<double>() < 1.5);
  CHECK(cyl["u0"].get<double>() <= 1.0);
  CHECK(s.run.err.find("cylindrical Ēz") != std::string::npos);
}

TEST_CASE("a luminaire result leaves hilight: the schedule (CSV), the report per luminaire, glTF", "[lux][cli][gltf]") {
  const auto dir = test::output_dir("layout_outputs");
  const auto criteria = criteria_file(dir);
  const auto ies = panel(dir);
  const Solved s = solve(dir, criteria, ies, {"--schedule", (dir / "schedule.csv").string()});
  INFO(s.run.err);
  REQUIRE(s.run.exit_code == 0);
  // The report: per luminaire product, position, aim, dimming %, lm, W.
  REQUIRE(s.report["luminaires"].size() == s.lights.size());
  for (size_t j = 0; j < s.lights.size(); ++j) {
    const auto& l = s.report["luminaires"][j];
    CHECK(l["product"] == "hilight tests Panel 600, 3600 lm HT-600");
    for (int c = 0; c < 3; ++c) CHECK(l["position"][c].get<double>() == Approx(s.lights[j].position[c]).margin(1e-5));
    CHECK(l["aim"][1].get<double>() == Approx(-1.0));
    CHECK(l["dimming_percent"].get<double>() == Approx(100.0 * luminaire_dimming(s.lights[j])).epsilon(1e-5));
    CHECK(l["luminous_flux_lm"].get<double>() == Approx(luminous_flux(s.lights[j])).epsilon(1e-4));
    CHECK(l["power_w"].get<double>() == Approx(36.0 * luminaire_dimming(s.lights[j])).epsilon(1e-5));
  }
  // The CSV: a header and one row per luminaire.
  std::ifstream csv(dir / "schedule.csv");
  std::string line;
  std::vector<std::string> rows;
  while (std::getline(csv, line)) rows.push_back(line);
  REQUIRE(rows.size() == s.lights.size() + 1);
  CHECK(rows[0].rfind("index,product,file,x_m,y_m,z_m,aim_x,aim_y,aim_z,spin_deg,dimming_percent,luminous_flux_lm,power_w", 0) == 0);
  for (size_t j = 0; j < s.lights.size(); ++j) {
    // RFC 4180: a field with a comma is quoted.
    std::vector<std::string> cells(1);
    bool quoted = false;
    for (char ch : rows[j + 1]) {
      if (ch == '"') quoted = !quoted;
      else if (ch == ',' && !quoted) cells.emplace_back();
      else if (ch != '\r') cells.back() += ch;
    }
    CHECK(cells[1] == "hilight tests Panel 600, 3600 lm HT-600");
    REQUIRE(cells.size() == 13);
    CHECK(std::stod(cells[3]) == Approx(s.lights[j].position.x).margin(1e-5));
    CHECK(std::stod(cells[5]) == Approx(s.lights[j].position.z).margin(1e-5));
    CHECK(std::stod(cells[10]) == Approx(100.0 * luminaire_dimming(s.lights[j])).margin(0.01));
  }
  // glTF: each luminaire a spot, the IES file and dimming in its extras; hilight reads the luminaires back.
  const Solved g = solve(dir, criteria, ies, {}, "lights.glb");
  INFO(g.run.err);
  REQUIRE(g.run.exit_code == 0);
  const Lighting back = read_gltf_lights(dir / "lights.glb");
  REQUIRE(back.size() == s.lights.size());
  for (size_t j = 0; j < back.size(); ++j) {
    CHECK(back[j].type == LightType::Luminaire);
    CHECK(back[j].profile_path == std::filesystem::absolute(ies).lexically_normal().string());
    CHECK(glm::length(back[j].position - s.lights[j].position) < 1e-4f);
    CHECK(luminaire_dimming(back[j]) == Approx(luminaire_dimming(s.lights[j])).epsilon(1e-5));
  }
  const std::string text = test::read_file(dir / "lights.glb");
  CHECK(text.find("\"profile\":\"panel.ies\"") != std::string::npos);  // named from the glTF's folder
  CHECK(text.find("\"type\":\"spot\"") != std::string::npos);
  // A profile outside the glTF's folder is named, not read (as its buffers, issue 35).
  std::filesystem::create_directories(dir / "elsewhere");
  const Solved away = solve(dir, criteria, ies, {}, "elsewhere/lights.glb");
  REQUIRE(away.run.exit_code == 0);
  CHECK(test::read_file(dir / "elsewhere" / "lights.glb").find(std::filesystem::absolute(ies).lexically_normal().string()) != std::string::npos);
  CHECK_THROWS_WITH(read_gltf_lights(dir / "elsewhere" / "lights.glb"), Catch::Contains("outside the glTF's folder"));
}

TEST_CASE("a luminaire result's glTF opens in Blender: spots with the IES file named in their extras", "[lux][gltf][blender]") {
  if (std::system("blender --version > /dev/null 2>&1") != 0) {
    std::cout << "SKIPPED: blender is not installed (setup.sh installs it)" << std::endl;
    return;
  }
  const auto dir = test::output_dir("layout_blender");
  const auto criteria = criteria_file(dir);
  const auto ies = panel(dir);
  const Solved g = solve(dir, criteria, ies, {}, "lights.glb");
  INFO(g.run.err);
  REQUIRE(g.run.exit_code == 0);
  const auto log = dir / "blender.log";
  const std::string command = "blender -b --factory-startup --python '" + std::string(HILIGHT_SOURCE_DIR) +
                              "/tools/blender_gltf_roundtrip.py' -- '" + (dir / "lights.glb").string() + "' '" +
                              (dir / "blender.glb").string() + "' '" + (dir / "blender.json").string() + "' > '" + log.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  INFO(test::read_file(log));
  REQUIRE(status == 0);
  const auto report = nlohmann::json::parse(test::read_file(dir / "blender.json"));
  REQUIRE(report["lights"].size() == size_t(g.report["lights"].get<size_t>()));
  for (const auto& b : report["lights"]) {
    CHECK(b["type"] == "SPOT");
    CHECK(b["direction"][1].get<double>() == Approx(-1.0).margin(1e-5));
    REQUIRE(b["extras"].contains("hilight"));
    CHECK(b["extras"]["hilight"]["profile"] == "panel.ies");
    CHECK(b["extras"]["hilight"]["type"] == "luminaire");
  }
}

TEST_CASE("bad layout input: one line naming what is wrong, exit 2, nothing written", "[lux][layout][cli]") {
  const auto dir = test::output_dir("layout_bad");
  const auto criteria = criteria_file(dir);
  const auto ies = panel(dir);
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--maintenance-factor", "0"}, "--maintenance-factor"},
      {{"--maintenance-factor", "1.2"}, "--maintenance-factor"},
      {{"--luminaire-size", "7,7"}, "does not fit the room"},
      {{"--luminaire-size", "0.6"}, "--luminaire-size"},
      {{"--min-spacing", "40"}, "--min-spacing"},
      {{"--ceiling-grid", "8"}, "--ceiling-grid"},
      {{"--ceiling-grid-origin", "1;2"}, "--ceiling-grid-origin"},
      {{"--margin", "1.5"}, "--margin"},
      {{"--operating-hours", "8000,2000"}, "--operating-hours"},
      {{"--leni-factors", "1,2,1"}, "--leni-factors"},
      {{"--layout", "grid"}, "--layout"},
  };
  for (const auto& [args, named] : cases) {
    const Solved s = solve(dir, criteria, ies, args);
    INFO(args.front() << " " << args.back() << ": " << s.run.err);
    CHECK(s.run.exit_code == 2);
    CHECK(test::line_count(s.run.err) == 1);
    CHECK(s.run.err.find(named) != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir / "lights.json"));
    CHECK_FALSE(std::filesystem::exists(dir / "report.json"));
  }
  // A UGR limit with a luminaire that gives no luminous area.
  const Solved no_area = solve(dir, criteria, point_panel(dir), {"--ugr-max", "19"});
  CHECK(no_area.run.exit_code == 2);
  CHECK(test::line_count(no_area.run.err) == 1);
  CHECK(no_area.run.err.find("--ugr-max") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "lights.json"));
  // Criteria options with a painted target.
  const auto painted = test::run_hilight({"solve", kRoom, "--target", (dir / "t.ply").string(), "-o", (dir / "l.json").string(), "--margin", "0.05"});
  CHECK(painted.exit_code == 2);
  CHECK(painted.err.find("--margin") != std::string::npos);
}

TEST_CASE("a luminaire result in a copy of the input IFC: IfcLightFixture in its IfcSpace, read again by IfcPlusPlus and assimp",
          "[lux][cli][ifc][real]") {
#ifndef HILIGHT_HAVE_IFCPP
  std::cout << "SKIPPED: this build has no IfcPlusPlus (apt install libifcplusplus-dev libboost-dev)" << std::endl;
  return;
#else
  const std::string house = (builders::testmodels_dir() / "IFC" / "AC14-FZK-Haus.ifc").string();
  if (!std::filesystem::exists(house)) {
    std::cout << "SKIPPED: assimp-testmodels is not installed" << std::endl;
    return;
  }
  const auto dir = test::output_dir("layout_ifc");
  const auto ies = panel(dir);
  REQUIRE(test::run_hilight({"target", "workplane", house, "--region", "3", "--lux", "300", "--u0", "0.4", "-o", (dir / "c.json").string()})
              .exit_code == 0);
  const auto r = test::run_hilight({"solve", house, "--target", (dir / "c.json").string(), "--luminaire", ies.string(), "--mount",
                                    "ceiling", "--offset", "0.1", "-o", (dir / "lit.ifc").string(), "--report", (dir / "r.json").string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find("IfcLightFixture") != std::string::npos);
  const auto report = nlohmann::json::parse(test::read_file(dir / "r.json"));
  // IfcPlusPlus reads the copy: one fixture per luminaire, where the report puts it, contained in a named IfcSpace.
  const std::vector<cli::IfcFixture> fixtures = cli::read_ifc_fixtures(dir / "lit.ifc");
  REQUIRE(fixtures.size() == report["luminaires"].size());
  const std::set<std::string> rooms = {"Flur", "Wohnen", "Schlafzimmer", "Bad", "Buero", "K\xc3\xbc" "che", "Galerie"};
  for (size_t j = 0; j < fixtures.size(); ++j) {
    INFO(fixtures[j].name << " in " << fixtures[j].container);
    const auto& p = report["luminaires"][j]["position"];
    CHECK(glm::length(fixtures[j].position - glm::dvec3(p[0].get<double>(), p[1].get<double>(), p[2].get<double>())) < 1e-3);
    CHECK(rooms.count(fixtures[j].container) == 1);
  }
  // assimp reads it too (so hilight can solve in it again): the house as it was. The fixtures are
  // referenced in their spaces, which assimp's IFC reader does not draw (it crashes on contained ones).
  const Scene original = load_scene(house, {}), lit = load_scene(dir / "lit.ifc", {});
  CHECK(lit.triangles.size() == original.triangles.size());
  for (int k = 0; k < 3; ++k) {
    CHECK(lit.bounds.lo[k] == Approx(original.bounds.lo[k]).margin(1e-4));
    CHECK(lit.bounds.hi[k] == Approx(original.bounds.hi[k]).margin(1e-4));
  }
#endif
}

TEST_CASE("EN 12464-1's zones: the task, its immediate surround (0.5 m) and background (3 m) as criteria, met by the solve",
          "[lux][layout][cli]") {
  const auto dir = test::output_dir("layout_zones");
  const auto zones = dir / "zones.json";
  const auto t = test::run_hilight({"target", "workplane", kRoom, "--box", "2,0,1.5,4,3,3.5", "--lux", "500", "--u0", "0.6", "--zones",
                                    "-o", zones.string()});
  INFO(t.err);
  REQUIRE(t.exit_code == 0);
  const IlluminanceCriteria c = read_criteria(zones);
  REQUIRE(c.grids.size() == 3);
  CHECK(c.grids[0].name == "task");
  CHECK(c.grids[1].name == "surround");
  CHECK(c.grids[1].lux == 300);  // EN 12464-1's table for a 500 lx task
  CHECK(c.grids[1].u0 == Approx(0.4));
  CHECK(c.grids[2].name == "background");
  CHECK(c.grids[2].lux == Approx(100));  // a third of the surround's
  CHECK(c.grids[2].u0 == Approx(0.1));
  const auto from_task = [](const Vec3& p) {
    return std::hypot(std::max({2.f - p.x, 0.f, p.x - 4.f}), std::max({1.5f - p.z, 0.f, p.z - 3.5f}));
  };
  for (const Vec3& p : c.grids[0].points) CHECK(from_task(p) == 0.f);
  for (const Vec3& p : c.grids[1].points) {
    CHECK(from_task(p) > 0.f);
    CHECK(from_task(p) <= 0.5f + 1e-3f);
  }
  for (const Vec3& p : c.grids[2].points) {
    CHECK(from_task(p) > 0.5f);
    CHECK(from_task(p) <= 3.5f + 1e-3f);
  }
  CHECK(surround_lux(750) == 500);
  CHECK(surround_lux(300) == 200);
  CHECK(surround_lux(150) == 150);
  const Solved s = solve(dir, zones, panel(dir), {});
  INFO(s.run.err);
  REQUIRE(s.run.exit_code == 0);
  for (const auto& g : s.report["grids"]) CHECK(g["met"] == true);
  CHECK(s.run.err.find("surround: maintained") != std::string::npos);
  // Zones lie around a task area: one must be given.
  const auto no_box = test::run_hilight({"target", "workplane", kRoom, "--zones", "-o", (dir / "z2.json").string()});
  CHECK(no_box.exit_code == 2);
  CHECK(no_box.err.find("--zones") != std::string::npos);
}
