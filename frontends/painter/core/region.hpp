#pragma once
/// Regions of the surface as sets of scene vertices, from world points (a
/// stroke's dabs). The painter has no geodesic distances: a vertex belongs to
/// a dab when it lies within the radius and its normal is on the same side
/// as the surface at the dab's centre (so the far side of a thin wall, whose
/// normal faces away, is never reached through it).
#include "core/view_clip.hpp"
#include "hilight/ray_scene.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace hilight::painter {

/// A point on the surface: where a pick ray hit, with the surface normal there.
struct SurfacePick {
  Vec3 position{0.f};
  Vec3 normal{0.f, 1.f, 0.f};
};

/// The surface point nearest to `p` (within 1% of the scene diagonal), with
/// its shading normal; nullopt if no surface is that near. Session scripts
/// give bare world points; this recovers which side of a wall they are on.
std::optional<SurfacePick> pick_near(const RayScene& rays, const Vec3& p);
/// As above, nullopt too when that nearest surface point is hidden by the view (`visible`, if given).
std::optional<SurfacePick> pick_near(const RayScene& rays, const Vec3& p, const Visibility* visible);


/// Vertices within `radius` of `centre` whose normals face the same side as
/// `normal` (dot > 0), each with its distance to the centre.
struct VertexDistance {
  uint32_t vertex;
  float distance;
};
std::vector<VertexDistance> vertices_in_dab(const Scene& scene, const SurfacePick& centre, float radius);

/// Union of the dabs at `points` (each snapped to the surface with pick_near;
/// points off the surface are skipped), sorted and without duplicates.
std::vector<uint32_t> region_vertices(const RayScene& rays, const std::vector<Vec3>& points, float radius);

/// Mean position of the given points (the "centre" of a stroked region).
Vec3 centroid(const std::vector<Vec3>& points);

} // namespace hilight::painter
