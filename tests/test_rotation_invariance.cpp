// A turned scene gives the same light (issue 19): real models from
// assimp-testmodels on a floor, turned by seeded random rotations about any
// axis with their lights, tessellate to the same vertices (turned) and
// render the same per-vertex values; the bounce's random streams, its sample
// frames and the choice among a crease's equally near faces are laid out in
// the scene's own frame, which turns with it (own_frame.hpp), and a turn
// about the vertical or any axis solves to the same lights, with and
// without the bounce.
// Scale is test_scale_invariance.cpp's (the last case here turns and scales
// at once), translation test_far_from_origin.cpp's.
#include "hilight/io/lights_json.hpp"
#include "hilight/io/ply_reader.hpp"
#include "hilight/own_frame.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "support.hpp"

#include <glm/gtc/quaternion.hpp>

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <random>

using namespace hilight;
namespace fs = std::filesystem;

namespace {

/// A rotation drawn uniformly (a random unit quaternion), from `seed`.
glm::dmat3 random_rotation(uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  glm::dquat q(normal(rng), normal(rng), normal(rng), normal(rng));
  return glm::mat3_cast(glm::normalize(q));
}

/// `scene` turned by r and scaled by k, in decimals (a scale that is not a
/// power of two rounds each coordinate: one-ulp differences, as in a file
/// exported in another unit).
void write_obj(const fs::path& path, const Scene& scene, const glm::dmat3& r, double k = 1.0) {
  std::ofstream obj(path);
  obj << std::setprecision(17);
  for (size_t v = 0; v < scene.positions.size(); ++v) {
    const DVec3 p = k * (r * DVec3(scene.positions[v])), n = r * DVec3(scene.normals[v]);
    obj << "v " << p.x << ' ' << p.y << ' ' << p.z << "\nvn " << n.x << ' ' << n.y << ' ' << n.z << "\n";
  }
  for (const auto& t : scene.triangles)
    obj << "f " << t[0] + 1 << "//" << t[0] + 1 << ' ' << t[1] + 1 << "//" << t[1] + 1 << ' ' << t[2] + 1 << "//" << t[2] + 1 << "\n";
}

/// A point light and a soft-edged spotlight over the models, turned by r
/// and scaled by k (intensities by k², the same irradiance); `nudged`: each
/// a few centimetres off and 10% brighter (a fine-tune's start).
void write_lights(const fs::path& path, const glm::dmat3& r, bool nudged = false, double k = 1.0) {
  const double more = (nudged ? 1.1 : 1.0) * k * k;
  const DVec3 off = nudged ? DVec3(0.06, -0.04, 0.05) : DVec3(0.0);
  const DVec3 a = k * (r * (DVec3(1.25, 2.3, 0.75) + off)), b = k * (r * (DVec3(-1.0, 2.25, 1.5) - off)),
              d = r * glm::normalize(DVec3(0.3, -1.0, -0.2) + 0.5 * off);
  std::ofstream out(path);
  out << std::setprecision(17) << R"({"lights": [{"type": "point", "position": [)" << a.x << ", " << a.y << ", " << a.z
      << R"(], "intensity": [)" << 2 * more << ", " << 2 * more << ", " << 2 * more << R"(]}, {"type": "spot", "position": [)" << b.x
      << ", " << b.y << ", " << b.z << R"(], "direction": [)" << d.x << ", " << d.y << ", " << d.z
      << R"(], "cutoff_deg": 40, "falloff_deg": 8, "intensity": [)" << 3 * more << ", " << 2.4 * more << ", " << 1.8 * more << "]}]}";
}

bool skip_without_models() {
  if (fs::exists(builders::testmodels_dir())) return false;
  std::cout << "SKIPPED: assimp-testmodels is not installed" << std::endl;
  return true;
}

} // namespace

TEST_CASE("rotation: a real scene's own frame turns, moves and scales with it", "[invariance][rotation][real]") {
  if (skip_without_models()) return;
  Scene home = builders::curved_models_on_floor();
  home.update_bounds();
  const OwnFrame frame = own_frame(home);
  for (uint64_t seed : {19u, 37u, 2026u}) {
    const glm::dmat3 r = random_rotation(seed);
    const DVec3 shift(3.5, -1.25, 7.0);
    const double k = 0.01 * double(seed % 7 + 1);
    Scene turned = home;
    for (Vec3& p : turned.positions) p = Vec3(k * (r * DVec3(p) + shift));
    for (Vec3& n : turned.normals) n = Vec3(r * DVec3(n));
    turned.update_bounds();
    const OwnFrame moved = own_frame(turned);
    const double centre_off = glm::length(DVec3(moved.centre) - k * (r * DVec3(frame.centre) + shift)) / turned.diagonal();
    double axes_off = 0;
    for (int a = 0; a < 3; ++a) axes_off = std::max(axes_off, glm::length(DVec3(moved.axes[a]) - r * DVec3(frame.axes[a])));
    INFO("seed " << seed << ": centre off " << centre_off << " of the size, axes off " << axes_off);
    CHECK(centre_off < 1e-6);
    CHECK(axes_off < 1e-4);
  }
}

TEST_CASE("rotation: real models turned at random render the same per-vertex values on the same tessellation",
          "[invariance][rotation][render][cli][real]") {
  if (skip_without_models()) return;
  const fs::path dir = test::output_dir("rotation_render");
  Scene scene = builders::curved_models_on_floor();
  scene.update_bounds();
  const glm::dmat3 identity(1.0);
  write_obj(dir / "home.obj", scene, identity);
  write_lights(dir / "home-lights.json", identity);
  for (const std::string bounces : {"0", "1"}) {
    const auto home = test::run_hilight({"render", (dir / "home.obj").string(), "--lights", (dir / "home-lights.json").string(), "-o",
                                         (dir / ("home-b" + bounces + ".ply")).string(), "--bounces", bounces});
    REQUIRE(home.exit_code == 0);
  }
  const PlyVertices home = read_ply_vertices(dir / "home-b0.ply");
  for (uint64_t seed : {19u, 37u, 2026u}) {
    const glm::dmat3 r = random_rotation(seed);
    const std::string name = "turned" + std::to_string(seed);
    write_obj(dir / (name + ".obj"), scene, r);
    write_lights(dir / (name + "-lights.json"), r);
    for (const std::string bounces : {"0", "1"}) {
      const fs::path out = dir / (name + "-b" + bounces + ".ply");
      const auto run = test::run_hilight({"render", (dir / (name + ".obj")).string(), "--lights", (dir / (name + "-lights.json")).string(),
                                          "-o", out.string(), "--bounces", bounces});
      INFO("seed " << seed << ", bounces " << bounces << ": " << run.err);
      REQUIRE(run.exit_code == 0);
      // The same tessellation, turned: vertex for vertex, by position and normal.
      const PlyVertices turned = read_ply_vertices(out);
      REQUIRE(turned.count == home.count);
      const double size = scene.diagonal();
      double worst_position = 0, worst_normal = 0;
      for (size_t i = 0; i < home.count; ++i) {
        auto at = [&](const PlyVertices& v, const char* x, const char* y, const char* z) {
          return DVec3(v.properties.at(x)[i], v.properties.at(y)[i], v.properties.at(z)[i]);
        };
        worst_position = std::max(worst_position, glm::length(r * at(home, "x", "y", "z") - at(turned, "x", "y", "z")) / size);
        worst_normal = std::max(worst_normal, glm::length(r * at(home, "nx", "ny", "nz") - at(turned, "nx", "ny", "nz")));
      }
      INFO("worst position " << worst_position << " of the size, worst normal " << worst_normal);
      CHECK(worst_position < 1e-6);
      CHECK(worst_normal < 1e-5);
      const auto values = test::ply_colours(out), reference = test::ply_colours(dir / ("home-b" + bounces + ".ply"));
      const double d = test::dbar(values, reference);
      size_t off = 0;
      for (size_t i = 0; i < values.size(); ++i)
        if (glm::length(values[i] - reference[i]) > 0.05f * glm::length(reference[i]) + 1e-6f) ++off;
      const double share_off = double(off) / double(values.size());
      std::cout << "rotation seed " << seed << ", bounces " << bounces << ": D-bar " << d << ", vertices > 5% off " << share_off << std::endl;
      INFO("D-bar " << d << ", vertices more than 5% off: " << share_off);
      // Measured (docs/rendering-model.md, "Tolerances"): direct light is the
      // same to float precision (D-bar 2.2-2.6e-7). Before the crease faces'
      // tie went by the own frame's order, 0.01-0.07% of the vertices (the
      // Wuson's mirror seam) flipped between lit and dark: D-bar 0.08-0.6%.
      if (bounces == "0") {
        CHECK(off == 0);
        CHECK(d <= 1e-4);
      } else {
        // The bounce gathers along the same rays, turned (its streams and
        // sample frames are laid out in the scene's own frame). Measured
        // D-bar 0.03-0.04%, no vertex 5% off; within the bound the scale
        // test holds it to (0.2%).
        CHECK(off == 0);
        CHECK(d <= 2e-3);
      }
    }
  }
}

namespace {

/// The curved models turned by each of `turns` (and scaled by k) with their
/// lights: a target rendered, then solved and, given `tuned`, fine-tuned
/// (from the lights nudged off, turned the same way) with `options`;
/// `found` and `tuned` get the lights.
void solve_turned(const fs::path& dir, const std::vector<glm::dmat3>& turns, const std::vector<std::string>& options,
                  std::vector<Lighting>& found, std::vector<Lighting>* tuned, double k = 1.0) {
  Scene scene = builders::curved_models_on_floor();
  // The target is rendered with the bounces the solve is given (default 1).
  const auto given = std::find(options.begin(), options.end(), "--bounces");
  const std::string bounces = given != options.end() && given + 1 != options.end() ? *(given + 1) : "1";
  for (size_t s = 0; s < turns.size(); ++s) {
    const std::string name = "turn" + std::to_string(s);
    const fs::path obj = dir / (name + ".obj"), target = dir / (name + "-target.ply"), out = dir / (name + "-found.json"),
                   nudged = dir / (name + "-nudged.json"), tuned_out = dir / (name + "-tuned.json");
    write_obj(obj, scene, turns[s], k);
    write_lights(dir / (name + "-lights.json"), turns[s], false, k);
    write_lights(nudged, turns[s], true, k);
    REQUIRE(test::run_hilight({"render", obj.string(), "--lights", (dir / (name + "-lights.json")).string(), "-o", target.string(),
                               "--bounces", bounces}).exit_code == 0);
    std::vector<std::string> solve = {"solve", obj.string(), "--target", target.string(), "-o", out.string(), "--no-cache"};
    solve.insert(solve.end(), options.begin(), options.end());
    const auto r = test::run_hilight(solve);
    INFO("turn " << s << ": " << r.err);
    REQUIRE(r.exit_code == 0);
    found.push_back(read_lights_json(out));
    if (!tuned) continue;
    std::vector<std::string> tune = {"solve", obj.string(), "--target", target.string(), "-o", tuned_out.string(), "--no-cache",
                                     "--mode", "fine-tune", "--initial", nudged.string()};
    tune.insert(tune.end(), options.begin(), options.end());
    const auto t = test::run_hilight(tune);
    INFO("fine-tune, turn " << s << ": " << t.err);
    REQUIRE(t.exit_code == 0);
    tuned->push_back(read_lights_json(tuned_out));
  }
}

/// Every turn's lights, turned back, are turn 0's: positions within
/// `position_limit` of the size (the scene's scaled by k), intensities
/// within `intensity_limit`. The solve's lists may differ in order (each
/// light is matched to the nearest); fine-tune keeps its start's.
void check_same_lights(const std::string& what, const std::vector<glm::dmat3>& turns, const std::vector<Lighting>& lights,
                       bool ordered, double position_limit, double intensity_limit, double k = 1.0) {
  Scene scene = builders::curved_models_on_floor();
  scene.update_bounds();
  const double diagonal = k * scene.diagonal();
  for (size_t t = 1; t < turns.size(); ++t) {
    const glm::dmat3 back = glm::transpose(turns[t]);
    REQUIRE(lights[t].size() == lights[0].size());
    for (size_t j = 0; j < lights[0].size(); ++j) {
      size_t m = j;
      if (!ordered)
        for (size_t i = 0; i < lights[t].size(); ++i)
          if (glm::length(back * DVec3(lights[t][i].position) - DVec3(lights[0][j].position)) <
              glm::length(back * DVec3(lights[t][m].position) - DVec3(lights[0][j].position)))
            m = i;
      const Light& light = lights[t][m];
      const double off = glm::length(back * DVec3(light.position) - DVec3(lights[0][j].position)) / diagonal;
      std::cout << "rotation " << what << ", turn " << t << ", light " << j << ": position off " << off << " of the size, intensity ratio "
                << light.intensity.r / lights[0][j].intensity.r << std::endl;
      INFO(what << ", turn " << t << ", light " << j << ": position off " << off << " of the size");
      CHECK(light.type == lights[0][j].type);
      CHECK(off < position_limit);
      for (int ch = 0; ch < 3; ++ch)
        CHECK(double(light.intensity[ch]) == Approx(double(lights[0][j].intensity[ch])).epsilon(intensity_limit));
      if (light.type == LightType::Spot) {
        CHECK(glm::length(back * DVec3(light.direction) - DVec3(lights[0][j].direction)) < 10 * position_limit);
        CHECK(light.cutoff_deg == Approx(lights[0][j].cutoff_deg).epsilon(10 * position_limit));
      }
    }
  }
}

/// The identity, a seeded turn about the vertical, and seeded turns about
/// any axis: a turned floor's lamps stand outside its world box, so the
/// light space is then its own box, turned (light_bounds.cpp).
std::vector<glm::dmat3> seeded_turns(std::vector<uint64_t> any_axis) {
  std::mt19937_64 rng(1919);
  const double angle = std::uniform_real_distribution<double>(0.2, 6.0)(rng);
  std::vector<glm::dmat3> turns = {glm::dmat3(1.0), glm::dmat3(glm::dvec3(std::cos(angle), 0, -std::sin(angle)), glm::dvec3(0, 1, 0),
                                                               glm::dvec3(std::sin(angle), 0, std::cos(angle)))};
  for (uint64_t seed : any_axis) turns.push_back(random_rotation(seed));
  return turns;
}

} // namespace

TEST_CASE("rotation: real models turned about the vertical or any axis solve and fine-tune to the same lights, turned",
          "[invariance][rotation][solve][cli][real][slow]") {
  if (skip_without_models()) return;
  const std::vector<glm::dmat3> turns = seeded_turns({19, 37});
  std::vector<Lighting> found, tuned;
  solve_turned(test::output_dir("rotation_solve"), turns, {"--bounces", "0", "--samples", "1500"}, found, &tuned);
  REQUIRE(found[0].size() == 2);
  // The bare lamp comes back as a point light, not as the spot search's 89°
  // cone (wide_spots_as_points), and the spot as a spot.
  CHECK(std::count_if(found[0].begin(), found[0].end(), [](const Light& l) { return l.type == LightType::Point; }) == 1);
  CHECK(std::count_if(found[0].begin(), found[0].end(), [](const Light& l) { return l.type == LightType::Spot; }) == 1);
  REQUIRE(tuned[0].size() == 2);
  // The issue's bounds: positions within 10⁻⁴ of the size, intensities
  // within 0.1%. Measured: the solve within 2.5·10⁻⁸ of the size about
  // every axis; fine-tune within 1.4·10⁻⁵ and 7·10⁻⁵ in intensity (it
  // ended 2·10⁻⁴ apart while the crease faces' tie went by world axes;
  // turned off the vertical, the solve missed the lamps: D̄ 15%).
  check_same_lights("solve", turns, found, false, 1e-4, 1e-3);
  check_same_lights("fine-tune", turns, tuned, true, 1e-4, 1e-3);
}

TEST_CASE("rotation and scale: with the bounce, real models turned at random and scaled by 1000 solve and fine-tune to the lights that made the target",
          "[invariance][rotation][scale][solve][bounce][cli][real][slow]") {
  if (skip_without_models()) return;
  // The defaults (bounce, samples), on a seeded random turn, in millimetres
  // as a metre model exported in them would be (decimals: each coordinate
  // rounded, one-ulp differences; test_scale_invariance.cpp scales by powers
  // of two, exactly). Each solve is held to the lamps themselves, turned and
  // scaled: a stronger check than against the upright solve, at half the
  // cost. The issue's bounds: positions within 10⁻⁴ of the size,
  // intensities within 0.1%. Measured over seven random turns in metres:
  // the solve within 1.6·10⁻⁵ of the size of the lamps, fine-tune from 6–9
  // cm off the same, intensities within 0.01%; upright at ×1000 and ×0.001
  // 1.4·10⁻⁵, as at ×1; this turn at ×1000: 1.5·10⁻⁵, fine-tune 1.6·10⁻⁵
  // (1.3·10⁻⁵ and 2.3·10⁻⁵ since the settling's simplex takes two lights at
  // most, in 0.7 of the time).
  // Before the settling left the bounce's spikes out
  // (spot_proposals.cpp), the rounds stopped where a few samples' spikes
  // balanced the direct light: up to 1.2·10⁻⁴ (fine-tune 1.7·10⁻⁴); before
  // the settling itself, the spot 10 cm low upright (D̄ 2.9%), fine-tune
  // 7·10⁻³ of the size apart.
  const glm::dmat3 turn = random_rotation(19);
  const double k = 1000.0;
  std::vector<Lighting> found, tuned;
  const fs::path dir = test::output_dir("rotation_solve_bounce");
  solve_turned(dir, {turn}, {}, found, &tuned, k);
  const Lighting truth = read_lights_json(dir / "turn0-lights.json");
  const std::vector<glm::dmat3> same = {glm::dmat3(1.0), glm::dmat3(1.0)};  // both in the turned, scaled frame
  REQUIRE(found[0].size() == 2);
  check_same_lights("solve with the bounce (against the lamps)", same, {truth, found[0]}, false, 1e-4, 1e-3, k);
  REQUIRE(tuned[0].size() == 2);
  check_same_lights("fine-tune with the bounce (against the lamps)", same, {truth, tuned[0]}, true, 1e-4, 1e-3, k);
}
