#pragma once
/// RAII wrapper of an Embree device and the BVH of one hilight Scene: the
/// geometric queries of the renderers and the solver (shadow rays, first hits,
/// nearest surface point, inside-solid tests). occluded() is inline so hot
/// loops pay nothing beyond Embree's own call.
#include "hilight/own_frame.hpp"
#include "hilight/scene.hpp"

#include <embree3/rtcore.h>
#include <array>
#include <cstdint>
#include <cmath>
#include <memory>
#include <vector>

namespace hilight {

struct Hit {
  uint32_t triangle = RTC_INVALID_GEOMETRY_ID;
  float u = 0.f, v = 0.f, t = 0.f;
  bool valid() const { return triangle != RTC_INVALID_GEOMETRY_ID; }
};

class RayScene;

/// Where renderers shade a surface point (docs/rendering-model.md, "Where a
/// point is shaded"). Every renderer calls shading_point(), so they all shade
/// the same point.
struct ShadingPoint {
  Vec3 position;
  /// On a smooth surface (only its own smooth fan of triangles touches it):
  /// shaded at the point itself, and a ray leaves it skipping the first ε of
  /// its own path, so the fan's flat facets never shadow a light the smooth
  /// normal faces (the terminator). Otherwise (hard creases, contacts,
  /// touching parts) `position` is a hair inside the point's triangle and a
  /// ray is lifted ε along the normal of the side it leaves from.
  bool smooth = false;
  /// The triangle the point lies on (closest, agreeing best with its normal),
  /// or RTC_INVALID_GEOMETRY_ID when no surface is near.
  uint32_t triangle = RTC_INVALID_GEOMETRY_ID;
  /// On a smooth point found by shading_point(): the sine of the largest tilt
  /// of its own fan's facets against its tangent plane (a hair over). Only a
  /// direction with |n·ω| below it can lie in the point's wedge
  /// (in_own_wedge); 0: none can (a flat fan, a pixel's hit, a crease).
  float wedge = 0.f;
  /// The fan is one plane all around the point (`triangle`'s: a face cut
  /// into coplanar triangles, a tessellated one): its wedge is told from that
  /// plane alone, with no look-up.
  bool flat_fan = false;
  /// The tilted facets of a smooth point's own fan (the only ones its wedge
  /// test looks at), kept so that the test needs no look-up; a fan with more
  /// than kKeptFan of them (a sphere's pole) is looked up (kFanLookedUp).
  static constexpr uint8_t kKeptFan = 8, kFanLookedUp = 255;
  uint8_t fan_size = kFanLookedUp;
  std::array<uint32_t, kKeptFan> fan{};

  /// Where a ray toward unit `dir` starts, leaving on the side `side_normal` points to.
  Vec3 ray_start(const Vec3& dir, const Vec3& side_normal, float eps) const {
    return position + (smooth ? dir : side_normal) * eps;
  }
};

/// Smooth points stay where they are; others move a fixed step
/// (RayScene::shading_step(), relative to the scene's size) into the
/// face they lie on, away from the crease or from the surface touching them,
/// the same on any tessellation of that face (docs/rendering-model.md), so
/// that a point on an edge or corner never starts rays on a neighbouring
/// face's plane.
ShadingPoint shading_point(const RayScene& rays, const Vec3& position, const Vec3& normal);

/// The smooth point's wedge (docs/rendering-model.md, "The wedge"): true when
/// unit `dir` leaves `at` between its tangent plane (normal `n`) and the
/// facet of its own fan that lies under `dir` (the one whose corner, edge
/// half-disk or face holds dir's azimuth around n). Such a ray passes through
/// the smooth surface the fan stands for within about a facet, so it counts
/// as blocked. in_own_wedge_slow looks the fan up; in_own_wedge first rules
/// out the directions no facet can hold (nearly all of them).
bool in_own_wedge_slow(const RayScene& rays, const ShadingPoint& at, const Vec3& n, const Vec3& dir);
inline bool in_own_wedge(const RayScene& rays, const ShadingPoint& at, const Vec3& n, const Vec3& dir) {
  return at.wedge > 0.f && std::abs(glm::dot(n, dir)) < at.wedge && in_own_wedge_slow(rays, at, n, dir);
}

/// Where a pixel's hit inside a smooth-shaded triangle is shaded: lifted to
/// the smooth surface its vertex normals describe (each vertex's tangent
/// plane, blended by the barycentrics; Hanika 2021, "Hacking the shadow
/// terminator"), so the facets' terminator does not show inside a triangle.
/// At a vertex, and on a flat triangle, it is the hit itself. `side` (+1 or
/// -1) is the side of the shading normal the light is on: the lift goes to
/// that side, so a light behind a two-sided curved sheet is not shadowed by
/// the sheet's own facets either.
ShadingPoint smooth_hit_point(const RayScene& rays, const Hit& hit, float side = 1.f);

class RayScene {
public:
  explicit RayScene(const Scene& scene);
  /// The RayScene of `scene` that every renderer and solver in the process
  /// shares while any of them holds it: one BVH however many bind the scene
  /// (the painter binds a building five times). It keeps the scene alive.
  static std::shared_ptr<const RayScene> shared(std::shared_ptr<const Scene> scene);
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  const Scene& scene() const { return m_scene; }
  /// Offset used to lift ray origins off the surface (scene-relative).
  float epsilon() const { return m_epsilon; }
  /// How far shading_point() moves a point off a crease into its face:
  /// kShadingStep of the size (2.5 mm in an 8.4 m room), so the same scene
  /// at any scale is shaded at the same places (docs/rendering-model.md,
  /// "Tolerances"). Two needs meet here: fine meshes want it small against
  /// their facets (the glTF engine's solve drifts at 4e-4), and POV-Ray,
  /// which ignores shadow hits closer than an absolute 1e-3, wants it above
  /// that at the scale it is handed (povray_renderer.hpp).
  float shading_step() const { return m_shading_step; }
  static constexpr float kShadingStep = 3e-4f;
  /// The scene's own frame (own_frame.hpp): what is laid out in it — the
  /// bounce's streams, the refinement's directions — turns with the scene.
  const OwnFrame& own_frame() const { return m_own_frame; }

  /// True if anything blocks the segment origin + t*dir, t in (0, tfar).
  bool occluded(const Vec3& origin, const Vec3& dir, float tfar) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray;
    ray.org_x = origin.x; ray.org_y = origin.y; ray.org_z = origin.z;
    ray.dir_x = dir.x; ray.dir_y = dir.y; ray.dir_z = dir.z;
    ray.tnear = 0.f;
    ray.tfar = tfar;
    ray.mask = 0xFFFFFFFFu;
    ray.flags = 0;
    ray.time = 0.f;
    rtcOccluded1(m_rtc_scene, &context, &ray);
    return ray.tfar < 0.f;
  }

  Hit intersect(const Vec3& origin, const Vec3& dir, float tfar = 1e30f) const;

  /// Surface position and shading normal at a hit.
  Vec3 hit_position(const Hit& hit) const;
  Vec3 hit_normal(const Hit& hit) const;
  /// Unit geometric normal of every triangle (from its winding).
  const std::vector<Vec3>& face_normals() const { return m_face_normals; }

  /// The surface point nearest to `p` within `max_distance` (t = distance),
  /// or an invalid Hit.
  /// With a non-zero `normal_hint`, among surfaces equally near (a point on a
  /// crease touches several) the one whose normal agrees best wins. "Equally
  /// near": within `tie`, by default the ray epsilon.
  Hit closest_point(const Vec3& p, float max_distance, const Vec3& normal_hint = Vec3(0.f), float tie = -1.f) const;
  /// True if `p` is enclosed by geometry that faces away from it: rays in
  /// 14 directions all hit, and most of them hit a back face (so inside a
  /// closed, outward-wound object; inside an inward-wound room is free space).
  bool inside_solid(const Vec3& p) const;
  /// True when every triangle within `radius` of `p` is `own_triangle` or has
  /// a vertex at `p` (within radius/20) whose normal agrees with `normal`
  /// (cos ≥ 0.999): only the point's own smooth surface is near it. With
  /// `fan`, also what the point's wedge test needs of those own triangles:
  /// the sine of their largest tilt against the plane normal to `normal`
  /// (ShadingPoint::wedge), whether they are one plane all around p
  /// (ShadingPoint::flat_fan) and the tilted ones (ShadingPoint::fan).
  bool only_own_surface_near(const Vec3& p, const Vec3& normal, uint32_t own_triangle, float radius,
                             ShadingPoint* fan = nullptr) const;

  RTCScene rtc_scene() const { return m_rtc_scene; }

private:
  const Scene& m_scene;
  RTCDevice m_device = nullptr;
  RTCScene m_rtc_scene = nullptr;
  float m_epsilon = 1e-4f;
  float m_shading_step = 3e-3f;
  std::vector<Vec3> m_face_normals;
  OwnFrame m_own_frame;
};

} // namespace hilight
