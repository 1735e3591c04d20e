// Inside a real building (issue 20), through the launcher under a display:
// the IFC house of assimp-testmodels (`hilight info` lists its regions: 0
// outside, 1 the inside of both storeys, 3-5 closed ground-floor rooms).
// From above, its roof hides every room;
// with the cutaway the floor of a ground-floor room shows, and with a
// section 1.5 m over the upper storey's floor, that floor shows. Both are
// checked on the screenshots (the painted floor's colour at the centre
// pixel) and in the target the session wrote (nothing painted above the section).
#include "../support.hpp"
#include "../random_lights.hpp"
#include "hilight/image.hpp"
#include "hilight/io/image_io.hpp"
#include "hilight/io/lights_json.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/ray_scene.hpp"
#include "hilight/regions.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"

#include <catch2/catch.hpp>
#include <cstring>
#include <nlohmann/json.hpp>
#include <random>

namespace {

namespace fs = std::filesystem;
using namespace hilight;

fs::path house_path() { return builders::testmodels_dir() / "IFC/AC14-FZK-Haus.ifc"; }

/// The mean colour of the 5 x 5 pixels at the image's centre.
Rgb centre_colour(const Image& image) {
  Rgb sum(0.f);
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) sum += image.at(image.width / 2 + dx, image.height / 2 + dy);
  return sum / 25.f;
}

/// The floor under a room's centre (the first surface straight down from 1 m over the room's bottom).
Vec3 floor_of(const RayScene& rays, const Region& room) {
  const Vec3 c = room.box.center();
  const Hit hit = rays.intersect(Vec3(c.x, room.box.lo.y + 1.f, c.z), Vec3(0.f, -1.f, 0.f));
  REQUIRE(hit.valid());
  return rays.hit_position(hit);
}

/// Positions of a painter target PLY (binary little-endian, float x y z nx ny nz red green blue weight) and their colours.
std::vector<std::pair<Vec3, Rgb>> target_points(const fs::path& path) {
  const std::string bytes = test::read_file(path);
  const size_t header_end = bytes.find("end_header\n"), at = bytes.find("element vertex ");
  REQUIRE(header_end != std::string::npos);
  REQUIRE(at != std::string::npos);
  const size_t count = std::stoul(bytes.substr(at + 15)), start = header_end + 11, stride = 10 * sizeof(float);
  REQUIRE(bytes.size() >= start + count * stride);
  std::vector<std::pair<Vec3, Rgb>> out(count);
  for (size_t i = 0; i < count; ++i) {
    std::memcpy(&out[i].first, bytes.data() + start + i * stride, sizeof(Vec3));
    std::memcpy(&out[i].second, bytes.data() + start + i * stride + 6 * sizeof(float), sizeof(Rgb));
  }
  return out;
}

nlohmann::json vec(const Vec3& p) { return {p.x, p.y, p.z}; }

} // namespace

TEST_CASE("painter ui: in the IFC house the cutaway shows a room's floor from above and a section shows the upper storey",
          "[painter-ui][building]") {
  if (test::skip_without_display()) return;
  const fs::path dir = test::output_dir("painter_ui_building");
  const Scene house = load_scene(house_path());
  const RayScene rays(house);
  const Regions regions(rays);
  // A ground-floor room (region 3: 3.9 m x 5.3 m, docs/benchmarks.md) and the upper storey's biggest space.
  REQUIRE(regions.list().size() > 3);
  const Region& room = regions.list()[3];
  const Vec3 ground = floor_of(rays, room);
  // The house's inside (region 1) spans both storeys, joined by the stairs:
  // the upper floor is the first surface down from 0.75 m under its top.
  const Region& inside = regions.list()[1];
  const Hit attic_hit = rays.intersect(Vec3(inside.box.center().x, inside.box.hi.y - 0.75f, inside.box.center().z), Vec3(0.f, -1.f, 0.f));
  REQUIRE(attic_hit.valid());
  const Vec3 attic = rays.hit_position(attic_hit);
  REQUIRE(attic.y > ground.y + 2.f);
  const float section = attic.y + 1.5f;
  // A wall of the upper storey 1.4 m over its floor: a dab there reaches above the section.
  const Hit wall_hit = rays.intersect(attic + Vec3(0.f, 1.4f, 0.f), Vec3(1.f, 0.f, 0.f));
  REQUIRE(wall_hit.valid());
  const Vec3 wall = rays.hit_position(wall_hit);
  INFO("room floor at " << ground.y << ", upper floor at " << attic.y << ", wall at x " << wall.x);

  auto above = [](const Vec3& p) { return nlohmann::json{{"type", "camera"}, {"eye", vec(p + Vec3(0.f, 14.f, 6.f))}, {"target", vec(p)}, {"fov", 40}}; };
  auto shot = [&](const char* name) { return nlohmann::json{{"type", "screenshot"}, {"path", (dir / name).string()}}; };
  const nlohmann::json actions = {
      above(ground),
      {{"type", "cutaway"}, {"on", true}},
      {{"type", "brush"}, {"radius", 0.6}, {"colour", {0, 0, 1}}, {"brightness", 1}, {"hardness", 1}},
      {{"type", "stroke"}, {"world", {vec(ground)}}},
      {{"type", "view"}, {"show", "target"}},
      shot("cutaway.exr"),
      {{"type", "cutaway"}, {"on", false}},
      shot("closed.exr"),
      above(attic),
      {{"type", "section"}, {"height", section}},
      {{"type", "brush"}, {"colour", {0, 1, 0}}},
      {{"type", "stroke"}, {"world", {vec(attic)}}},
      {{"type", "brush"}, {"colour", {1, 0, 1}}, {"radius", 0.5}},
      {{"type", "stroke"}, {"world", {vec(wall)}}},
      shot("section.exr"),
      {{"type", "section"}, {"off", true}},
      shot("roof.exr"),
      {{"type", "save_target"}, {"path", (dir / "target.ply").string()}}};
  test::write_text(dir / "session.json", nlohmann::json{{"actions", actions}}.dump());
  const test::RunResult run = test::run_hilight({"paint", house_path().string(), "--size", "360x270", "--set", "bounce_samples=16",
                                                 "--no-cache", "--no-record", "--exit", "--script", (dir / "session.json").string()});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);

  const Rgb cut = centre_colour(read_exr(dir / "cutaway.exr")), closed = centre_colour(read_exr(dir / "closed.exr"));
  const Rgb cut_section = centre_colour(read_exr(dir / "section.exr")), roof = centre_colour(read_exr(dir / "roof.exr"));
  INFO("cutaway " << cut.r << " " << cut.g << " " << cut.b << "; closed " << closed.r << " " << closed.g << " " << closed.b);
  INFO("section " << cut_section.r << " " << cut_section.g << " " << cut_section.b << "; roof " << roof.r << " " << roof.g << " " << roof.b);
  // The room's painted (blue) floor shows through the cutaway, not under the roof.
  CHECK(cut.b > 0.5f);
  CHECK(cut.b > 3.f * std::max(cut.r, cut.g));
  CHECK_FALSE(closed.b > 3.f * std::max(closed.r, closed.g));
  // The upper storey's painted (green) floor shows under the section, not under the roof.
  CHECK(cut_section.g > 0.5f);
  CHECK(cut_section.g > 3.f * std::max(cut_section.r, cut_section.b));
  CHECK_FALSE(roof.g > 3.f * std::max(roof.r, roof.b));

  // What it wrote: the floors were painted, the wall only below the section.
  size_t blue = 0, green = 0, magenta = 0;
  float highest = -1e9f;
  for (const auto& [p, c] : target_points(dir / "target.ply")) {
    if (c.b > 0.5f && c.r < 0.1f && c.g < 0.1f) ++blue;
    if (c.g > 0.5f && c.r < 0.1f && c.b < 0.1f) ++green;
    if (c.r > 0.5f && c.b > 0.5f && c.g < 0.1f) ++magenta, highest = std::max(highest, p.y);
  }
  CHECK(blue > 0);
  CHECK(green > 0);
  REQUIRE(magenta > 0);
  CHECK(highest <= section);
  CHECK(highest > section - 0.6f);  // the dab did reach the wall's upper part, up to the section
}

TEST_CASE("painter ui: in the IFC house a room focus frames a room, the plan shows it, a walk stays in it and a focused solve lights it",
          "[painter-ui][building]") {
  if (test::skip_without_display()) return;
  const fs::path dir = test::output_dir("painter_ui_building_focus");
  const Scene house = load_scene(house_path());
  const RayScene rays(house);
  const Regions regions(rays);
  REQUIRE(regions.list().size() > 3);
  const int room = 3;  // a closed ground-floor room, 3.9 m x 5.3 m
  const Vec3 floor = floor_of(rays, regions.list()[room]);

  auto shot = [&](const char* name) { return nlohmann::json{{"type", "screenshot"}, {"path", (dir / name).string()}}; };
  auto save = [&](const char* name) { return nlohmann::json{{"type", "save_lights"}, {"path", (dir / name).string()}}; };
  const nlohmann::json actions = {
      {{"type", "brush"}, {"radius", 1.0}, {"colour", {1, 0.5, 0}}, {"brightness", 0.5}, {"hardness", 0.8}},
      {{"type", "stroke"}, {"world", {vec(floor)}}},
      {{"type", "focus"}, {"regions", {room}}},
      {{"type", "cutaway"}, {"on", true}},
      {{"type", "view"}, {"show", "target"}},
      shot("focus.exr"),
      {{"type", "plan"}, {"on", true}},
      shot("plan.exr"),
      // Painting in the plan: the window's centre pixel is the room's centre, seen from straight above.
      {{"type", "brush"}, {"radius", 0.3}, {"colour", {1, 0, 1}}, {"brightness", 1}, {"hardness", 1}},
      {{"type", "stroke"}, {"screen", {{180, 135}}}},
      {{"type", "save_target"}, {"path", (dir / "target.ply").string()}},
      {{"type", "plan"}, {"on", false}},
      // Into the room: stand at its centre, a step, look down at the floor and
      // place a spotlight from the eye; then walk into the wall and do it again.
      {{"type", "walk"}, {"on", true}},
      {{"type", "walk"}, {"move", {0.5, 0.25}}, {"turn", {0, -75}}},
      {{"type", "spot_region"}, {"world", {vec(floor)}}},
      {{"type", "walk"}, {"move", {30, 0}}},
      {{"type", "spot_region"}, {"world", {vec(floor)}}},
      save("walk.json"),
      {{"type", "walk"}, {"on", false}},
      {{"type", "undo"}},
      {{"type", "undo"}},
      {{"type", "solve"}},
      save("solved.json"),
      {{"type", "focus"}, {"regions", {room}}},  // framed again, from above
      {{"type", "view"}, {"show", "result"}},
      shot("solved.exr")};
  test::write_text(dir / "session.json", nlohmann::json{{"actions", actions}}.dump());
  const test::RunResult run = test::run_hilight({"paint", house_path().string(), "--size", "360x270", "--set", "bounce_samples=16",
                                                 "--samples", "800", "--cache-cells", "6", "--cache-dir", (dir / "cache").string(),
                                                 "--no-record", "--exit", "--script", (dir / "session.json").string()});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);

  // The focus frames the room from above and the plan shows it: the painted (orange) floor at the centre.
  for (const char* name : {"focus.exr", "plan.exr"}) {
    const Rgb c = centre_colour(read_exr(dir / name));
    INFO(name << ": " << c.r << " " << c.g << " " << c.b);
    // Orange as displayed (the exposure may clip it towards yellow), never the grey backdrop or the roof.
    CHECK(c.r > 0.4f);
    CHECK(c.g > 0.3f * c.r);
    CHECK(c.b < 0.1f * c.r);
  }
  // The plan's stroke landed on the room's floor, under the window's centre.
  size_t magenta = 0;
  const Vec3 centre = regions.list()[room].box.center();
  for (const auto& [p, c] : target_points(dir / "target.ply")) {
    if (!(c.r > 0.5f && c.b > 0.5f && c.g < 0.1f)) continue;
    ++magenta;
    INFO("magenta at " << p.x << " " << p.y << " " << p.z);
    CHECK(std::abs(p.y - floor.y) < 0.05f);
    CHECK(std::hypot(p.x - centre.x, p.z - centre.z) < 0.5f);
  }
  CHECK(magenta > 0);
  // The walk stood in the room at eye height and its walls held it: both spotlights stand at the eye, in the room.
  const Lighting walked = read_lights_json(dir / "walk.json");
  REQUIRE(walked.size() == 2);
  for (const Light& spot : walked) {
    INFO("spot at " << spot.position.x << " " << spot.position.y << " " << spot.position.z);
    CHECK(spot.type == LightType::Spot);
    CHECK(regions.at(spot.position) == room);
    CHECK(spot.position.y == Approx(floor.y + 1.6f).margin(0.01));
  }
  CHECK(glm::length(walked[1].position - walked[0].position) > 0.5f);  // it did walk, to the wall
  // The focused solve put its lights in the room, and they light its floor.
  const Lighting solved = read_lights_json(dir / "solved.json");
  REQUIRE(!solved.empty());
  for (const Light& light : solved) {
    INFO("light at " << light.position.x << " " << light.position.y << " " << light.position.z);
    CHECK(regions.at(light.position) == room);
  }
  const Rgb lit = centre_colour(read_exr(dir / "solved.exr"));
  INFO("solved view centre " << lit.r << " " << lit.g << " " << lit.b);
  CHECK(lit.r + lit.g + lit.b > 0.3f);
}

TEST_CASE("painter ui: a section height that is not a number is one error line naming the script", "[painter-ui][building][bad-input]") {
  const fs::path dir = test::output_dir("painter_ui_building_bad");
  test::write_text(dir / "bad.json", R"({"actions": [{"type": "section", "height": "1.5 m"}]})");
  const std::string room = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
  const test::RunResult run = test::run_hilight({"paint", room, "--no-record", "--exit", "--script", (dir / "bad.json").string()});
  CHECK(run.exit_code == 2);
  CHECK(test::line_count(run.err) == 1);
  CHECK_THAT(run.err, Catch::Contains("bad.json: action 0: section: 'height' must be a number"));
}

TEST_CASE("painter ui: the plan of the IFC house's ground floor shows one marker per light", "[painter-ui][building][plan]") {
  if (test::skip_without_display()) return;
  const fs::path dir = test::output_dir("painter_ui_building_plan_markers");
  auto house = std::make_shared<const Scene>(load_scene(house_path()));
  const auto rays = RayScene::shared(house);
  // Seeded lamps under the ceilings, those of the ground floor (below the
  // section) at least 0.6 m apart, so that no two markers touch; red, so
  // that their markers are the only red in the target view.
  std::mt19937_64 rng(2020);
  Lighting lamps;
  for (Light lamp : test::random_ceiling_lamps(*rays, rng, 16)) {
    if (lamp.position.y > 2.5f) continue;
    bool apart = true;
    for (const Light& other : lamps) apart = apart && glm::length(other.position - lamp.position) > 0.6f;
    if (!apart) continue;
    lamp.intensity = Rgb(4.f, 0.2f, 0.2f);
    lamps.push_back(lamp);
  }
  REQUIRE(lamps.size() >= 3);
  write_lights_json(dir / "lamps.json", lamps);
  const nlohmann::json actions = {{{"type", "load_lights"}, {"path", (dir / "lamps.json").string()}},
                                  {{"type", "section"}, {"height", 2.5}},
                                  {{"type", "plan"}, {"on", true}},
                                  {{"type", "view"}, {"show", "target"}},
                                  {{"type", "screenshot"}, {"path", (dir / "plan.exr").string()}}};
  test::write_text(dir / "session.json", nlohmann::json{{"actions", actions}}.dump());
  const test::RunResult run = test::run_hilight({"paint", house_path().string(), "--size", "480x360", "--set", "bounce_samples=16",
                                                 "--cache-cells", "6", "--cache-dir", (dir / "cache").string(), "--no-record", "--exit",
                                                 "--script", (dir / "session.json").string()});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  // Connected patches of marker red.
  const Image plan = read_exr(dir / "plan.exr");
  auto red = [&](int x, int y) {
    const Rgb& c = plan.at(x, y);
    return c.r > 0.5f && c.g < 0.6f * c.r && c.b < 0.6f * c.r;
  };
  std::vector<uint8_t> seen(plan.pixels.size(), 0);
  size_t markers = 0;
  for (int y = 0; y < plan.height; ++y)
    for (int x = 0; x < plan.width; ++x) {
      if (seen[size_t(y) * plan.width + x] || !red(x, y)) continue;
      ++markers;
      std::vector<std::pair<int, int>> stack{{x, y}};
      seen[size_t(y) * plan.width + x] = 1;
      while (!stack.empty()) {
        const auto [px, py] = stack.back();
        stack.pop_back();
        for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
          const int qx = px + dx, qy = py + dy;
          if (qx < 0 || qy < 0 || qx >= plan.width || qy >= plan.height) continue;
          if (seen[size_t(qy) * plan.width + qx] || !red(qx, qy)) continue;
          seen[size_t(qy) * plan.width + qx] = 1;
          stack.push_back({qx, qy});
        }
      }
    }
  CHECK(markers == lamps.size());
}
