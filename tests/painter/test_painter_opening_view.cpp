// The painter in a building (issue 36): it opens inside the largest lit room
// of the IFC house, and both that view and the plan view are exposed for what
// they show — neither mostly black nor mostly white; a bright room behind a
// wall does not darken the room in view. With
// HILIGHT_UPDATE_DOC_IMAGES=1 the screenshots are copied to docs/images/ for
// docs/painter.md.
#include "../random_lights.hpp"
#include "../support.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "hilight/io/image_io.hpp"
#include "hilight/io/lights_file.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/plan_view.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>

using namespace hilight;
namespace fs = std::filesystem;

namespace {

/// A screenshot a person can read: the luma (0–255) of its pixels that are
/// not nearly black has a mean and spread of a lit scene, and at most
/// `most_black` of it is nearly black (a plan's dark site around the house
/// may be; a room is not), little of it white.
void check_readable(const fs::path& png, double most_black) {
  const PngPixels image = read_png(png);
  const size_t n = size_t(image.width) * size_t(image.height);
  REQUIRE(n > 0);
  double sum = 0, sum2 = 0, lit = 0, white = 0;
  for (size_t i = 0; i < n; ++i) {
    const double y = 0.2126 * image.rgb[3 * i] + 0.7152 * image.rgb[3 * i + 1] + 0.0722 * image.rgb[3 * i + 2];
    if (y < 8) continue;
    ++lit;
    sum += y;
    sum2 += y * y;
    white += y > 250 ? 1 : 0;
  }
  const double black = 1.0 - lit / double(n);
  const double mean = lit > 0 ? sum / lit : 0, spread = lit > 0 ? std::sqrt(std::max(0.0, sum2 / lit - mean * mean)) : 0;
  INFO(png.filename().string() << ": black " << black << "; the rest: luma mean " << mean << ", spread " << spread << ", white "
                               << white / double(n));
  CHECK(black < most_black);
  CHECK(mean > 40);
  CHECK(mean < 200);
  CHECK(spread > 15);
  CHECK(white / double(n) < 0.15);
}

/// Two closed rooms side by side as an OBJ, their faces toward the inside: a
/// 6 × 3 × 5 m room and, past a 0.2 m wall at x = 6, a 3 × 3 × 5 m one.
void write_two_rooms(const fs::path& path) {
  std::ofstream out(path);
  size_t base = 0;
  for (const auto& [size, x] : {std::pair(Vec3(6.f, 3.f, 5.f), 0.f), std::pair(Vec3(3.f, 3.f, 5.f), 6.2f)}) {
    const Scene room = builders::box_room(size);
    for (const Vec3& p : room.positions) out << "v " << p.x + x << ' ' << p.y << ' ' << p.z << '\n';
    for (const auto& t : room.triangles) out << "f " << base + t[0] + 1 << ' ' << base + t[1] + 1 << ' ' << base + t[2] + 1 << '\n';
    base += room.positions.size();
  }
}

} // namespace

TEST_CASE("painter ui: a bright room behind a wall does not darken the exposure of the room in view", "[painter-ui][view]") {
  if (test::skip_without_display()) return;
  const fs::path dir = test::output_dir("painter_exposure_behind_wall");
  write_two_rooms(dir / "two-rooms.obj");
  // A dim lamp in the large room, one a thousand times brighter in the small room next door.
  write_lights_file(dir / "lights.json",
                    {Light::point(Vec3(3.f, 2.6f, 2.5f), Rgb(1.f)), Light::point(Vec3(7.7f, 2.6f, 2.5f), Rgb(1000.f))});
  // The opening view (inside the larger lit room) and one looking at the wall, the bright room behind it in the frustum.
  const nlohmann::json actions = {{{"type", "screenshot"}, {"path", (dir / "opening.png").string()}},
                                  {{"type", "camera"}, {"eye", {1.f, 1.6f, 2.5f}}, {"target", {6.f, 1.3f, 2.5f}}, {"fov", 65}},
                                  {{"type", "screenshot"}, {"path", (dir / "wall.png").string()}}};
  test::write_text(dir / "session.json", nlohmann::json{{"actions", actions}}.dump());
  const test::RunResult run = test::run_hilight({"paint", (dir / "two-rooms.obj").string(), "--lights", (dir / "lights.json").string(),
                                                 "--size", "320x240", "--set", "bounce_samples=16", "--no-cache", "--no-record", "--exit",
                                                 "--script", (dir / "session.json").string()});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  // Exposed for the bright room's walls, the large room's would be nearly black.
  check_readable(dir / "opening.png", 0.2);
  check_readable(dir / "wall.png", 0.2);
}

TEST_CASE("painter ui: the IFC house opens inside a lit room, and the opening and plan views are readable", "[painter-ui][view]") {
  if (test::skip_without_display()) return;
  const fs::path dir = test::output_dir("painter_opening_view");
  const fs::path house = builders::testmodels_dir() / "IFC/AC14-FZK-Haus.ifc";
  float ground_floor_cut = 0.f;
  {
    const auto scene = std::make_shared<const Scene>(load_scene(house));
    const auto rays = RayScene::shared(scene);
    std::mt19937_64 rng(3600);
    write_lights_file(dir / "lights.json", test::random_ceiling_lamps(*rays, rng, 4));
    ground_floor_cut = plan_sections(*scene).front().section;
  }
  // The plan of the ground floor, cut as the T key cuts it in the storey the camera stands in.
  const nlohmann::json actions = {{{"type", "screenshot"}, {"path", (dir / "opening.png").string()}},
                                  {{"type", "section"}, {"height", ground_floor_cut}},
                                  {{"type", "plan"}, {"on", true}},
                                  {{"type", "screenshot"}, {"path", (dir / "plan.png").string()}}};
  test::write_text(dir / "session.json", nlohmann::json{{"actions", actions}}.dump());
  const test::RunResult run = test::run_hilight({"paint", house.string(), "--lights", (dir / "lights.json").string(), "--size", "480x360",
                                                 "--set", "bounce_samples=16", "--no-cache", "--no-record", "--exit", "--script",
                                                 (dir / "session.json").string()});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  check_readable(dir / "opening.png", 0.2);
  check_readable(dir / "plan.png", 0.6);  // the house covers a third of the site's plan
  if (const char* update = std::getenv("HILIGHT_UPDATE_DOC_IMAGES"); update && std::string(update) == "1") {
    const fs::path images = fs::path(HILIGHT_SOURCE_DIR) / "docs/images";
    fs::create_directories(images);
    fs::copy_file(dir / "opening.png", images / "painter-house-opening.png", fs::copy_options::overwrite_existing);
    fs::copy_file(dir / "plan.png", images / "painter-house-plan.png", fs::copy_options::overwrite_existing);
  }
}
