// Numbers no real input holds (issue 35): a light at 10¹⁹ (Embree aborted
// `render --bounces 1`), a target near float's limit (the lights came out
// as null and D̄ as -nan%), a luminaire at 3e38 cd. Each is refused in one
// line naming the file, exit 2, nothing written.
#include "hilight/error.hpp"
#include "hilight/io/lights_json.hpp"
#include "hilight/io/photometry_io.hpp"
#include "hilight/io/ply_reader.hpp"
#include "photometry_files.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iomanip>

namespace fs = std::filesystem;
using Catch::Matchers::Contains;

namespace {

const std::string kRoom = HILIGHT_SOURCE_DIR "/scenes/room.obj";
const std::string kRoomLights = HILIGHT_SOURCE_DIR "/scenes/room-lights.json";

void check_refused(const test::RunResult& r, const std::string& file, const std::string& mention) {
  CAPTURE(r.exit_code, r.out, r.err);
  CHECK(r.exit_code == 2);
  CHECK(test::line_count(r.err) == 1);
  CHECK_THAT(r.err, Contains(file) && Contains(mention));
}

} // namespace

TEST_CASE("render refuses a light beyond the renderers' reach, naming the file and the light", "[render][cli][bad-input]") {
  const fs::path dir = test::output_dir("light_beyond_reach");
  for (const std::string far : {"1e19", "-3e30", "2e8"}) {
    CAPTURE(far);
    const fs::path lights = dir / "far.json";
    test::write_text(lights, R"({"lights": [{"type": "point", "position": [1, 2, 1], "intensity": [1, 1, 1]},
      {"type": "point", "position": [)" + far + R"(, 1, 1], "intensity": [1, 1, 1]}]})");
    for (const std::string bounces : {"0", "1"}) {
      check_refused(test::run_hilight({"render", kRoom, "--lights", lights.string(), "-o", (dir / "out.ply").string(), "--bounces", bounces}),
                    lights.string(), "light 1");
      CHECK_FALSE(fs::exists(dir / "out.ply"));
    }
  }
  // Far, but within a million sizes of the room: rendered as before.
  test::write_text(dir / "distant.json", R"({"lights": [{"type": "point", "position": [1000, 2, 1], "intensity": [1e6, 1e6, 1e6]}]})");
  CHECK(test::run_hilight({"render", kRoom, "--lights", (dir / "distant.json").string(), "-o", (dir / "distant.ply").string(), "--bounces", "0"})
            .exit_code == 0);
}

TEST_CASE("a target near float's limit is refused in one line, and nothing is written", "[solve][target][bad-input]") {
  const fs::path dir = test::output_dir("target_near_float_limit");
  REQUIRE(test::run_hilight({"render", kRoom, "--lights", kRoomLights, "-o", (dir / "target.ply").string(), "--bounces", "0"}).exit_code == 0);
  const hilight::PlyVertices ply = hilight::read_ply_vertices(dir / "target.ply");
  // The same target with its colours scaled to near 3e38 (float's largest is 3.4e38).
  const fs::path huge = dir / "huge.ply";
  {
    std::ofstream out(huge);
    out << "ply\nformat ascii 1.0\nelement vertex " << ply.count
        << "\nproperty float x\nproperty float y\nproperty float z\nproperty float red\nproperty float green\nproperty float blue\nend_header\n"
        << std::setprecision(9);
    const auto& p = ply.properties;
    double largest = 0;
    for (size_t i = 0; i < ply.count; ++i) largest = std::max({largest, p.at("red")[i], p.at("green")[i], p.at("blue")[i]});
    const double scale = 3e38 / largest;
    for (size_t i = 0; i < ply.count; ++i)
      out << p.at("x")[i] << ' ' << p.at("y")[i] << ' ' << p.at("z")[i] << ' ' << p.at("red")[i] * scale << ' ' << p.at("green")[i] * scale
          << ' ' << p.at("blue")[i] * scale << "\n";
  }
  const auto r = test::run_hilight({"solve", kRoom, "--target", huge.string(), "-o", (dir / "lights.json").string(), "--no-cache", "--lights", "1"});
  check_refused(r, huge.string(), "above 1e12");
  CHECK_THAT(r.err, !Contains("nan"));
  CHECK_FALSE(fs::exists(dir / "lights.json"));
}

TEST_CASE("IES and EULUMDAT files beyond any luminaire's candela are refused, naming the file", "[photometry][bad-input]") {
  const auto flat = [](double value) { return [value](double, double) { return value; }; };
  CHECK(hilight::parse_ies(test::ies_text(test::angles(0, 180, 10), {0}, flat(1e6)), "floodlight.ies").peak() == Approx(1e6));
  for (const double candela : {3e38, 2e10}) {
    CAPTURE(candela);
    try {
      hilight::parse_ies(test::ies_text(test::angles(0, 180, 10), {0}, flat(candela)), "absurd.ies");
      FAIL("accepted");
    } catch (const hilight::InputError& e) {
      CHECK_THAT(std::string(e.what()), Contains("absurd.ies") && Contains("beyond any luminaire"));
    }
    // EULUMDAT is in cd per 1000 lm: its lamps' flux scales it.
    try {
      hilight::parse_ldt(test::ldt_text(1, {0}, test::angles(0, 180, 10), {std::vector<double>(19, candela)}, 1000), "absurd.ldt");
      FAIL("accepted");
    } catch (const hilight::InputError& e) {
      CHECK_THAT(std::string(e.what()), Contains("absurd.ldt") && Contains("beyond any luminaire"));
    }
  }
}

TEST_CASE("the lights writer refuses NaN and infinity rather than write null", "[lights][json]") {
  hilight::Lighting lights = {hilight::Light::point(hilight::Vec3(1.f, 2.f, 3.f), hilight::Rgb(1.f))};
  CHECK_NOTHROW(hilight::lights_to_json(lights, "m"));
  lights[0].intensity.g = std::nanf("");
  CHECK_THROWS_AS(hilight::lights_to_json(lights, "m"), std::logic_error);
  lights[0].intensity.g = 1.f;
  lights[0].position.x = INFINITY;
  CHECK_THROWS_AS(hilight::lights_to_json(lights, "m"), std::logic_error);
}
