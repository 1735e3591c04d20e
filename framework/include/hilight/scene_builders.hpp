#pragma once
/// Scenes built in code, shared by tests, benchmarks and the bundled demo
/// (OSPRay's pattern): the same scene everywhere, no files to drift.
/// Builders return raw meshes; pass them through finish_scene() to validate
/// and tessellate exactly as a loaded file would be.
#include "hilight/scene.hpp"

namespace hilight::builders {

/// Adds an axis-aligned box with its own material. `inward` winds the faces so
/// their normals point into the box (a room); otherwise outward (an object).
void add_box(Scene& scene, const Vec3& lo, const Vec3& hi, const Rgb& albedo, bool inward, const std::string& name);
/// Adds a quad (two triangles) with corners a, b, c, d in order; normal from the winding.
void add_quad(Scene& scene, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Rgb& albedo,
              const std::string& name);

/// A square floor in y = 0, centred at the origin, normal +Y.
Scene plane(float half_size, const Rgb& albedo = Rgb(0.8f));
/// A closed box room [0,size], normals inward.
Scene box_room(const Vec3& size, const Rgb& albedo = Rgb(0.8f));
/// A sphere (subdivided icosahedron) of `radius` at the origin with smooth
/// radial normals; `inward` winds it as a closed room seen from inside.
Scene sphere(float radius, int subdivisions, bool inward, const Rgb& albedo = Rgb(0.8f));
/// The furnished room's table (top 1.2–2.8 × 1.4–2.4 at 0.72–0.78, four legs).
void add_table(Scene& scene);
/// A 6 x 3 x 5 room with a table, a cabinet, a bench and a pillar: the
/// interior test scene (cf. the paper's Table 1), and the bundled demo.
Scene furnished_room();
/// An open-plan office `width` (x) by `depth` (z), 3 m high: rows of desks
/// (1.6 × 0.8, tops at 0.75) two metres apart and cabinets along one wall.
/// The illuminance design's benchmark (hilight bench lux).
Scene open_plan_office(float width = 20.f, float depth = 10.f);

} // namespace hilight::builders
