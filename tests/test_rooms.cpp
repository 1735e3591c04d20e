// Rooms with names and the building default (issue 34 §5, §7): the FZK
// house's IfcSpaces (assimp-testmodels) are rooms `--place region:NAME`
// takes and `hilight info` lists, on their storeys; a name no room has is
// one line and exit 2 with nothing written; in a building (an IFC with
// storeys, a closed interior) lights hang from the ceiling unless
// `--place anywhere` says otherwise; an open scene keeps free placement.
#include "hilight/io/scene_io.hpp"
#include "hilight/light_space.hpp"
#include "hilight/regions.hpp"
#include "hilight/room_split.hpp"
#include "hilight/fixtures/built_scenes.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "support.hpp"

#ifdef HILIGHT_HAVE_IFCPP
#include "../frontends/common/ifc_spaces.hpp"
#endif

#include <catch2/catch.hpp>
#include <sstream>
#include <fstream>
#include <set>
#include <nlohmann/json.hpp>

using namespace hilight;
namespace fs = std::filesystem;

namespace {

fs::path fzk_house() { return builders::testmodels_dir() / "IFC/AC14-FZK-Haus.ifc"; }

/// `scene` as an OBJ the CLI reads (positions and triangles, one grey).
void write_obj(const fs::path& path, const Scene& scene) {
  std::ofstream obj(path);
  for (const auto& p : scene.positions) obj << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
  for (const auto& t : scene.triangles) obj << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

nlohmann::json lights_of(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in).at("lights");
}

/// The lines of `text` that start with "hilight: " and hold `part`.
size_t lines_with(const std::string& text, const std::string& part) {
  size_t count = 0, at = 0;
  while (at < text.size()) {
    const size_t end = std::min(text.find('\n', at), text.size());
    if (text.compare(at, 9, "hilight: ") == 0 && text.substr(at, end - at).find(part) != std::string::npos) ++count;
    at = end + 1;
  }
  return count;
}

/// Renders `lights` (a lights file's JSON) on `scene` into `dir`/target.ply, direct light.
fs::path render_target(const fs::path& dir, const fs::path& scene, const std::string& lights) {
  test::write_text(dir / "truth.json", lights);
  const auto r = test::run_hilight({"render", scene.string(), "--lights", (dir / "truth.json").string(), "-o", (dir / "target.ply").string(),
                                    "--bounces", "0"});
  REQUIRE(r.exit_code == 0);
  return dir / "target.ply";
}

} // namespace

#ifdef HILIGHT_HAVE_IFCPP
TEST_CASE("rooms: the FZK house's IfcSpaces are named rooms on their storeys, and region:NAME keeps lights in them", "[rooms][real]") {
  const Scene house = load_scene(fzk_house());
  const cli::IfcRooms ifc = cli::read_ifc_rooms(fzk_house(), house);
  REQUIRE(ifc.storeys == std::vector<std::string>{"0. Erdgeschoss", "1. Dachgeschoss"});
  REQUIRE(ifc.rooms.size() == 7);  // the Galerie's body is clipped by the roof: its extrusion is its outline
  std::map<std::string, const NamedRoom*> by_name;
  for (const auto& r : ifc.rooms) by_name[r.name] = &r;
  for (const char* name : {"Wohnen", "Schlafzimmer", "Flur", "Bad", "Buero", "K\xc3\xbc" "che", "Galerie"}) CHECK(by_name.count(name) == 1);
  const NamedRoom& living = *by_name.at("Wohnen");
  CHECK(living.number == "5");
  CHECK(living.storey == "0. Erdgeschoss");
  CHECK(by_name.at("Galerie")->storey == "1. Dachgeschoss");
  CHECK(by_name.at("Galerie")->y0 > living.y1);  // upstairs
  // The outline is the room's: its centre inside, the bedroom's centre and a point beyond its wall outside.
  const Vec3 centre = living.box.center();
  CHECK(living.contains(centre));
  CHECK_FALSE(living.contains(by_name.at("Schlafzimmer")->box.center()));
  CHECK_FALSE(living.contains(Vec3(living.box.hi.x + 0.5f, centre.y, centre.z)));
  // Rooms are told apart within a storey: the living room and the bedroom share no point.
  CHECK_FALSE(by_name.at("Schlafzimmer")->contains(centre));

  // region:NAME (a room, its number, a storey; exact, then ignoring case), not-region:NAME.
  const RayScene rays(house);
  PlacementRules rules;
  rules.add("region:wohnen");
  rules.resolve_room_names(ifc.rooms);
  REQUIRE(rules.rooms.size() == 1);
  const LightSpace space(rays, rules);
  CHECK(space.admissible(Vec3(centre.x, 1.5f, centre.z)));
  const Vec3 bedroom = by_name.at("Schlafzimmer")->box.center();
  CHECK_FALSE(space.admissible(Vec3(bedroom.x, 1.5f, bedroom.z)));
  CHECK(space.bounds().hi.x <= living.box.hi.x + 1e-4f);  // candidates spread over the room only
  PlacementRules storey;
  storey.add("region:0. Erdgeschoss");  // a name that starts with a digit is still a name
  storey.add("not-region:Wohnen");
  storey.add("not-region:5");  // a number is still the numbered region (hilight info's), not the IfcSpace '5'
  CHECK(storey.not_regions == std::vector<int>{5});
  storey.resolve_room_names(ifc.rooms);
  CHECK(storey.rooms.size() == 6);
  REQUIRE(storey.not_rooms.size() == 1);
  storey.not_regions.clear();
  const LightSpace downstairs(rays, storey);
  CHECK(downstairs.admissible(Vec3(bedroom.x, 1.5f, bedroom.z)));
  CHECK_FALSE(downstairs.admissible(Vec3(centre.x, 1.5f, centre.z)));
  const Vec3 gallery = by_name.at("Galerie")->box.center();
  CHECK_FALSE(downstairs.admissible(Vec3(gallery.x, by_name.at("Galerie")->y0 + 1.f, gallery.z)));

  PlacementRules unknown;
  unknown.add("region:Keller");
  CHECK_THROWS_WITH(unknown.resolve_room_names(ifc.rooms), Catch::Contains("region:Keller") && Catch::Contains("Wohnen"));
  PlacementRules unresolved;
  unresolved.add("region:Wohnen");
  CHECK_THROWS_WITH(LightSpace(rays, unresolved), Catch::Contains("region:Wohnen"));  // never silently everywhere
}
#endif

TEST_CASE("rooms: hilight info lists the FZK house's rooms and storeys, and says which regions are outside", "[rooms][real]") {
  const auto r = test::run_hilight({"info", fzk_house().string()});
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("building   an IFC building with storeys: lights on the ceiling by default") != std::string::npos);
  CHECK(r.out.find("'0. Erdgeschoss' '1. Dachgeschoss'") != std::string::npos);
  CHECK(r.out.find("(outside the building: not a room)") != std::string::npos);  // the terrain's side
  if (r.out.find("rooms      7 named") == std::string::npos) {
    WARN("no named rooms: this build has no IfcPlusPlus");
    return;
  }
  for (const char* line : {"  Wohnen         5    0. Erdgeschoss", "  Galerie        7    1. Dachgeschoss", "  Flur           6"}) {
    INFO(line);
    CHECK(r.out.find(line) != std::string::npos);
  }
  const auto j = test::run_hilight({"info", fzk_house().string(), "--json"});
  REQUIRE(j.exit_code == 0);
  const auto info = nlohmann::json::parse(j.out);
  CHECK(info.at("rooms").size() == 7);
  CHECK(info.at("storeys").size() == 2);
  CHECK(info.at("building") == "an IFC building with storeys");
}

TEST_CASE("rooms: a region name the scene lacks is one line naming it, exit 2, nothing written", "[rooms][real][bad-input]") {
  const fs::path dir = test::output_dir("rooms_unknown_name");
  const fs::path target = render_target(dir, fzk_house(), R"({"lights":[{"type":"point","position":[7.5,2.3,-2.0],"intensity":[30,30,30]}]})");
  for (const std::string rule : {"region:Keller", "not-region:Dachboden"}) {
    INFO(rule);
    const fs::path out = dir / "lights.json", report = dir / "report.json";
    const auto r = test::run_hilight({"solve", fzk_house().string(), "--target", target.string(), "--place", rule, "-o", out.string(),
                                      "--report", report.string()});
    CHECK(r.exit_code == 2);
    CHECK(lines_with(r.err, rule.substr(rule.find(':') + 1)) == 1);
    CHECK(r.err.find("--place " + rule) != std::string::npos);
    CHECK_FALSE(fs::exists(out));
    CHECK_FALSE(fs::exists(report));
  }
}

TEST_CASE("rooms: region:K of a region that is not a room of the building (outside it, the void under its slab) is refused, in a solve and for criteria", "[rooms][real][bad-input]") {
  // Which regions are not rooms, as hilight info marks them.
  const auto info = test::run_hilight({"info", fzk_house().string()});
  REQUIRE(info.exit_code == 0);
  std::vector<int> not_rooms, rooms;
  std::istringstream lines(info.out);
  bool in_regions = false;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("regions", 0) == 0) in_regions = true;
    else if (in_regions && line.rfind("  ", 0) == 0 && line.find('[') != std::string::npos)
      (line.find("not a room") != std::string::npos ? not_rooms : rooms).push_back(std::stoi(line));
  }
  REQUIRE_FALSE(not_rooms.empty());
  REQUIRE_FALSE(rooms.empty());
  const fs::path dir = test::output_dir("rooms_not_a_room");
  const fs::path out = dir / "lights.json", missing_target = dir / "no-target.ply";
  for (int k : not_rooms) {
    const std::string rule = "region:" + std::to_string(k);
    INFO(rule);
    const auto r = test::run_hilight({"solve", fzk_house().string(), "--target", missing_target.string(), "--place", rule, "-o", out.string()});
    CHECK(r.exit_code == 2);
    CHECK(test::line_count(r.err) == 1);
    CHECK(r.err.find("--place " + rule + ": region " + std::to_string(k) + " is not a room") != std::string::npos);
    CHECK_FALSE(fs::exists(out));
    // Nor are criteria laid out there.
    const fs::path criteria = dir / "criteria.json";
    const auto t = test::run_hilight({"target", "workplane", fzk_house().string(), "--region", std::to_string(k), "-o", criteria.string()});
    CHECK(t.exit_code == 2);
    CHECK(test::line_count(t.err) == 1);
    CHECK(t.err.find("--region " + std::to_string(k) + ": region " + std::to_string(k) + " is not a room") != std::string::npos);
    CHECK_FALSE(fs::exists(criteria));
  }
  // A room's number passes (the solve goes on to the target, missing here), and excluding an outside region is allowed.
  for (const std::string rule : {"region:" + std::to_string(rooms.front()), "not-region:" + std::to_string(not_rooms.front())}) {
    INFO(rule);
    const auto r = test::run_hilight({"solve", fzk_house().string(), "--target", missing_target.string(), "--place", rule, "-o", out.string()});
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(missing_target.filename().string()) != std::string::npos);
    CHECK(r.err.find("is not a room") == std::string::npos);
  }
}

#ifdef HILIGHT_HAVE_IFCPP
TEST_CASE("rooms: in the FZK house a solve with region:Wohnen hangs its light from the living room's ceiling", "[rooms][real][solve]") {
  test::CliOwnPlacement own;  // the building default under test
  const fs::path dir = test::output_dir("rooms_fzk_living");
  // A ceiling lamp in the living room and one in the office: only the first may be found.
  const fs::path target = render_target(dir, fzk_house(),
                                        R"({"lights":[{"type":"point","position":[7.5,2.3,-2.0],"intensity":[30,30,30]},)"
                                        R"({"type":"point","position":[2.0,2.3,-8.0],"intensity":[20,20,20]}]})");
  const auto r = test::run_hilight({"solve", fzk_house().string(), "--target", target.string(), "--place", "region:Wohnen", "--bounces", "0",
                                    "--samples", "3000", "-o", (dir / "lights.json").string()});
  REQUIRE(r.exit_code == 0);
  CHECK(lines_with(r.err, "lights on the ceiling (an IFC building with storeys; --place anywhere lifts it)") == 1);
  const Scene house = load_scene(fzk_house());
  const auto rooms = cli::read_ifc_rooms(fzk_house(), house).rooms;
  const NamedRoom& living = *rooms_named(rooms, "Wohnen").front();
  const auto lights = lights_of(dir / "lights.json");
  REQUIRE_FALSE(lights.empty());
  bool found = false;
  for (const auto& l : lights) {
    const Vec3 p(l["position"][0].get<float>(), l["position"][1].get<float>(), l["position"][2].get<float>());
    INFO(p.x << ", " << p.y << ", " << p.z);
    CHECK(living.contains(p));
    CHECK(p.y == Approx(2.3f).margin(0.01f));  // 0.2 under the living room's ceiling (2.5 m)
    found |= glm::length(p - Vec3(7.5f, 2.3f, -2.f)) < 0.1f;  // the office lamp's light through the doors pulls it a little
  }
  CHECK(found);
}
#endif

TEST_CASE("rooms: a closed interior hangs lights from the ceiling by default, and with --place anywhere and in open scenes they keep free placement",
          "[rooms][placement][solve]") {
  test::CliOwnPlacement own;  // the building default under test
  const fs::path dir = test::output_dir("rooms_interior_default");
  write_obj(dir / "room.obj", finish_scene(builders::box_room(Vec3(4.f, 3.f, 3.f)), {}));
  // A lamp at 1.6 m, well under the 3 m ceiling: what the default cannot reach and anywhere can.
  const fs::path target = render_target(dir, dir / "room.obj", R"({"lights":[{"type":"point","position":[1.5,1.6,1.2],"intensity":[3,3,3]}]})");
  const auto ceiling = test::run_hilight({"solve", (dir / "room.obj").string(), "--target", target.string(), "--bounces", "0", "--lights", "1",
                                          "-o", (dir / "ceiling.json").string()});
  REQUIRE(ceiling.exit_code == 0);
  CHECK(lines_with(ceiling.err, "lights on the ceiling (an interior, closed on every side; --place anywhere lifts it)") == 1);
  for (const auto& l : lights_of(dir / "ceiling.json")) CHECK(l["position"][1].get<double>() == Approx(2.8).margin(1e-3));
  CHECK(lines_with(ceiling.err, "poor fit") == 1);  // the lamp hangs lower than the default allows...
  CHECK(lines_with(ceiling.err, "held on the ceiling (a building's default): if the target's lamps hang lower, --place anywhere frees them") == 1);
  const auto anywhere = test::run_hilight({"solve", (dir / "room.obj").string(), "--target", target.string(), "--bounces", "0", "--lights", "1",
                                           "--place", "anywhere", "-o", (dir / "anywhere.json").string()});
  REQUIRE(anywhere.exit_code == 0);
  CHECK(lines_with(anywhere.err, "lights on the ceiling") == 0);
  CHECK(lines_with(anywhere.err, "poor fit") == 0);
  const auto free = lights_of(dir / "anywhere.json");
  REQUIRE(free.size() == 1);
  CHECK(free[0]["position"][1].get<double>() == Approx(1.6).margin(0.02));
  // A height rule says where: no default either.
  const auto low = test::run_hilight({"solve", (dir / "room.obj").string(), "--target", target.string(), "--bounces", "0", "--lights", "1",
                                      "--place", "height:1:2", "-o", (dir / "low.json").string()});
  REQUIRE(low.exit_code == 0);
  CHECK(lines_with(low.err, "lights on the ceiling") == 0);

  // An open scene (a floor with a block on it, a product): free placement, no note.
  Scene product = builders::plane(2.f);
  builders::add_box(product, Vec3(-0.3f, 0.f, -0.3f), Vec3(0.3f, 0.6f, 0.3f), Rgb(0.8f), false, "block");
  write_obj(dir / "product.obj", finish_scene(std::move(product), {}));
  const fs::path lit = render_target(dir, dir / "product.obj", R"({"lights":[{"type":"point","position":[0.8,1.2,0.4],"intensity":[2,2,2]}]})");
  const auto open = test::run_hilight({"solve", (dir / "product.obj").string(), "--target", lit.string(), "--bounces", "0", "--lights", "1",
                                       "-o", (dir / "product.json").string()});
  REQUIRE(open.exit_code == 0);
  CHECK(lines_with(open.err, "lights on the ceiling") == 0);
  const auto product_lights = lights_of(dir / "product.json");
  REQUIRE(product_lights.size() == 1);
  CHECK(product_lights[0]["position"][1].get<double>() == Approx(1.2).margin(0.02));
}

namespace {

/// A 6 x 3 x 4 room split at x = 3 by a wall 0.2 thick; `door`: a 0.9 m wide, 2.1 m high opening in it.
Scene two_rooms(bool door) {
  Scene s = builders::box_room(Vec3(6.f, 3.f, 4.f));
  if (door) {
    builders::add_box(s, Vec3(2.9f, 0.f, 0.f), Vec3(3.1f, 3.f, 1.55f), Rgb(0.8f), false, "wall");
    builders::add_box(s, Vec3(2.9f, 0.f, 2.45f), Vec3(3.1f, 3.f, 4.f), Rgb(0.8f), false, "wall");
    builders::add_box(s, Vec3(2.9f, 2.1f, 1.55f), Vec3(3.1f, 3.f, 2.45f), Rgb(0.8f), false, "lintel");
  } else {
    builders::add_box(s, Vec3(2.9f, 0.f, 0.f), Vec3(3.1f, 3.f, 4.f), Rgb(0.8f), false, "wall");
  }
  return finish_scene(std::move(s), {});
}

} // namespace

TEST_CASE("rooms: free space splits at doors into rooms numbered by place, and an open scene has none", "[rooms][regions]") {
  for (bool door : {true, false}) {
    INFO((door ? "a door" : "a closed wall"));
    const Scene scene = two_rooms(door);
    const RayScene rays(scene);
    const RoomSplit split(rays);
    REQUIRE(split.list().size() == 2);
    CHECK(split.at(Vec3(1.5f, 1.5f, 2.f)) == 1);  // numbered along x
    CHECK(split.at(Vec3(4.5f, 1.5f, 2.f)) == 2);
    CHECK(split.at(Vec3(2.8f, 1.f, 2.f)) == 1);   // the doorway's near half
    CHECK(split.at(Vec3(3.2f, 1.f, 2.f)) == 2);
    CHECK(split.list()[0].volume == Approx(split.list()[1].volume).epsilon(0.1));
    CHECK(Regions(rays).list().size() == (door ? 1u : 2u));  // the regions join what the door opens
  }
  Scene product = builders::plane(2.f);
  builders::add_box(product, Vec3(-0.3f, 0.f, -0.3f), Vec3(0.3f, 0.6f, 0.3f), Rgb(0.8f), false, "block");
  const Scene open = finish_scene(std::move(product), {});
  const RayScene open_rays(open);
  CHECK(RoomSplit(open_rays).list().empty());  // all of its air reaches the sides: no room
}

TEST_CASE("rooms: the furnished home splits at its doorways into its rooms, numbered by place", "[rooms][real]") {
  // The FZK house's ground floor with its inner doors' leaves taken out: one region. Its kitchen, living
  // room and hall are one open space (their IfcSpaces abut with no wall between), the office, bath and
  // bedroom are behind doorways: four rooms, numbered along x (office, bath, the open space, bedroom).
  const builders::BuiltScene home = builders::furnished_home();
  const Scene scene = finish_scene(home.scene, {builders::kHomeTestEdge});
  const RayScene rays(scene);
  const RoomSplit split(rays);
  CHECK(Regions(rays).list().size() >= 1);
  CHECK(Regions(rays).at(Vec3(2.05f, 1.5f, -7.85f)) == Regions(rays).at(Vec3(10.f, 1.5f, -2.15f)));  // joined by doorways
  REQUIRE(split.list().size() == 4);
  REQUIRE(home.zones.size() == 6);
  std::vector<int> rooms;
  for (const Bounds& zone : home.zones) rooms.push_back(split.at(Vec3(zone.center().x, 1.5f, zone.center().z)));
  // Zones: kitchen, living room, hall, office, bath, bedroom.
  CHECK(rooms == std::vector<int>{3, 3, 3, 1, 2, 4});
  CHECK(split.at(Vec3(6.f, 1.5f, -20.f)) == 0);  // outside the flat
}

TEST_CASE("rooms: region:room2 keeps a solve's lights in the second room of a scene split at its door", "[rooms][placement][solve]") {
  test::CliOwnPlacement own;  // the building default applies too: the lamps are on the ceiling
  const fs::path dir = test::output_dir("rooms_split_place");
  write_obj(dir / "rooms.obj", two_rooms(true));
  const auto info = test::run_hilight({"info", (dir / "rooms.obj").string()});
  REQUIRE(info.exit_code == 0);
  CHECK(info.out.find("rooms      2 (free space split at doors; --place region:room1 ...)") != std::string::npos);
  CHECK(info.out.find("regions    1 ") != std::string::npos);
  const fs::path target = render_target(dir, dir / "rooms.obj",
                                        R"({"lights":[{"type":"point","position":[1.4,2.8,1.8],"intensity":[2,2,2]},)"
                                        R"({"type":"point","position":[4.4,2.8,2.3],"intensity":[1.5,1.5,1.5]}]})");
  const auto r = test::run_hilight({"solve", (dir / "rooms.obj").string(), "--target", target.string(), "--bounces", "0", "--place", "region:room2",
                                    "-o", (dir / "lights.json").string()});
  REQUIRE(r.exit_code == 0);
  CHECK(lines_with(r.err, "lights on the ceiling (an interior, closed on every side") == 1);
  const auto lights = lights_of(dir / "lights.json");
  REQUIRE_FALSE(lights.empty());
  bool found = false;
  for (const auto& l : lights) {
    const Vec3 p(l["position"][0].get<float>(), l["position"][1].get<float>(), l["position"][2].get<float>());
    CHECK(p.x > 3.1f);  // beyond the dividing wall
    found |= glm::length(p - Vec3(4.4f, 2.8f, 2.3f)) < 0.05f;
  }
  CHECK(found);
  const auto bad = test::run_hilight({"solve", (dir / "rooms.obj").string(), "--target", target.string(), "--place", "region:room3", "-o",
                                      (dir / "none.json").string()});
  CHECK(bad.exit_code == 2);
  CHECK(lines_with(bad.err, "region:room3: no room or storey is named room3 (the scene's rooms: room1, room2)") == 1);
  CHECK_FALSE(fs::exists(dir / "none.json"));
}

#ifdef HILIGHT_HAVE_IFCPP
TEST_CASE("rooms: hilight target workplane --region Wohnen lays the grid in the living room only", "[rooms][real][criteria]") {
  const fs::path dir = test::output_dir("rooms_workplane_named");
  const auto r = test::run_hilight({"target", "workplane", fzk_house().string(), "--region", "Wohnen", "--lux", "500", "-o",
                                    (dir / "wohnen.json").string()});
  REQUIRE(r.exit_code == 0);
  std::ifstream in(dir / "wohnen.json");
  const auto criteria = nlohmann::json::parse(in);
  const Scene house = load_scene(fzk_house());
  const auto rooms = cli::read_ifc_rooms(fzk_house(), house).rooms;
  const NamedRoom& living = *rooms_named(rooms, "Wohnen").front();
  const auto& points = criteria.at("grids").at(0).at("points");
  CHECK(points.size() >= 20);  // 7.9 x 3.7 m less a 0.5 m band, at EN 12464-1's spacing
  for (const auto& p : points) CHECK(living.contains(Vec3(p[0].get<float>(), p[1].get<float>(), p[2].get<float>())));
  const auto bad = test::run_hilight({"target", "workplane", fzk_house().string(), "--region", "Keller", "-o", (dir / "keller.json").string()});
  CHECK(bad.exit_code == 2);
  CHECK(lines_with(bad.err, "--region Keller: no room or storey is named Keller") == 1);
  CHECK_FALSE(fs::exists(dir / "keller.json"));
}
#endif
