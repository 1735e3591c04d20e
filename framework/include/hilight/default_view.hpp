#pragma once
/// The views a picture takes when the user names none (issue 36): `hilight
/// render` and `export` without `--camera`, the HTML report's views and the
/// painter's opening view. A building or a closed box is seen from inside
/// its largest lit room, at eye height, across the room; a scene with no
/// enclosed room (a product, a landscape) from outside (Camera::framing).
/// The room: in the largest enclosed region holding a light (else in every
/// enclosed one), the largest room of the split at doors
/// (room_split.hpp), cut at the storeys' floors (plan_sections), that holds
/// a light; with none lit, the room with the most floor to stand on (its plan
/// at eye height) of the main storey: of the storeys within a tenth of the
/// most such floor, the one at ground level — the outside ground the scene
/// shows around the building, else the file's elevation 0 — the lowest of
/// equally near ones (a ground floor, not a basement of the same plan, an
/// attic under a sloping roof nor an upper floor). The whole region where the
/// split finds no room.
#include "hilight/camera.hpp"
#include "hilight/lighting.hpp"
#include "hilight/ray_scene.hpp"

#include <vector>

namespace hilight {

/// Up to `count` views (at least one), best first. Inside the room: the eyes
/// and directions that see the most lit surface the farthest, each later one
/// from elsewhere in the room or looking another way. Outside: the framing
/// view turned about the vertical by 360°/count each. With no lights every
/// surface counts as lit.
std::vector<Camera> default_views(const RayScene& rays, const Lighting& lights, float aspect, size_t count = 1);

/// The first of default_views.
Camera default_view(const RayScene& rays, const Lighting& lights, float aspect);

/// The region default_views looks into: the index in Regions(rays).list()
/// of the region its eyes stand in, the largest enclosed one holding a light
/// (with no lit one, the region of the main storey's room, else the largest
/// enclosed one); -1 when no region is enclosed (the view is from outside).
int default_view_room(const RayScene& rays, const Lighting& lights);

} // namespace hilight
