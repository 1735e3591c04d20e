// README's "A first hour" (issue 36 §5), walked as a designer would walk it
// on the bundled room: open it in the painter, paint the floor and walls dim
// and the table top bright (white, the lamp's colour), solve with the
// defaults (a closed room: lights 0.2 below the ceiling), look at the result;
// then the guide's `hilight solve ... -o lights.glb --report-html` on the
// saved target. Each step's window is checked for what a person would see
// (neither mostly black nor mostly white; the painted table brighter than
// the floor, in the target and in the lit result). With
// HILIGHT_UPDATE_DOC_IMAGES=1 the windows, halved to 640 x 400, are stored in
// docs/images/ for the README.
#include "../support.hpp"
#include "hilight/image.hpp"
#include "hilight/io/image_io.hpp"
#include "hilight/io/lights_json.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <regex>

namespace fs = std::filesystem;
using namespace hilight;

namespace {

constexpr int kWidth = 1280, kHeight = 800;
// The guide's view of the table (steps 2 and 3): from the room's far corner, above the bench.
const Vec3 kEye(5.6f, 2.4f, 4.7f), kLookAt(1.9f, 0.5f, 1.8f);
constexpr float kFov = 62.f;

/// Luma (0–255) of an sRGB pixel.
double luma(const PngPixels& image, int x, int y) {
  const unsigned char* p = &image.rgb[3 * (size_t(y) * size_t(image.width) + size_t(x))];
  return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

/// A window a person can read: little of it nearly black or nearly white,
/// the rest with the mean and spread of a lit picture. `dark`: a dim room
/// lit as asked (the result's floor and walls are dim by request).
void check_readable(const fs::path& png, bool dark = false) {
  const PngPixels image = read_png(png);
  REQUIRE(image.width * image.height > 0);
  double sum = 0, sum2 = 0, black = 0, white = 0;
  const double n = double(image.width) * double(image.height);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const double v = luma(image, x, y);
      sum += v;
      sum2 += v * v;
      black += v < 8 ? 1 : 0;
      white += v > 250 ? 1 : 0;
    }
  const double mean = sum / n, spread = std::sqrt(std::max(0.0, sum2 / n - mean * mean));
  INFO(png.filename().string() << ": luma mean " << mean << ", spread " << spread << ", black " << black / n << ", white " << white / n);
  CHECK(mean > (dark ? 20 : 30));
  CHECK(mean < 200);
  CHECK(spread > 15);
  CHECK(black / n < (dark ? 0.5 : 0.3));
  CHECK(white / n < 0.1);
}

/// The window pixel (x right, y down) where the guide's camera sees a world point.
std::pair<int, int> pixel_of(const Vec3& p) {
  const glm::mat4 vp = glm::perspective(glm::radians(kFov), float(kWidth) / float(kHeight), 0.01f, 100.f) *
                       glm::lookAt(kEye, kLookAt, Vec3(0.f, 1.f, 0.f));
  const glm::vec4 clip = vp * glm::vec4(p, 1.f);
  const float x = clip.x / clip.w, y = clip.y / clip.w;
  return {int(std::lround((x + 1.f) / 2.f * kWidth)), int(std::lround((1.f - y) / 2.f * kHeight))};
}

/// The mean luma of the 9 x 9 pixels where the guide's camera sees `p`.
double luma_at(const PngPixels& image, const Vec3& p) {
  const auto [cx, cy] = pixel_of(p);
  REQUIRE(cx >= 4);
  REQUIRE(cy >= 4);
  REQUIRE(cx < image.width - 4);
  REQUIRE(cy < image.height - 4);
  double sum = 0;
  for (int dy = -4; dy <= 4; ++dy)
    for (int dx = -4; dx <= 4; ++dx) sum += luma(image, cx + dx, cy + dy);
  return sum / 81.0;
}

/// `from` halved (2 x 2 pixels averaged in linear light) into `to`: small enough for the README.
void write_halved(const fs::path& from, const fs::path& to) {
  const PngPixels image = read_png(from);
  auto linear = [](unsigned char v) {
    const float e = float(v) / 255.f;
    return e <= 0.04045f ? e / 12.92f : std::pow((e + 0.055f) / 1.055f, 2.4f);
  };
  Image half(image.width / 2, image.height / 2);
  for (int y = 0; y < half.height; ++y)
    for (int x = 0; x < half.width; ++x) {
      Rgb sum(0.f);
      for (int k = 0; k < 4; ++k) {
        const unsigned char* p = &image.rgb[3 * (size_t(2 * y + k / 2) * size_t(image.width) + size_t(2 * x + k % 2))];
        sum += Rgb(linear(p[0]), linear(p[1]), linear(p[2]));
      }
      half.at(x, y) = sum / 4.f;
      half.covered[size_t(y) * size_t(half.width) + size_t(x)] = 1;
    }
  write_image(to, half, 1.f);
}

/// Points over a wall, floor or ceiling rectangle: `from` + i·`a` + j·`b`, serpentine, as a hand strokes it.
nlohmann::json sweep(const Vec3& from, const Vec3& a, int na, const Vec3& b, int nb) {
  nlohmann::json points = nlohmann::json::array();
  for (int j = 0; j < nb; ++j)
    for (int i = 0; i < na; ++i) {
      const int k = j % 2 ? na - 1 - i : i;
      const Vec3 p = from + float(k) * a + float(j) * b;
      points.push_back({p.x, p.y, p.z});
    }
  return points;
}

} // namespace

TEST_CASE("painter ui: README's first hour, walked on the bundled room, with its screenshots", "[painter-ui][guide]") {
  if (test::skip_without_display()) return;
  test::CliOwnPlacement own;  // the guide's defaults: a closed room's lights hang from the ceiling
  const fs::path dir = test::output_dir("painter_ui_first_hour");
  const std::string room = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
  const nlohmann::json camera = {{"type", "camera"}, {"eye", {kEye.x, kEye.y, kEye.z}}, {"target", {kLookAt.x, kLookAt.y, kLookAt.z}}, {"fov", kFov}};
  // Step 2: white, brightness 0.02, radius 0.5 over the floor and the four walls; 0.6 on the table top.
  const nlohmann::json actions = {
      {{"type", "screenshot"}, {"path", (dir / "1-open.png").string()}, {"panels", true}},
      camera,
      {{"type", "brush"}, {"radius", 0.5}, {"colour", 1.0}, {"brightness", 0.02}},
      {{"type", "stroke"}, {"world", sweep(Vec3(0.25f, 0.f, 0.25f), Vec3(0.5f, 0.f, 0.f), 12, Vec3(0.f, 0.f, 0.5f), 10)}},
      {{"type", "stroke"}, {"world", sweep(Vec3(0.25f, 0.4f, 0.f), Vec3(0.5f, 0.f, 0.f), 12, Vec3(0.f, 0.7f, 0.f), 4)}},
      {{"type", "stroke"}, {"world", sweep(Vec3(0.25f, 0.4f, 5.f), Vec3(0.5f, 0.f, 0.f), 12, Vec3(0.f, 0.7f, 0.f), 4)}},
      {{"type", "stroke"}, {"world", sweep(Vec3(0.f, 0.4f, 0.25f), Vec3(0.f, 0.f, 0.5f), 10, Vec3(0.f, 0.7f, 0.f), 4)}},
      {{"type", "stroke"}, {"world", sweep(Vec3(6.f, 0.4f, 0.25f), Vec3(0.f, 0.f, 0.5f), 10, Vec3(0.f, 0.7f, 0.f), 4)}},
      {{"type", "brush"}, {"brightness", 0.6}},
      {{"type", "stroke"}, {"world", sweep(Vec3(1.4f, 0.78f, 1.6f), Vec3(0.3f, 0.f, 0.f), 5, Vec3(0.f, 0.f, 0.3f), 3)}},
      {{"type", "view"}, {"show", "target"}},
      {{"type", "screenshot"}, {"path", (dir / "2-paint.png").string()}, {"panels", true}},
      {{"type", "screenshot"}, {"path", (dir / "2-paint-view.png").string()}},
      // Step 3: solve (F5), the result view (key 1).
      {{"type", "solve"}},
      {{"type", "view"}, {"show", "result"}},
      {{"type", "screenshot"}, {"path", (dir / "3-solve.png").string()}, {"panels", true}},
      {{"type", "screenshot"}, {"path", (dir / "3-solve-view.png").string()}},
      // Step 4: save.
      {{"type", "save_target"}, {"path", (dir / "my-target.ply").string()}},
      {{"type", "save_lights"}, {"path", (dir / "my-lights.json").string()}}};
  test::write_text(dir / "session.json", nlohmann::json{{"actions", actions}}.dump());
  // The painter's own settings (what the guide's reader sees), the light cache aside.
  const test::RunResult run = test::run_hilight({"paint", room, "--size", std::to_string(kWidth) + "x" + std::to_string(kHeight),
                                                 "--no-cache", "--no-record", "--exit", "--script", (dir / "session.json").string()});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  for (const char* shot : {"1-open.png", "2-paint.png", "2-paint-view.png"}) check_readable(dir / shot);
  for (const char* shot : {"3-solve.png", "3-solve-view.png"}) check_readable(dir / shot, true);

  // The solve found lights, 0.2 below the 3 m ceiling as the guide says, in the unit the file states.
  const nlohmann::json saved = nlohmann::json::parse(test::read_file(dir / "my-lights.json"));
  CHECK(saved["intensity_unit"] == "W/sr");
  const Lighting lights = read_lights_json(dir / "my-lights.json");
  REQUIRE_FALSE(lights.empty());
  for (const Light& l : lights) CHECK(l.position.y == Approx(2.8f).margin(1e-3));
  // The guide says the bright table takes spotlights (a point lamp would light the floor beside it as much).
  CHECK(std::any_of(lights.begin(), lights.end(), [](const Light& l) { return l.type == LightType::Spot; }));

  // The painted table top shows brighter than the painted floor beside it, in the target and in the lit result.
  const Vec3 table(2.0f, 0.78f, 1.9f), floor(3.6f, 0.f, 2.6f);
  for (const char* shot : {"2-paint-view.png", "3-solve-view.png"}) {
    const PngPixels image = read_png(dir / shot);
    const double on_table = luma_at(image, table), on_floor = luma_at(image, floor);
    INFO(shot << ": table luma " << on_table << ", floor luma " << on_floor);
    CHECK(on_table > 1.5 * on_floor);
  }

  // Step 5: the guide's command on the saved target: the lights as glTF and the report.
  const test::RunResult solve = test::run_hilight({"solve", room, "--target", (dir / "my-target.ply").string(), "-o",
                                                   (dir / "lights.glb").string(), "--report-html", (dir / "report.html").string(),
                                                   "--set", "bounce_samples=16", "--samples", "800", "--no-cache"});
  INFO(solve.err);
  REQUIRE(solve.exit_code == 0);
  std::smatch said;
  const std::regex summary("hilight: ([0-9]+) lights?[^,\n]*, D̄ ([0-9.]+)%");
  REQUIRE(std::regex_search(solve.err, said, summary));
  CHECK(std::stoi(said[1]) >= 1);
  CHECK(fs::file_size(dir / "lights.glb") > 1000);
  // The report the guide describes: the three views, the plan with each light's lux below it, the timings.
  const std::string report = test::read_file(dir / "report.html");
  for (const char* part : {"<h2>Target, result, difference", "<h2>Plans", " lx<", "<h2>Lights", "<h2>Timings"}) {
    INFO(part);
    CHECK(report.find(part) != std::string::npos);
  }
  CHECK(report.find("<img") != std::string::npos);
  // Spotlights won: the report says so where the light-count walk would be, not that the lights were given.
  CHECK(report.find("the lights were given") == std::string::npos);

  if (const char* update = std::getenv("HILIGHT_UPDATE_DOC_IMAGES"); update && std::string(update) == "1") {
    const fs::path images = fs::path(HILIGHT_SOURCE_DIR) / "docs/images";
    write_halved(dir / "1-open.png", images / "first-hour-open.png");
    write_halved(dir / "2-paint.png", images / "first-hour-paint.png");
    write_halved(dir / "3-solve.png", images / "first-hour-solve.png");
  }
}
