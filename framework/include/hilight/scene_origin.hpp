#pragma once
/// Where a scene sits and its length unit (issues 15 and 19): floats near
/// 10⁴ carry only millimetres, so a scene far from the origin would be ray
/// traced, tessellated and solved more coarsely than the same scene at home;
/// and lux is per square metre, so a model in millimetres must be computed
/// in metres. load_scene gives every scene a SceneFrame: its vertices become
/// local = (world − origin) · scale, with the origin the centre of its bounds
/// rounded to a multiple of a power of two at least its size (exact in float;
/// a scene near the origin is not moved) and scale the metres per file unit.
/// Every position a command reads (lights, targets, criteria, cameras,
/// placement boxes) goes to local coordinates, every position it writes back
/// to world ones. docs/rendering-model.md, "Where a scene sits".
#include "hilight/light_space.hpp"
#include "hilight/lighting.hpp"
#include "hilight/math.hpp"
#include "hilight/scene.hpp"
#include "hilight/units.hpp"

#include <filesystem>

#include <string>

namespace hilight {

/// The origin a scene with these bounds is moved to (0 for a scene whose
/// centre is within about its size of the origin).
glm::dvec3 recentring_origin(const Bounds& bounds);

/// Metres per unit: "mm", "cm", "m", "in", "ft"; InputError otherwise.
double metres_per_unit(const std::string& unit);

inline Vec3 to_local(const glm::dvec3& world, const SceneFrame& f) { return Vec3((world - f.origin) * f.scale); }
inline Vec3 to_local(const Vec3& world, const SceneFrame& f) { return to_local(glm::dvec3(world), f); }
inline glm::dvec3 to_world(const Vec3& local, const SceneFrame& f) { return glm::dvec3(local) / f.scale + f.origin; }
/// A length (an offset, an edge) in the file's unit, in hilight's.
inline float length_to_local(double length, const SceneFrame& f) { return float(length * f.scale); }

/// Lights read from `file` for `scene`, moved in (in double precision), each checked to lie within
/// reach: no farther from the scene than a million times its size (a light
/// at 10¹⁹ aborted Embree; beyond that reach a light adds nothing a float
/// can hold). InputError naming the file and the light otherwise. Every
/// command that reads lights for a scene calls this (render, solve
/// --initial); the solve then holds them to its own light space.
Lighting lights_from_file(const std::filesystem::path& file, Units units, const Scene& scene);

/// Placement rules given in the file's coordinates (boxes, heights, the
/// ceiling offset) in hilight's.
PlacementRules rules_to_local(PlacementRules rules, const SceneFrame& frame);
/// The inverse: rules in hilight's coordinates as the file's (to show them as the user gave them).
PlacementRules rules_to_world(PlacementRules rules, const SceneFrame& frame);

} // namespace hilight
