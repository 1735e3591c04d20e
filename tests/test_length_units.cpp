// Known units (issue 19 §2): a scene file has a length unit (--unit for
// formats that do not say; glTF metres; IFC as its unit assignment says, which
// assimp applies); hilight computes in metres, so the same room in
// millimetres renders the same light, `info` says the unit and the size in
// metres, and an implausible size is said once.
#include "hilight/io/lights_json.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

using namespace hilight;
namespace fs = std::filesystem;

namespace {

const std::string kRoom = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
const std::string kLights = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room-4lights.json";

/// The bundled room and its lights in millimetres (every coordinate × 1000).
void write_room_in_mm(const fs::path& dir) {
  std::ifstream in(kRoom);
  std::ofstream out(dir / "room_mm.obj");
  out << std::setprecision(17);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("v ", 0) == 0) {
      std::istringstream v(line.substr(2));
      double x, y, z;
      v >> x >> y >> z;
      out << "v " << x * 1000 << ' ' << y * 1000 << ' ' << z * 1000 << "\n";
    } else {
      out << line << "\n";
    }
  }
  fs::copy_file(std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.mtl", dir / "room.mtl", fs::copy_options::overwrite_existing);
  nlohmann::json lights = nlohmann::json::parse(test::read_file(kLights));
  for (auto& l : lights["lights"])
    for (auto& c : l["position"]) c = c.get<double>() * 1000;
  std::ofstream(dir / "lights_mm.json") << lights.dump();
}

/// A STEP real: full precision, always with a decimal point ("3000.", "1.e-05").
std::string step_real(double v) {
  std::ostringstream out;
  out << std::setprecision(17) << v;
  std::string s = out.str();
  if (s.find('.') == std::string::npos) s.insert(std::min(s.find('e'), s.size()), ".");
  return s;
}

/// "a,b,c" with every number multiplied by k.
std::string scaled_numbers(const std::string& list, double k) {
  std::string out;
  std::istringstream in(list);
  std::string item;
  for (bool first = true; std::getline(in, item, ','); first = false) out += (first ? "" : ",") + step_real(std::stod(item) * k);
  return out;
}

/// An IFC file's geometry with every length multiplied by k: the points, the
/// extrusion depths and the profiles' dimensions (all that the house's
/// geometry is made of; placements and directions are points or unitless).
std::string scale_ifc_lengths(const std::string& text, double k) {
  // The last numeric arguments of each entity carrying lengths.
  static const std::regex point(R"(IFCCARTESIANPOINT\(\(([^)]*)\)\))");
  static const std::regex depth(R"((IFCEXTRUDEDAREASOLID\([^,]*,[^,]*,[^,]*,)([^)]*)\))");
  static const std::regex rectangle(R"((IFCRECTANGLEPROFILEDEF\([^,]*,[^,]*,[^,]*,)([^)]*)\))");
  static const std::regex circle(R"((IFCCIRCLEPROFILEDEF\([^,]*,[^,]*,[^,]*,)([^)]*)\))");
  std::ostringstream out;
  std::istringstream in(text);
  std::smatch m;
  for (std::string line; std::getline(in, line);) {
    if (std::regex_search(line, m, point))
      line = m.prefix().str() + "IFCCARTESIANPOINT((" + scaled_numbers(m[1], k) + "))" + m.suffix().str();
    else
      for (const std::regex* r : {&depth, &rectangle, &circle})
        if (std::regex_search(line, m, *r)) {
          line = m.prefix().str() + m[1].str() + scaled_numbers(m[2], k) + ")" + m.suffix().str();
          break;
        }
    out << line << '\n';
  }
  return out.str();
}

} // namespace

TEST_CASE("info says a scene's unit and its size in metres, and warns of an implausible one", "[units][cli]") {
  const auto dir = test::output_dir("units_info");
  write_room_in_mm(dir);
  const auto m = test::run_hilight({"info", kRoom});
  CHECK(m.exit_code == 0);
  CHECK(m.out.find("unit       m (1 m); 8.367 m across") != std::string::npos);
  CHECK(m.err.find("warning") == std::string::npos);
  // The millimetre file read as metres: an 8 km room, said once, naming --unit.
  const auto wrong = test::run_hilight({"info", (dir / "room_mm.obj").string()});
  CHECK(wrong.exit_code == 0);
  CHECK(test::line_count(wrong.err) == 1);
  CHECK(wrong.err.find("--unit") != std::string::npos);
  const auto mm = test::run_hilight({"info", (dir / "room_mm.obj").string(), "--unit", "mm"});
  CHECK(mm.exit_code == 0);
  CHECK(mm.out.find("unit       mm (0.001 m); 8.367 m across") != std::string::npos);
  CHECK(mm.err.find("warning") == std::string::npos);
  // The metre file said to be in millimetres: 8 mm across, said.
  const auto tiny = test::run_hilight({"info", kRoom, "--unit", "mm"});
  CHECK(tiny.err.find("--unit") != std::string::npos);
  CHECK(tiny.out.find("0.008367 m across") != std::string::npos);
}

TEST_CASE("the same room in millimetres renders the same light and solves to the same lights, in millimetres", "[units][cli]") {
  const auto dir = test::output_dir("units_render");
  write_room_in_mm(dir);
  REQUIRE(test::run_hilight({"render", kRoom, "--lights", kLights, "-o", (dir / "m.ply").string()}).exit_code == 0);
  const auto r = test::run_hilight({"render", (dir / "room_mm.obj").string(), "--unit", "mm", "--lights", (dir / "lights_mm.json").string(),
                                    "-o", (dir / "mm.ply").string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto a = test::ply_colours(dir / "m.ply"), b = test::ply_colours(dir / "mm.ply");
  REQUIRE(a.size() == b.size());
  CHECK(test::dbar(b, a) <= 1e-6);
  // Solved from its own render: the lights come back in millimetres, and the file says so.
  const auto s = test::run_hilight({"solve", (dir / "room_mm.obj").string(), "--unit", "mm", "--target", (dir / "mm.ply").string(), "-o",
                                    (dir / "found.json").string(), "--no-cache"});
  INFO(s.err);
  REQUIRE(s.exit_code == 0);
  const auto found = nlohmann::json::parse(test::read_file(dir / "found.json"));
  CHECK(found["length_unit"] == "mm");
  const Lighting lights = read_lights_json(dir / "found.json"), truth = read_lights_json(dir / "lights_mm.json");
  REQUIRE(lights.size() == truth.size());
  for (const auto& t : truth) {
    float nearest = 1e30f;
    for (const auto& l : lights) nearest = std::min(nearest, glm::length(l.position - t.position));
    CHECK(nearest < 50.f);  // 5 cm, in millimetres
  }
}

TEST_CASE("IFC says its unit (assimp applies it), and IFC refuses another --unit", "[units][cli][real]") {
  const fs::path house = builders::testmodels_dir() / "IFC" / "AC14-FZK-Haus.ifc";
  if (!fs::exists(house)) {
    std::cout << "SKIPPED: assimp-testmodels is not installed" << std::endl;
    return;
  }
  // The same coordinates with the length unit declared as millimetres: a thousandth of the size, in metres.
  const auto dir = test::output_dir("units_ifc");
  std::string text = test::read_file(house);
  const std::string metre = "IFCSIUNIT(*,.LENGTHUNIT.,$,.METRE.)";
  REQUIRE(text.find(metre) != std::string::npos);
  text.replace(text.find(metre), metre.size(), "IFCSIUNIT(*,.LENGTHUNIT.,.MILLI.,.METRE.)");
  test::write_text(dir / "house_mm.ifc", text);
  const auto m = test::run_hilight({"info", house.string(), "--json"});
  const auto mm = test::run_hilight({"info", (dir / "house_mm.ifc").string(), "--json"});
  REQUIRE(m.exit_code == 0);
  REQUIRE(mm.exit_code == 0);
  const double size_m = nlohmann::json::parse(m.out)["size_m"], size_mm = nlohmann::json::parse(mm.out)["size_m"];
  CHECK(size_m == Approx(24.10).epsilon(0.01));  // the smallest ball holding it (rendering-model.md)
  CHECK(size_mm == Approx(size_m / 1000).epsilon(1e-4));
  // The same geometry in millimetres, every length × 1000: the same house, in metres.
  std::string in_mm = scale_ifc_lengths(test::read_file(house), 1000.0);
  in_mm.replace(in_mm.find(metre), metre.size(), "IFCSIUNIT(*,.LENGTHUNIT.,.MILLI.,.METRE.)");
  test::write_text(dir / "house_scaled_mm.ifc", in_mm);
  const auto scaled = test::run_hilight({"info", (dir / "house_scaled_mm.ifc").string(), "--json"});
  REQUIRE(scaled.exit_code == 0);
  CHECK(double(nlohmann::json::parse(scaled.out)["size_m"]) == Approx(size_m).epsilon(1e-5));
  // The same house: the same box and the same surface area in metres. Not
  // the same triangles: assimp cuts the openings with tolerances in the
  // file's own unit and makes 35,953 triangles of the millimetre file
  // against 35,903 (measured), so vertices are not compared one to one.
  const Scene a = load_scene(house), b = load_scene(dir / "house_scaled_mm.ifc");
  CHECK(glm::length(a.bounds.lo - b.bounds.lo) <= 1e-5f * a.diagonal());
  CHECK(glm::length(a.bounds.hi - b.bounds.hi) <= 1e-5f * a.diagonal());
  const auto area = [](const Scene& s) {
    double sum = 0.0;
    for (const auto& t : s.triangles)
      sum += 0.5 * glm::length(glm::cross(DVec3(s.positions[t[1]] - s.positions[t[0]]), DVec3(s.positions[t[2]] - s.positions[t[0]])));
    return sum;
  };
  CHECK(area(b) == Approx(area(a)).epsilon(1e-3));
  const auto refused = test::run_hilight({"info", house.string(), "--unit", "mm"});
  CHECK(refused.exit_code == 2);
  CHECK(refused.err.find("does not apply") != std::string::npos);
}

TEST_CASE("a glTF written in millimetres takes --unit mm as an override, said once: the engine, not rooms", "[units][cli][real]") {
  const fs::path engine = builders::testmodels_dir() / "glTF2" / "2CylinderEngine-glTF-Binary" / "2CylinderEngine.glb";
  if (!fs::exists(engine)) {
    std::cout << "SKIPPED: assimp-testmodels is not installed" << std::endl;
    return;
  }
  const auto m = test::run_hilight({"info", engine.string(), "--json"});
  const auto mm = test::run_hilight({"info", engine.string(), "--unit", "mm", "--json"});
  REQUIRE(m.exit_code == 0);
  REQUIRE(mm.exit_code == 0);
  const auto as_metres = nlohmann::json::parse(m.out), as_millimetres = nlohmann::json::parse(mm.out);
  // Read as its specification says, a 766 m engine whose cavities are room-sized.
  CHECK(double(as_metres["size_m"]) == Approx(765.76).epsilon(1e-3));
  CHECK(as_metres["rooms"].size() >= 1);
  CHECK(m.err.find("--unit") == std::string::npos);  // nothing to say: its size is possible
  // In millimetres, as it was written: 0.77 m, no rooms, and the override said once, naming the file.
  CHECK(as_millimetres["unit"] == "mm");
  CHECK(double(as_millimetres["size_m"]) == Approx(double(as_metres["size_m"]) / 1000).epsilon(1e-5));
  CHECK(as_millimetres["rooms"].empty());
  CHECK(std::count(mm.err.begin(), mm.err.end(), '\n') == 1);
  CHECK(mm.err.find("2CylinderEngine.glb") != std::string::npos);
  CHECK(mm.err.find("glTF is in metres by its specification") != std::string::npos);
}
