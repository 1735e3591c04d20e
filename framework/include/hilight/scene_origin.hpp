#pragma once
/// Where a scene sits (issue 15): floats near 10⁴ carry millimetres, so a
/// scene far from the origin would be ray traced, tessellated and solved
/// more coarsely than the same scene at home. load_scene moves it: its
/// vertices become local = world − origin, with the origin the centre of
/// its bounds snapped to a power of two at least its size (so the move is
/// exact in float and a scene near the origin is not moved at all). Every
/// position a command reads (lights, targets, criteria, cameras, placement
/// boxes) goes to local coordinates, every position it writes back to world
/// ones. docs/rendering-model.md, "Where a scene sits".
#include "hilight/light_space.hpp"
#include "hilight/lighting.hpp"
#include "hilight/math.hpp"

namespace hilight {

/// The origin a scene with these bounds is moved to (0 for a scene whose
/// centre is within about its size of the origin).
glm::dvec3 recentring_origin(const Bounds& bounds);

inline Vec3 to_local(const Vec3& world, const glm::dvec3& origin) { return Vec3(glm::dvec3(world) - origin); }
inline glm::dvec3 to_world(const Vec3& local, const glm::dvec3& origin) { return glm::dvec3(local) + origin; }

/// Light positions moved in (read from a file) or out (to be written).
Lighting lights_to_local(Lighting lights, const glm::dvec3& origin);
Lighting lights_to_world(Lighting lights, const glm::dvec3& origin);

/// Placement rules given in world coordinates (boxes, heights) in local ones.
PlacementRules rules_to_local(PlacementRules rules, const glm::dvec3& origin);

} // namespace hilight
