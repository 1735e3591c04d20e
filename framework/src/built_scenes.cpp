#include "hilight/built_scenes.hpp"

#include "hilight/light_bounds.hpp"
#include "hilight/scene_builders.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hilight::builders {

namespace {

constexpr float kPi = 3.14159265f;

/// An opening in a wall: [u0,u1] along it, [y0,y1] up.
struct Opening {
  float u0, u1, y0, y1;
};

/// A wall from u0 to u1 along x (`along_x`) or z, centred at `at` across,
/// `thickness` thick, from y0 to y1, with openings (sorted, apart): solid
/// pieces between them, a sill below and a lintel above each.
void add_wall(Scene& s, bool along_x, float at, float thickness, float u0, float u1, float y0, float y1,
              std::vector<Opening> openings, const Rgb& albedo, const std::string& name) {
  std::sort(openings.begin(), openings.end(), [](const Opening& a, const Opening& b) { return a.u0 < b.u0; });
  auto piece = [&](float a0, float a1, float b0, float b1) {
    if (a1 - a0 <= 1e-4f || b1 - b0 <= 1e-4f) return;
    const float t0 = at - 0.5f * thickness, t1 = at + 0.5f * thickness;
    if (along_x) add_box(s, Vec3(a0, b0, t0), Vec3(a1, b1, t1), albedo, false, name);
    else add_box(s, Vec3(t0, b0, a0), Vec3(t1, b1, a1), albedo, false, name);
  };
  float u = u0;
  for (const auto& o : openings) {
    piece(u, o.u0, y0, y1);
    piece(o.u0, o.u1, y0, o.y0);  // sill
    piece(o.u0, o.u1, o.y1, y1);  // lintel
    u = o.u1;
  }
  piece(u, u1, y0, y1);
}

/// A slab from y0 to y1 over [x0,x1] x [z0,z1] with one rectangular hole.
void add_slab_with_hole(Scene& s, float x0, float x1, float z0, float z1, float y0, float y1, const Bounds& hole,
                        const Rgb& albedo, const std::string& name) {
  add_box(s, Vec3(x0, y0, z0), Vec3(hole.lo.x, y1, z1), albedo, false, name);
  add_box(s, Vec3(hole.hi.x, y0, z0), Vec3(x1, y1, z1), albedo, false, name);
  add_box(s, Vec3(hole.lo.x, y0, z0), Vec3(hole.hi.x, y1, hole.lo.z), albedo, false, name);
  add_box(s, Vec3(hole.lo.x, y0, hole.hi.z), Vec3(hole.hi.x, y1, z1), albedo, false, name);
}

/// Appends a triangle with its own flat normal (sharp edges).
void push_triangle(Scene& s, const Vec3& a, const Vec3& b, const Vec3& c, uint32_t material) {
  const Vec3 n = glm::normalize(glm::cross(b - a, c - a));
  const uint32_t base = uint32_t(s.positions.size());
  for (const Vec3& p : {a, b, c}) s.positions.push_back(p), s.normals.push_back(n);
  s.triangles.push_back({base, base + 1, base + 2});
  s.triangle_material.push_back(material);
}

/// A closed prism of `sides` facets (a cylinder) standing on `base`.
void add_cylinder(Scene& s, const Vec3& base, float radius, float height, int sides, const Rgb& albedo, const std::string& name) {
  s.materials.push_back({name, albedo});
  const uint32_t m = uint32_t(s.materials.size() - 1);
  const Vec3 top = base + Vec3(0.f, height, 0.f);
  for (int i = 0; i < sides; ++i) {
    const float a0 = 2.f * kPi * float(i) / float(sides), a1 = 2.f * kPi * float(i + 1) / float(sides);
    const Vec3 d0(radius * std::cos(a0), 0.f, radius * std::sin(a0)), d1(radius * std::cos(a1), 0.f, radius * std::sin(a1));
    push_triangle(s, base + d0, top + d0, top + d1, m);  // side, outward
    push_triangle(s, base + d0, top + d1, base + d1, m);
    push_triangle(s, top, top + d1, top + d0, m);        // lid, up
    push_triangle(s, base, base + d0, base + d1, m);     // bottom, down
  }
}

void add_furniture(Scene& s, const Vec3& room_lo, const Vec3& room_hi, int index) {
  // A table off-centre and a cabinet against a wall; which wall varies by room.
  const Vec3 c = 0.5f * (room_lo + room_hi);
  const float dx = (index % 2 ? 0.6f : -0.6f), dz = (index % 3 ? 0.4f : -0.4f);
  add_box(s, Vec3(c.x + dx - 0.6f, room_lo.y, c.z + dz - 0.4f), Vec3(c.x + dx + 0.6f, room_lo.y + 0.75f, c.z + dz + 0.4f),
          Rgb(0.55f, 0.4f, 0.3f), false, "table");
  const bool left = index % 2 == 0;
  const float x0 = left ? room_lo.x : room_hi.x - 0.5f;
  add_box(s, Vec3(x0, room_lo.y, c.z - 0.6f), Vec3(x0 + 0.5f, room_lo.y + 1.8f, c.z + 0.6f), Rgb(0.7f, 0.7f, 0.65f), false, "cabinet");
}

BuiltScene named(const std::string& name, const std::string& builder) {
  BuiltScene b;
  b.name = name;
  b.scene.source = "builtin:" + builder;
  return b;
}

} // namespace

BuiltScene two_storey_building() {
  BuiltScene b = named("building", "two_storey_building");
  Scene& s = b.scene;
  const float W = 12.f, D = 8.f, H = 3.f, slab = 0.2f, ext = 0.25f, inner = 0.12f;
  const Rgb wall(0.75f), floor(0.55f, 0.5f, 0.45f), ceiling(0.85f);
  const Bounds stair_hole{Vec3(0.3f, 0.f, 0.3f), Vec3(1.5f, 0.f, 3.0f)};
  // Slabs: ground, the upper floor (with the stair opening), the roof.
  add_box(s, Vec3(-ext, -slab, -ext), Vec3(W + ext, 0.f, D + ext), floor, false, "ground slab");
  add_slab_with_hole(s, 0.f, W, 0.f, D, H - slab, H, stair_hole, floor, "upper floor");
  add_box(s, Vec3(-ext, 2 * H - slab, -ext), Vec3(W + ext, 2 * H, D + ext), ceiling, false, "roof");
  for (int storey = 0; storey < 2; ++storey) {
    const float y0 = storey * H, y1 = y0 + H - slab;
    // Exterior walls, a window in each room (sill 0.9 m, 1.2 m high).
    const float sill = y0 + 0.9f, head = y0 + 2.1f;
    add_wall(s, true, -0.5f * ext, ext, -ext, W + ext, y0, y1, {{2.f, 3.4f, sill, head}, {8.f, 9.4f, sill, head}}, wall, "facade");
    add_wall(s, true, D + 0.5f * ext, ext, -ext, W + ext, y0, y1, {{2.5f, 3.9f, sill, head}, {8.5f, 9.9f, sill, head}}, wall, "facade");
    add_wall(s, false, -0.5f * ext, ext, 0.f, D, y0, y1, {}, wall, "facade");
    add_wall(s, false, W + 0.5f * ext, ext, 0.f, D, y0, y1, {}, wall, "facade");
    // Interior walls with doors (0.9 x 2.1 m) joining the four rooms.
    add_wall(s, false, 0.5f * W, inner, 0.f, D, y0, y1, {{1.6f, 2.5f, y0, y0 + 2.1f}, {5.4f, 6.3f, y0, y0 + 2.1f}}, wall, "partition");
    add_wall(s, true, 0.5f * D, inner, 0.f, 0.5f * W - 0.5f * inner, y0, y1, {{2.5f, 3.4f, y0, y0 + 2.1f}}, wall, "partition");
    add_wall(s, true, 0.5f * D, inner, 0.5f * W + 0.5f * inner, W, y0, y1, {{8.6f, 9.5f, y0, y0 + 2.1f}}, wall, "partition");
    for (int room = 0; room < 4; ++room) {
      const float rx0 = room % 2 ? 0.5f * W + 0.5f * inner : 0.f, rx1 = room % 2 ? W : 0.5f * W - 0.5f * inner;
      const float rz0 = room / 2 ? 0.5f * D + 0.5f * inner : 0.f, rz1 = room / 2 ? D : 0.5f * D - 0.5f * inner;
      const Vec3 lo(rx0, y0, rz0), hi(rx1, y1, rz1);
      add_furniture(s, lo, hi, storey * 4 + room);
      // Lamps hang in the upper half of the room, away from the walls.
      b.zones.push_back({Vec3(rx0 + 0.6f, y0 + 1.9f, rz0 + 0.6f), Vec3(rx1 - 0.6f, y1 - 0.15f, rz1 - 0.6f)});
    }
  }
  // The stair: steps up along z under the opening.
  for (int step = 0; step < 14; ++step) {
    const float top = (step + 1) * (H / 15.f), z = 0.3f + step * (2.7f / 14.f);
    add_box(s, Vec3(stair_hole.lo.x, 0.f, z), Vec3(stair_hole.hi.x, top, z + 2.7f / 14.f), Rgb(0.6f, 0.5f, 0.4f), false, "stair");
  }
  return b;
}

BuiltScene l_corridor() {
  BuiltScene b = named("corridor", "l_corridor");
  Scene& s = b.scene;
  const float L = 10.f, w = 2.f, h = 2.6f, t = 0.2f;
  const Rgb wall(0.8f), floor(0.5f, 0.45f, 0.4f);
  // Floor and ceiling slabs of both legs (leg A along x, leg B along z).
  add_box(s, Vec3(-t, -t, -t), Vec3(L + t, 0.f, w), floor, false, "floor");
  add_box(s, Vec3(L - w, -t, w), Vec3(L + t, 0.f, L + t), floor, false, "floor");
  add_box(s, Vec3(-t, h, -t), Vec3(L + t, h + t, w), wall, false, "ceiling");
  add_box(s, Vec3(L - w, h, w), Vec3(L + t, h + t, L + t), wall, false, "ceiling");
  // Walls: the outer L and the inner corner.
  add_box(s, Vec3(-t, 0.f, -t), Vec3(L + t, h, 0.f), wall, false, "wall");         // south, along A
  add_box(s, Vec3(L, 0.f, 0.f), Vec3(L + t, h, L + t), wall, false, "wall");       // east, along B
  add_box(s, Vec3(-t, 0.f, 0.f), Vec3(0.f, h, w), wall, false, "wall");            // west end of A
  add_box(s, Vec3(L - w, 0.f, L), Vec3(L, h, L + t), wall, false, "wall");         // north end of B
  add_box(s, Vec3(-t, 0.f, w), Vec3(L - w, h, w + t), wall, false, "wall");        // inner, along A
  add_box(s, Vec3(L - w - t, 0.f, w + t), Vec3(L - w, h, L), wall, false, "wall"); // inner, along B
  add_box(s, Vec3(2.f, 0.f, 0.f), Vec3(3.5f, 0.45f, 0.45f), Rgb(0.5f, 0.35f, 0.25f), false, "bench");
  add_box(s, Vec3(L - 0.45f, 0.f, 6.f), Vec3(L, 0.45f, 7.5f), Rgb(0.5f, 0.35f, 0.25f), false, "bench");
  b.zones.push_back({Vec3(0.4f, 1.6f, 0.4f), Vec3(L - 0.4f, h - 0.15f, w - 0.4f)});
  b.zones.push_back({Vec3(L - w + 0.4f, 1.6f, w + 0.4f), Vec3(L - 0.4f, h - 0.15f, L - 0.4f)});
  return b;
}

BuiltScene product_on_turntable() {
  BuiltScene b = named("product", "product_on_turntable");
  Scene& s = b.scene;
  add_cylinder(s, Vec3(0.f), 0.5f, 0.06f, 32, Rgb(0.3f), "turntable");
  add_cylinder(s, Vec3(0.f, 0.06f, 0.f), 0.16f, 0.4f, 24, Rgb(0.8f, 0.25f, 0.2f), "body");
  add_cylinder(s, Vec3(0.f, 0.46f, 0.f), 0.05f, 0.14f, 16, Rgb(0.85f), "neck");
  const Scene ball = sphere(0.1f, 2, false, Rgb(0.9f, 0.85f, 0.6f));
  const uint32_t base = uint32_t(s.positions.size()), mat = uint32_t(s.materials.size());
  for (size_t i = 0; i < ball.positions.size(); ++i) {
    s.positions.push_back(ball.positions[i] + Vec3(0.3f, 0.16f, 0.15f));
    s.normals.push_back(ball.normals[i]);
  }
  for (size_t t = 0; t < ball.triangles.size(); ++t) {
    s.triangles.push_back({base + ball.triangles[t][0], base + ball.triangles[t][1], base + ball.triangles[t][2]});
    s.triangle_material.push_back(mat + ball.triangle_material[t]);
  }
  s.materials.insert(s.materials.end(), ball.materials.begin(), ball.materials.end());
  // Key, fill and rim positions: a shell 0.9–1.3 m from the product, above
  // the turntable's plane, outside the scene's bounds.
  for (int k = 0; k < 6; ++k) {
    const float a = 2.f * kPi * float(k) / 6.f;
    const Vec3 c(1.1f * std::cos(a), 0.9f, 1.1f * std::sin(a));
    b.zones.push_back({c - Vec3(0.2f, 0.4f, 0.2f), c + Vec3(0.2f, 0.4f, 0.2f)});
  }
  b.far_lights = true;
  return b;
}

BuiltScene stage() {
  BuiltScene b = named("stage", "stage");
  Scene& s = b.scene;
  const Rgb boards(0.45f, 0.35f, 0.25f), black(0.15f), flat(0.7f);
  add_box(s, Vec3(-6.f, -0.01f, -4.f), Vec3(6.f, 0.f, 6.f), Rgb(0.3f), false, "auditorium floor");
  add_box(s, Vec3(-4.f, 0.f, -3.f), Vec3(4.f, 0.8f, 2.f), boards, false, "platform");
  add_box(s, Vec3(-5.f, 0.f, -3.4f), Vec3(5.f, 5.f, -3.f), black, false, "back wall");
  add_box(s, Vec3(-4.6f, 0.8f, -2.5f), Vec3(-4.2f, 4.f, 0.5f), flat, false, "flat");
  add_box(s, Vec3(4.2f, 0.8f, -2.5f), Vec3(4.6f, 4.f, 0.5f), flat, false, "flat");
  add_box(s, Vec3(-1.5f, 0.8f, -1.2f), Vec3(-0.7f, 1.6f, -0.4f), Rgb(0.8f, 0.75f, 0.6f), false, "crate");
  add_cylinder(s, Vec3(1.4f, 0.8f, -0.5f), 0.3f, 1.2f, 20, Rgb(0.7f, 0.7f, 0.8f), "column");
  // The rig: a bar over the stage and one over the front of the house.
  b.zones.push_back({Vec3(-3.5f, 4.2f, -2.f), Vec3(3.5f, 4.8f, 0.5f)});
  b.zones.push_back({Vec3(-3.5f, 3.5f, 2.5f), Vec3(3.5f, 4.5f, 4.5f)});
  b.aim = Bounds{Vec3(-3.f, 0.8f, -2.f), Vec3(3.f, 0.8f, 1.5f)};
  return b;
}

Lighting random_lights(const BuiltScene& built, const RayScene& rays, std::mt19937_64& rng, const RandomLightRules& rules) {
  std::uniform_real_distribution<float> u(0.f, 1.f);
  auto in = [&](const Bounds& b) { return b.lo + Vec3(u(rng), u(rng), u(rng)) * (b.hi - b.lo); };
  const Scene& scene = rays.scene();
  const float diagonal = scene.diagonal();
  if (!(diagonal > 0.f)) throw std::invalid_argument("random_lights: an empty scene (" + built.name + ")");
  const Vec3 centre = scene.bounds.center();
  const Bounds space = built.far_lights ? open_light_bounds(scene) : scene.light_bounds();
  auto free = [&](const Vec3& p, float clearance) {
    return space.contains(p) && !rays.inside_solid(p) && !rays.closest_point(p, clearance).valid();
  };
  const size_t count = std::uniform_int_distribution<size_t>(rules.min_count, rules.max_count)(rng);
  Lighting lights;
  for (int attempt = 0; attempt < 20000 && lights.size() < count; ++attempt) {
    const Bounds& zone = built.zones[std::uniform_int_distribution<size_t>(0, built.zones.size() - 1)(rng)];
    const Vec3 p = in(zone);
    if (!free(p, rules.clearance * diagonal)) continue;
    bool apart = true;
    for (const auto& l : lights) apart &= glm::length(l.position - p) > rules.min_apart * diagonal;
    if (!apart) continue;
    const float level = rules.min_intensity + u(rng) * (rules.max_intensity - rules.min_intensity);
    const float scale = built.far_lights ? glm::dot(p - centre, p - centre) : 1.f;
    const Rgb intensity = level * scale * Rgb(0.7f + 0.3f * u(rng), 0.7f + 0.3f * u(rng), 0.7f + 0.3f * u(rng));
    if (built.aim) {
      const Vec3 at = in(*built.aim);
      const float cutoff = 12.f + 16.f * u(rng), falloff = 2.f + 4.f * u(rng);
      lights.push_back(Light::spot(p, glm::normalize(at - p), cutoff, intensity * glm::dot(at - p, at - p), falloff));
    } else {
      lights.push_back(Light::point(p, intensity));
    }
  }
  return lights;
}

} // namespace hilight::builders
