// Pictures a person can read (issue 36): with no --camera, a building and a
// closed box are seen from inside their lit room (default_view.hpp), and the
// PNG is neither mostly black nor mostly white. In the FZK house the stair's
// opening joins the ground floor's hall and living room to the attic (one
// region, one room of the split at doors): lamps on the ground floor put the
// eye there, on that storey, not in the larger attic; with no lamp at all the
// eye stands on the ground floor too, where a person opening a house expects.
#include "hilight/default_view.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "hilight/io/image_io.hpp"
#include "hilight/io/lights_file.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/plan_view.hpp"
#include "hilight/regions.hpp"
#include "hilight/room_split.hpp"
#include "random_lights.hpp"
#include "support.hpp"

#ifdef HILIGHT_HAVE_IFCPP
#include "../frontends/common/ifc_spaces.hpp"
#endif

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <random>

using namespace hilight;
namespace fs = std::filesystem;

namespace {

const fs::path kHouse = builders::testmodels_dir() / "IFC/AC14-FZK-Haus.ifc";

/// What a person sees in a PNG: the mean and spread of its scene pixels'
/// luma (0–255), the shares that are nearly black and nearly white, and the
/// share of background (nothing there: encode_png's grey, 0.12 linear = 97).
struct Looks {
  double mean = 0, spread = 0, black = 0, white = 0, background = 0;
};

Looks looks_of(const fs::path& png) {
  const PngPixels image = read_png(png);
  const size_t n = size_t(image.width) * size_t(image.height);
  REQUIRE(n > 0);
  Looks l;
  double sum2 = 0;
  size_t scene = 0;
  for (size_t i = 0; i < n; ++i) {
    if (image.rgb[3 * i] == 97 && image.rgb[3 * i + 1] == 97 && image.rgb[3 * i + 2] == 97) {
      l.background += 1;
      continue;
    }
    ++scene;
    const double y = 0.2126 * image.rgb[3 * i] + 0.7152 * image.rgb[3 * i + 1] + 0.0722 * image.rgb[3 * i + 2];
    l.mean += y;
    sum2 += y * y;
    l.black += y < 8 ? 1 : 0;
    l.white += y > 250 ? 1 : 0;
  }
  REQUIRE(scene > 0);
  l.mean /= double(scene);
  l.spread = std::sqrt(std::max(0.0, sum2 / double(scene) - l.mean * l.mean));
  l.black /= double(scene);
  l.white /= double(scene);
  l.background /= double(n);
  return l;
}

/// Readable: filled with the scene (a view from inside), not mostly dark or
/// bright, not one flat colour.
void check_readable(const Looks& l) {
  INFO("luma mean " << l.mean << ", spread " << l.spread << ", black " << l.black << ", white " << l.white << ", background "
                    << l.background);
  CHECK(l.background < 0.05);
  CHECK(l.mean > 40);
  CHECK(l.mean < 200);
  CHECK(l.spread > 15);
  CHECK(l.black < 0.3);
  CHECK(l.white < 0.15);
}

/// A closed 5 × 3 × 4 m box, its faces toward the inside, with a table: as an OBJ.
void write_closed_box(const fs::path& path) {
  Scene box = builders::box_room(Vec3(5.f, 3.f, 4.f));
  builders::add_table(box);
  std::ofstream out(path);
  for (const Vec3& p : box.positions) out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
  for (const auto& t : box.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

/// Seeded random ceiling lamps in the FZK house's ground floor, all in one
/// room of the split at doors that also reaches the upper storey (through
/// the stair's opening): the room whose ground floor the view must pick out.
struct GroundFloorLamps {
  Lighting lamps;
  int room = 0;        ///< its number in the split
  PlanSection storey;  ///< the ground floor
};

GroundFloorLamps ground_floor_lamps(const RayScene& rays, const RoomSplit& split, uint64_t seed, size_t count) {
  const std::vector<PlanSection> storeys = plan_sections(rays.scene());
  REQUIRE(storeys.size() >= 2);  // the ground floor and the attic
  GroundFloorLamps out;
  out.storey = storeys.front();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> u(0.f, 1.f), drop(0.15f, 0.4f), level(1.f, 4.f);
  const Bounds space = rays.scene().light_bounds();
  for (int attempt = 0; attempt < 20000 && out.lamps.size() < count; ++attempt) {
    const Vec3 p(space.lo.x + u(rng) * space.extent().x, out.storey.floor + u(rng) * (out.storey.top - out.storey.floor),
                 space.lo.z + u(rng) * space.extent().z);
    const int room = split.at(p);
    if (room == 0 || (out.room != 0 && room != out.room)) continue;
    if (out.room == 0 && !(split.list()[size_t(room - 1)].box.hi.y > out.storey.top)) continue;  // a room of one storey
    // Under a ceiling of this storey, over its floor.
    const Hit up = rays.intersect(p, Vec3(0, 1, 0)), down = rays.intersect(p, Vec3(0, -1, 0));
    if (!up.valid() || !down.valid() || rays.face_normals()[up.triangle].y > -0.9f || rays.face_normals()[down.triangle].y < 0.9f) continue;
    const Vec3 lamp(p.x, p.y + up.t - drop(rng), p.z);
    if (lamp.y > out.storey.top || lamp.y - (p.y - down.t) < 2.f || split.at(lamp) != room || rays.inside_solid(lamp)) continue;
    if (std::any_of(out.lamps.begin(), out.lamps.end(), [&](const Light& l) { return glm::length(l.position - lamp) < 1.f; })) continue;
    out.room = room;
    out.lamps.push_back(Light::point(lamp, Rgb(level(rng))));
  }
  REQUIRE(out.lamps.size() == count);
  return out;
}

} // namespace

TEST_CASE("default view: the IFC house from inside its lit interior at eye height, an open plane from outside", "[view]") {
  const auto scene = std::make_shared<const Scene>(load_scene(kHouse));
  const auto rays = RayScene::shared(scene);
  std::mt19937_64 rng(36);
  const Lighting lamps = test::random_ceiling_lamps(*rays, rng, 3);
  const int room = default_view_room(*rays, lamps);
  REQUIRE(room >= 0);
  const Regions regions(*rays);
  // Not the outside (the first region, around the house): a room with a lamp in it.
  CHECK(regions.list()[size_t(room)].volume < regions.list()[0].volume);
  CHECK(std::any_of(lamps.begin(), lamps.end(), [&](const Light& l) { return regions.at(l.position) == room; }));
  const std::vector<Camera> views = default_views(*rays, lamps, 4.f / 3.f, 3);
  REQUIRE(views.size() == 3);
  for (const Camera& v : views) {
    INFO("eye " << v.eye.x << ", " << v.eye.y << ", " << v.eye.z);
    CHECK(regions.at(v.eye) == room);
    CHECK_FALSE(rays->inside_solid(v.eye));
    // At eye height: the floor straight below 1–2 m down.
    const Hit floor = rays->intersect(v.eye, Vec3(0.f, -1.f, 0.f));
    REQUIRE(floor.valid());
    CHECK(floor.t > 1.f);
    CHECK(floor.t < 2.f);
  }
  // The same scene and lights: the same views (no dependence on threads).
  const std::vector<Camera> again = default_views(*rays, lamps, 4.f / 3.f, 3);
  for (size_t k = 0; k < views.size(); ++k) CHECK(glm::length(again[k].eye - views[k].eye) == 0.f);

  // A plane encloses nothing: seen from outside, as Camera::framing frames it.
  const auto plane = test::finish(builders::plane(5.f), 0.5f);
  const auto plane_rays = RayScene::shared(plane);
  CHECK(default_view_room(*plane_rays, {}) == -1);
  const Camera outside = default_view(*plane_rays, {}, 4.f / 3.f), framing = Camera::framing(plane->bounds, 4.f / 3.f);
  CHECK(glm::length(outside.eye - framing.eye) < 1e-4f);
}

TEST_CASE("default view: in the FZK house lamps in a ground-floor room put the eyes in that room, not in the attic over it",
          "[view][rooms]") {
  const auto scene = std::make_shared<const Scene>(load_scene(kHouse));
  const auto rays = RayScene::shared(scene);
  const RoomSplit split(*rays);
  const std::vector<PlanSection> storeys = plan_sections(*scene);
  std::vector<Vec3> eyes;
  // Seed 31's one lamp hangs in a window's reveal: the regions' coarse grid puts it outside, the split in the room.
  for (const uint64_t seed : {29, 30, 31, 32})
    for (const size_t count : {1, 3}) {
      const GroundFloorLamps lit = ground_floor_lamps(*rays, split, seed, count);
      if (seed == 31 && count == 1) CHECK(Regions(*rays).at(lit.lamps[0].position) != default_view_room(*rays, lit.lamps));
      const std::vector<Camera> views = default_views(*rays, lit.lamps, 4.f / 3.f, 3);
      REQUIRE(views.size() == 3);
      for (const Camera& v : views) {
        INFO("seed " << seed << ", " << count << " lamps: eye " << v.eye.x << ", " << v.eye.y << ", " << v.eye.z << " in room "
                     << split.at(v.eye));
        CHECK(split.at(v.eye) == lit.room);
        CHECK(storey_floor(storeys, v.eye) == lit.storey.floor);
        CHECK(v.eye.y < lit.storey.top);
        const Hit floor = rays->intersect(v.eye, Vec3(0.f, -1.f, 0.f));
        REQUIRE(floor.valid());
        CHECK(floor.t > 1.f);
        CHECK(floor.t < 2.f);
        eyes.push_back(v.eye);
      }
    }
#ifdef HILIGHT_HAVE_IFCPP
  // As the IFC names its rooms: each eye in one of the ground floor's IfcSpaces (the hall, living room and
  // kitchen are that room of the split), none in the Galerie upstairs.
  const cli::IfcRooms ifc = cli::read_ifc_rooms(kHouse, *scene);
  REQUIRE_FALSE(ifc.rooms.empty());
  for (const Vec3& eye : eyes) {
    const auto holding = std::find_if(ifc.rooms.begin(), ifc.rooms.end(), [&](const NamedRoom& room) { return room.contains(eye); });
    INFO("eye " << eye.x << ", " << eye.y << ", " << eye.z);
    REQUIRE(holding != ifc.rooms.end());
    INFO("in " << holding->name);
    CHECK(holding->storey == ifc.storeys.front());
  }
#endif
  // The CLI's render with no --camera looks from there, and the picture reads.
  const fs::path dir = test::output_dir("default_view_ground_floor");
  write_lights_file(dir / "lights.json", ground_floor_lamps(*rays, split, 3602, 3).lamps);
  const auto r = test::run_hilight({"render", kHouse.string(), "--lights", (dir / "lights.json").string(), "--bounces", "0", "--width",
                                    "240", "--height", "180", "-o", (dir / "ground-floor.png").string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  check_readable(looks_of(dir / "ground-floor.png"));
}

TEST_CASE("default view: with no light a building opens on its main storey, the FZK house on its ground floor, not in the attic",
          "[view][rooms]") {
  const auto scene = std::make_shared<const Scene>(load_scene(kHouse));
  const auto rays = RayScene::shared(scene);
  const std::vector<PlanSection> storeys = plan_sections(*scene);
  REQUIRE(storeys.size() >= 2);
  const Camera view = default_view(*rays, {}, 4.f / 3.f);
  INFO("eye " << view.eye.x << ", " << view.eye.y << ", " << view.eye.z);
  CHECK(storey_floor(storeys, view.eye) == storeys.front().floor);
  CHECK(view.eye.y < storeys.front().top);
  const Hit floor = rays->intersect(view.eye, Vec3(0.f, -1.f, 0.f));
  REQUIRE(floor.valid());
  CHECK(floor.t > 1.f);
  CHECK(floor.t < 2.f);
  CHECK(default_view_room(*rays, {}) == Regions(*rays).at(view.eye));
#ifdef HILIGHT_HAVE_IFCPP
  // In one of the ground floor's IfcSpaces, not the Galerie in the attic.
  const cli::IfcRooms ifc = cli::read_ifc_rooms(kHouse, *scene);
  const auto holding = std::find_if(ifc.rooms.begin(), ifc.rooms.end(), [&](const NamedRoom& room) { return room.contains(view.eye); });
  REQUIRE(holding != ifc.rooms.end());
  INFO("in " << holding->name);
  CHECK(holding->storey == ifc.storeys.front());
#endif
}

TEST_CASE("render: with no --camera the IFC house and a closed box are pictures a person can read", "[cli][render][view]") {
  const fs::path dir = test::output_dir("default_view_render");
  SECTION("the IFC house, lit by three ceiling lamps") {
    const auto scene = std::make_shared<const Scene>(load_scene(kHouse));
    const auto rays = RayScene::shared(scene);
    std::mt19937_64 rng(360);
    write_lights_file(dir / "house-lights.json", test::random_ceiling_lamps(*rays, rng, 3));
    // Direct light only: the bounce of a 117k-vertex house takes half a minute.
    const auto r = test::run_hilight({"render", kHouse.string(), "--lights", (dir / "house-lights.json").string(), "--bounces", "0",
                                      "--width", "240", "--height", "180", "-o", (dir / "house.png").string()});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    check_readable(looks_of(dir / "house.png"));
  }
  SECTION("a closed box with a table, lit by two ceiling lamps") {
    write_closed_box(dir / "box.obj");
    const auto scene = std::make_shared<const Scene>(load_scene(dir / "box.obj"));
    const auto rays = RayScene::shared(scene);
    std::mt19937_64 rng(361);
    write_lights_file(dir / "box-lights.json", test::random_ceiling_lamps(*rays, rng, 2));
    const auto r = test::run_hilight({"render", (dir / "box.obj").string(), "--lights", (dir / "box-lights.json").string(),
                                      "--width", "240", "--height", "180", "-o", (dir / "box.png").string()});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    check_readable(looks_of(dir / "box.png"));
    // Seen from inside: from outside a closed box shows only its outer walls, unlit.
    CHECK(default_view_room(*rays, {}) >= 0);
  }
}

TEST_CASE("default view: with no light a building over a basement as large as its ground floor opens on the ground floor",
          "[view][rooms]") {
  // Three closed storeys of one 10 x 8 m plan, 2.8 m high, slabs 0.2 m: a
  // basement (floor at -3), the ground floor (at elevation 0) and an upper
  // floor, those two split by a partition with a door. The basement, one
  // open room, has the most floor to stand on, the ground floor within a
  // tenth of it: the ground floor must win by its elevation, nearest 0, and
  // not the basement, the lowest.
  Scene raw;
  for (const float floor : {-3.f, 0.f, 3.f}) {
    builders::add_box(raw, Vec3(0.f, floor, 0.f), Vec3(10.f, floor + 2.8f, 8.f), Rgb(0.7f), true, "storey");
    if (floor < 0.f) continue;
    builders::add_box(raw, Vec3(4.9f, floor, 0.f), Vec3(5.1f, floor + 2.8f, 3.5f), Rgb(0.7f), false, "partition");
    builders::add_box(raw, Vec3(4.9f, floor, 4.5f), Vec3(5.1f, floor + 2.8f, 8.f), Rgb(0.7f), false, "partition");
  }
  const auto scene = test::finish(std::move(raw), 0.5f);
  const auto rays = RayScene::shared(scene);
  const std::vector<PlanSection> storeys = plan_sections(*scene);
  REQUIRE(storeys.size() == 3);
  CHECK(storeys.front().floor == Approx(-3.f).margin(0.05f));
  const Camera view = default_view(*rays, {}, 4.f / 3.f);
  INFO("eye " << view.eye.x << ", " << view.eye.y << ", " << view.eye.z);
  CHECK(storey_floor(storeys, view.eye) == Approx(0.f).margin(0.05f));
  CHECK(view.eye.y > 1.f);
  CHECK(view.eye.y < 2.8f);
  // Moved up 100 m (a model at its site's elevation) with nothing around it, no storey is near 0: the
  // lowest of them, the basement. With the site's ground around it (a 2 m ring at the ground floor's
  // level), the ground floor again.
  for (const bool terrain : {false, true}) {
    Scene high;
    for (const float floor : {-3.f, 0.f, 3.f}) {
      builders::add_box(high, Vec3(0.f, 100.f + floor, 0.f), Vec3(10.f, 102.8f + floor, 8.f), Rgb(0.7f), true, "storey");
      if (floor < 0.f) continue;
      builders::add_box(high, Vec3(4.9f, 100.f + floor, 0.f), Vec3(5.1f, 102.8f + floor, 3.5f), Rgb(0.7f), false, "partition");
      builders::add_box(high, Vec3(4.9f, 100.f + floor, 4.5f), Vec3(5.1f, 102.8f + floor, 8.f), Rgb(0.7f), false, "partition");
    }
    if (terrain) {
      const Rgb grass(0.3f, 0.45f, 0.2f);
      builders::add_box(high, Vec3(-2.f, 99.8f, -2.f), Vec3(12.f, 100.f, 0.f), grass, false, "terrain");
      builders::add_box(high, Vec3(-2.f, 99.8f, 8.f), Vec3(12.f, 100.f, 10.f), grass, false, "terrain");
      builders::add_box(high, Vec3(-2.f, 99.8f, 0.f), Vec3(0.f, 100.f, 8.f), grass, false, "terrain");
      builders::add_box(high, Vec3(10.f, 99.8f, 0.f), Vec3(12.f, 100.f, 8.f), grass, false, "terrain");
    }
    const auto high_scene = test::finish(std::move(high), 0.5f);
    const Camera high_view = default_view(*RayScene::shared(high_scene), {}, 4.f / 3.f);
    INFO((terrain ? "with" : "without") << " the site's ground: eye " << high_view.eye.x << ", " << high_view.eye.y << ", "
                                        << high_view.eye.z);
    if (terrain) {
      CHECK(high_view.eye.y > 101.f);
      CHECK(high_view.eye.y < 102.8f);
    } else {
      CHECK(high_view.eye.y < 99.8f);
    }
  }
  // A lamp in the basement takes the eyes there: a light decides before any storey does.
  const Lighting lamp = {Light::point(Vec3(3.f, -0.8f, 4.f), Rgb(1.f))};
  const Camera lit = default_view(*rays, lamp, 4.f / 3.f);
  INFO("lit eye " << lit.eye.x << ", " << lit.eye.y << ", " << lit.eye.z);
  CHECK(lit.eye.y < -0.2f);
}
