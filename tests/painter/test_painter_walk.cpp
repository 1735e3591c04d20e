// Walk mode's movement (core/walk.hpp): the eye stands at eye height over
// the floor, walls stop it (radius short) and the rest of a move slides
// along them; in the IFC house no step in any direction crosses a surface.
#include "core/walk.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/regions.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "painter_fixtures.hpp"

#include <catch2/catch.hpp>
#include <cmath>

using namespace hilight;
using namespace hilight::painter;

namespace {

/// Two 3 x 3 x 4 rooms side by side, a closed wall 0.2 thick at x = 3.
painter_test::World two_rooms() {
  Scene raw = builders::box_room(Vec3(6.f, 3.f, 4.f));
  builders::add_box(raw, Vec3(2.9f, 0.f, 0.f), Vec3(3.1f, 3.f, 4.f), Rgb(0.8f), false, "wall");
  return painter_test::make_world(std::move(raw), 0.5f);
}

} // namespace

TEST_CASE("painter walk: the eye stands on the floor and a wall stops it, the rest of the move slides along", "[painter][walk]") {
  const auto world = two_rooms();
  const WalkSettings settings;
  const Vec3 start = stand_at(*world.rays, Vec3(1.f, 2.5f, 2.f), settings);
  CHECK(start.y == Approx(1.6f).margin(1e-3));

  // Straight at the wall: stopped the radius short of it, in the first room.
  const Vec3 stopped = walk_step(*world.rays, start, Vec3(10.f, 0.f, 0.f), settings);
  CHECK(stopped.x == Approx(2.9f - settings.radius).margin(1e-3));
  CHECK(stopped.y == Approx(1.6f).margin(1e-3));
  // Many small steps do not creep through either.
  Vec3 p = start;
  for (int i = 0; i < 100; ++i) p = walk_step(*world.rays, p, Vec3(0.1f, 0.f, 0.f), settings);
  CHECK(p.x < 2.9f);
  // Diagonally: x stops at the wall, z goes on.
  const Vec3 slid = walk_step(*world.rays, start, Vec3(3.f, 0.f, 1.f), settings);
  CHECK(slid.x == Approx(2.9f - settings.radius).margin(1e-3));
  CHECK(slid.z > start.z + 0.5f);
  CHECK(slid.z < 4.f - 0.1f);
  // Away from walls a move is exact.
  const Vec3 free = walk_step(*world.rays, start, Vec3(0.5f, 7.f, -0.5f), settings);
  CHECK(free.x == Approx(1.5f).margin(1e-4));
  CHECK(free.z == Approx(1.5f).margin(1e-4));
  CHECK(free.y == Approx(1.6f).margin(1e-3));  // the move's y is ignored
}

TEST_CASE("painter walk: in the IFC house walking never passes through a wall", "[painter][walk][real]") {
  auto scene = std::make_shared<const Scene>(load_scene(builders::testmodels_dir() / "IFC/AC14-FZK-Haus.ifc"));
  const RayScene rays(*scene);
  const Regions regions(rays);
  // A closed room (the largest region is the outside, then the storeys).
  REQUIRE(regions.list().size() >= 3);
  const Region& room = regions.list().back();
  const Vec3 centre = room.box.center();
  const Vec3 start = stand_at(rays, Vec3(centre.x, room.box.lo.y + 1.7f, centre.z));
  REQUIRE(regions.at(start) == room.id);
  size_t stopped = 0;
  for (int k = 0; k < 8; ++k) {
    const float angle = float(k) * 2.f * float(kPi) / 8.f;
    const Vec3 step = 0.25f * Vec3(std::cos(angle), 0.f, std::sin(angle));
    Vec3 p = start;
    float walked = 0.f;
    for (int i = 0; i < 80; ++i) {
      const Vec3 next = walk_step(rays, p, step);
      // The eye's horizontal move crosses no surface (the vertical settle is a stand_at, tested above).
      const Vec3 across(next.x - p.x, 0.f, next.z - p.z);
      if (glm::length(across) > 1e-6f) {
        INFO("direction " << k << ", step " << i);
        CHECK_FALSE(rays.occluded(p, glm::normalize(across), glm::length(across)));
      }
      walked += glm::length(across);
      p = next;
    }
    stopped += walked < 19.f;  // 80 steps of 0.25 m: short of it, a wall stopped the walk
    // A closed room's walls hold every direction: the eye stays in it.
    INFO("direction " << k);
    CHECK(regions.at(p) == room.id);
  }
  CHECK(stopped == 8);
}
