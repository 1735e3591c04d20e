#include "hilight/ray_scene.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <mutex>
#include <optional>

#include <stdexcept>
#include <string>

namespace hilight {

namespace {
void throw_device_error(RTCDevice device, const char* what) {
  throw std::runtime_error(std::string("Embree: ") + what + " failed (error " + std::to_string(int(rtcGetDeviceError(device))) + ")");
}
} // namespace

RayScene::RayScene(const Scene& scene) : m_scene(scene) {
  m_device = rtcNewDevice(nullptr);
  if (!m_device) throw std::runtime_error("Embree: cannot create a device");
  m_rtc_scene = rtcNewScene(m_device);
  rtcSetSceneBuildQuality(m_rtc_scene, RTC_BUILD_QUALITY_HIGH);
  // Watertight intersection: no rays slipping between triangles, which
  // matters for shadow rays from points near edges and for scenes far from
  // the origin (measured: 47 leaking shadowed points at 1e4 offset → 4),
  // at no measurable cost in φ throughput.
  rtcSetSceneFlags(m_rtc_scene, RTC_SCENE_FLAG_ROBUST);
  RTCGeometry geom = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_TRIANGLE);
  // Shared buffers: Embree reads hilight's arrays in place. Vertex buffers
  // need 16 bytes of padding past the end, hence the copy with one spare float.
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                3 * sizeof(float), scene.positions.size()));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                  3 * sizeof(unsigned), scene.triangles.size()));
  if (!vertices || !indices) throw_device_error(m_device, "buffer allocation");
  for (size_t i = 0; i < scene.positions.size(); ++i)
    for (int k = 0; k < 3; ++k) vertices[3 * i + k] = scene.positions[i][k];
  for (size_t t = 0; t < scene.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) indices[3 * t + k] = scene.triangles[t][k];
  rtcCommitGeometry(geom);
  rtcAttachGeometry(m_rtc_scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(m_rtc_scene);
  if (rtcGetDeviceError(m_device) != RTC_ERROR_NONE) throw_device_error(m_device, "BVH build");
  // Offsets off surfaces: small against the scene, yet several float ulps of
  // its largest coordinate (a scene far from the origin has coarse floats).
  // Both relative, so a scene scaled by any k gets offsets scaled by k.
  float largest = std::max(glm::length(scene.bounds.lo), glm::length(scene.bounds.hi));
  m_epsilon = std::max({1e-5f * scene.diagonal(), 1e-6f * largest, std::numeric_limits<float>::min()});
  m_shading_step = std::max(kShadingStep * scene.diagonal(), 4.f * m_epsilon);
  m_face_normals.resize(scene.triangles.size());
  for (size_t t = 0; t < scene.triangles.size(); ++t) m_face_normals[t] = scene.face_normal(t);
  m_own_frame = hilight::own_frame(scene);
}

std::shared_ptr<const RayScene> RayScene::shared(std::shared_ptr<const Scene> scene) {
  // What keeps a shared RayScene's scene alive: a scene's address cannot be
  // reused while its RayScene is listed and live.
  struct Owned {
    std::shared_ptr<const Scene> scene;
    RayScene rays;
    explicit Owned(std::shared_ptr<const Scene> s) : scene(std::move(s)), rays(*scene) {}
  };
  static std::mutex mutex;
  static std::map<const Scene*, std::weak_ptr<const RayScene>> live;
  const std::lock_guard lock(mutex);
  std::erase_if(live, [](const auto& entry) { return entry.second.expired(); });
  if (const auto found = live.find(scene.get()); found != live.end())
    if (auto rays = found->second.lock()) return rays;
  const Scene* key = scene.get();
  auto owned = std::make_shared<const Owned>(std::move(scene));
  std::shared_ptr<const RayScene> rays(owned, &owned->rays);
  live[key] = rays;
  return rays;
}

RayScene::~RayScene() {
  if (m_rtc_scene) rtcReleaseScene(m_rtc_scene);
  if (m_device) rtcReleaseDevice(m_device);
}

Hit RayScene::intersect(const Vec3& origin, const Vec3& dir, float tfar) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  rh.ray.org_x = origin.x; rh.ray.org_y = origin.y; rh.ray.org_z = origin.z;
  rh.ray.dir_x = dir.x; rh.ray.dir_y = dir.y; rh.ray.dir_z = dir.z;
  rh.ray.tnear = 0.f;
  rh.ray.tfar = tfar;
  rh.ray.mask = 0xFFFFFFFFu;
  rh.ray.flags = 0;
  rh.ray.time = 0.f;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(m_rtc_scene, &context, &rh);
  Hit hit;
  if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
    hit.triangle = rh.hit.primID;
    hit.u = rh.hit.u;
    hit.v = rh.hit.v;
    hit.t = rh.ray.tfar;
  }
  return hit;
}

Vec3 RayScene::hit_position(const Hit& hit) const {
  const auto& tri = m_scene.triangles[hit.triangle];
  const auto& p = m_scene.positions;
  return (1.f - hit.u - hit.v) * p[tri[0]] + hit.u * p[tri[1]] + hit.v * p[tri[2]];
}

Vec3 RayScene::hit_normal(const Hit& hit) const {
  const auto& tri = m_scene.triangles[hit.triangle];
  const auto& n = m_scene.normals;
  Vec3 s = (1.f - hit.u - hit.v) * n[tri[0]] + hit.u * n[tri[1]] + hit.v * n[tri[2]];
  float len = glm::length(s);
  return len > 0.f ? s / len : m_scene.face_normal(hit.triangle);
}

} // namespace hilight

namespace hilight {

namespace {

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection
// 5.1.5), returned with its barycentric (u, v) for b and c.
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, float& u, float& v) {
  Vec3 ab = b - a, ac = c - a, ap = p - a;
  float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.f && d2 <= 0.f) { u = 0.f; v = 0.f; return a; }
  Vec3 bp = p - b;
  float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.f && d4 <= d3) { u = 1.f; v = 0.f; return b; }
  float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.f && d1 >= 0.f && d3 <= 0.f) { float w = d1 / (d1 - d3); u = w; v = 0.f; return a + w * ab; }
  Vec3 cp = p - c;
  float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.f && d5 <= d6) { u = 0.f; v = 1.f; return c; }
  float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.f && d2 >= 0.f && d6 <= 0.f) { float w = d2 / (d2 - d6); u = 0.f; v = w; return a + w * ac; }
  float va = d3 * d6 - d5 * d4;
  if (va <= 0.f && (d4 - d3) >= 0.f && (d5 - d6) >= 0.f) {
    float w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    u = 1.f - w; v = w;
    return b + w * (c - b);
  }
  float denom = 1.f / (va + vb + vc);
  u = vb * denom;  // weight of b
  v = vc * denom;  // weight of c
  return a + ab * u + ac * v;
}

/// Every triangle within the nearest distance + `tie` of `p`; the choice
/// among them is made after the query (closest_point), so it does not depend
/// on the order Embree visits them in, which changes when the scene turns.
struct ClosestQuery {
  const Scene* scene;
  Vec3 p;
  float tie;  ///< distances within this count as equal
  float limit;  ///< the farthest a candidate may be
  float nearest;
  struct Candidate {
    uint32_t triangle;
    float distance, u, v;
  };
  std::vector<Candidate> candidates;
};

bool closest_callback(RTCPointQueryFunctionArguments* args) {
  auto* q = static_cast<ClosestQuery*>(args->userPtr);
  const auto& tri = q->scene->triangles[args->primID];
  const auto& pos = q->scene->positions;
  float u, v;
  const float dist = glm::length(closest_on_triangle(q->p, pos[tri[0]], pos[tri[1]], pos[tri[2]], u, v) - q->p);
  if (dist > q->limit || dist > q->nearest + q->tie) return false;
  q->candidates.push_back({args->primID, dist, u, v});
  if (dist < q->nearest) {
    q->nearest = dist;
    args->query->radius = dist + q->tie;  // shrink the search, keeping ties in reach
    return true;
  }
  return false;
}

/// An order on face normals given in the scene's own frame: it does not
/// depend on how a face is cut into triangles (its pieces share its normal to
/// within rounding) nor on how the scene is turned (the frame turns with it).
/// Equally close, equally agreeing triangles are told apart by it.
bool normal_before(const Vec3& a, const Vec3& b) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(a[k] - b[k]) > 1e-4f) return a[k] > b[k];
  return false;
}

/// The sine of a facet's tilt against the tangent plane normal to n: 0 where
/// it has no wedge to speak of — tilted under 10⁻⁴ (a flat fan, but for
/// rounding) or nearly edge-on to the plane (not a height field over it).
float facet_tilt(const Vec3& face, const Vec3& n) {
  if (std::abs(glm::dot(face, n)) < 1e-3f) return 0.f;
  const float sine = glm::length(glm::cross(face, n));
  return sine >= 1e-4f ? sine : 0.f;
}

/// Where p lies on an edge of `tri` (within touch): the direction from that
/// edge into the triangle, perpendicular to it; nullopt off every edge (the
/// callers look at the corners first).
std::optional<Vec3> into_from_edge(const Scene& scene, const std::array<uint32_t, 3>& tri, const Vec3& p, float touch) {
  const auto& pos = scene.positions;
  for (int k = 0; k < 3; ++k) {
    const Vec3 a = pos[tri[k]], ab = pos[tri[(k + 1) % 3]] - a, ac = pos[tri[(k + 2) % 3]] - a;
    const float length2 = glm::dot(ab, ab);
    if (!(length2 > 0.f)) continue;
    const float along = glm::dot(p - a, ab) / length2;
    if (along < 0.f || along > 1.f || glm::length(a + along * ab - p) > touch) continue;
    return ac - (glm::dot(ac, ab) / length2) * ab;
  }
  return std::nullopt;
}

/// The mean of the unit directions from p into triangle `tri` over its angle
/// at p (∫ω dθ: 2 sin(α/2) along the bisector at a corner, 2 inward on an
/// edge); sets `inside` when p is inside it (the whole disk).
Vec3 angle_mean(const Scene& scene, const std::array<uint32_t, 3>& tri, const Vec3& p, float touch, bool& inside) {
  const auto& pos = scene.positions;
  for (int k = 0; k < 3; ++k)
    if (glm::length(pos[tri[k]] - p) <= touch) {
      const Vec3 to_b = pos[tri[(k + 1) % 3]] - p, to_c = pos[tri[(k + 2) % 3]] - p;
      const float lb = glm::length(to_b), lc = glm::length(to_c);
      if (!(lb > 0.f && lc > 0.f)) return Vec3(0.f);
      const Vec3 ub = to_b / lb, uc = to_c / lc, bisector = ub + uc;
      return glm::length(bisector) > 0.f ? glm::length(ub - uc) * glm::normalize(bisector) : Vec3(0.f);
    }
  if (const auto inward = into_from_edge(scene, tri, p, touch))
    return glm::length(*inward) > 0.f ? 2.f * glm::normalize(*inward) : Vec3(0.f);
  float u, v;
  inside = inside || glm::length(closest_on_triangle(p, pos[tri[0]], pos[tri[1]], pos[tri[2]], u, v) - p) <= touch;
  return Vec3(0.f);
}

struct OwnSurfaceQuery {
  const Scene* scene;
  const std::vector<Vec3>* face_normals;
  Vec3 p, normal;
  uint32_t own_triangle;
  float radius, same_position;
  bool foreign = false;
  float tilt = 0.f;        ///< the largest facet_tilt of an own triangle
  bool coplanar = true;    ///< every own triangle in own_triangle's plane
  bool inside = false;     ///< p inside an own triangle
  Vec3 around{0.f};        ///< the own triangles' angle_mean: 0 where they go all around p
  uint8_t tilted_count = 0;  ///< own triangles with a tilt (ShadingPoint::fan_size)
  std::array<uint32_t, ShadingPoint::kKeptFan> tilted{};
  void own(uint32_t triangle) {
    const Vec3& face = (*face_normals)[triangle];
    const float t = facet_tilt(face, normal);
    tilt = std::max(tilt, t);
    if (t > 0.f) keep_tilted(triangle);
    coplanar = coplanar && glm::dot(face, (*face_normals)[own_triangle]) >= 1.f - 1e-6f;
    around += angle_mean(*scene, scene->triangles[triangle], p, same_position, inside);
  }
  /// Keeps a tilted own triangle for the wedge test, once (a BVH may list a
  /// triangle twice); past kKeptFan of them the fan is looked up instead.
  void keep_tilted(uint32_t triangle) {
    if (tilted_count == ShadingPoint::kFanLookedUp) return;
    const auto kept = tilted.begin() + tilted_count;
    if (std::find(tilted.begin(), kept, triangle) != kept) return;
    if (tilted_count == ShadingPoint::kKeptFan) tilted_count = ShadingPoint::kFanLookedUp;
    else tilted[tilted_count++] = triangle;
  }
  /// One plane all around p: its wedge needs no look-up (ShadingPoint::flat_fan).
  bool flat() const { return coplanar && (inside || glm::length(around) < 0.05f); }
};

bool own_surface_callback(RTCPointQueryFunctionArguments* args) {
  auto* q = static_cast<OwnSurfaceQuery*>(args->userPtr);
  if (q->foreign) return false;
  if (args->primID == q->own_triangle) {
    q->own(args->primID);
    return false;
  }
  const auto& tri = q->scene->triangles[args->primID];
  const auto& pos = q->scene->positions;
  float u, v;
  Vec3 c = closest_on_triangle(q->p, pos[tri[0]], pos[tri[1]], pos[tri[2]], u, v);
  if (glm::length(c - q->p) > q->radius) return false;
  for (uint32_t w : tri)
    if (glm::length(pos[w] - q->p) <= q->same_position && glm::dot(q->scene->normals[w], q->normal) >= 0.999f) {
      q->own(args->primID);
      return false;
    }
  // Sharing an edge with the point's own triangle (the same two corners,
  // with the same normals) is the same smooth surface: a point on that edge
  // (a refined render's midpoint) is smooth as a vertex there would be.
  const auto& own = q->scene->triangles[q->own_triangle];
  int shared = 0;
  for (uint32_t w : tri)
    for (uint32_t o : own)
      shared += glm::length(pos[w] - pos[o]) <= q->same_position &&
                glm::dot(q->scene->normals[w], q->scene->normals[o]) >= 0.999f;
  if (shared >= 2) {
    q->own(args->primID);
    return false;
  }
  q->foreign = true;
  return false;
}

/// The wedge test of one smooth point against its own fan (in_own_wedge_slow).
struct WedgeQuery {
  const Scene* scene;
  const std::vector<Vec3>* face_normals;
  Vec3 p, n, dir;
  float radius, same_position;
  bool blocked = false;
};

/// Whether the direction `x`, in the plane of triangle `tri`, points into the
/// triangle from p: between the two edges at a corner, into the half-disk at
/// an edge, anywhere inside. False when the triangle does not touch p.
bool points_into(const Scene& scene, const std::array<uint32_t, 3>& tri, const Vec3& p, const Vec3& x, float touch) {
  const auto& pos = scene.positions;
  for (int k = 0; k < 3; ++k)
    if (glm::length(pos[tri[k]] - p) <= touch) {
      const Vec3 e1 = pos[tri[(k + 1) % 3]] - p, e2 = pos[tri[(k + 2) % 3]] - p, wound = glm::cross(e1, e2);
      return glm::dot(glm::cross(e1, x), wound) >= 0.f && glm::dot(glm::cross(x, e2), wound) >= 0.f;
    }
  if (const auto inward = into_from_edge(scene, tri, p, touch)) return glm::dot(x, *inward) >= 0.f;
  float u, v;
  return glm::length(closest_on_triangle(p, pos[tri[0]], pos[tri[1]], pos[tri[2]], u, v) - p) <= touch;
}

/// Whether facet `triangle` of the fan blocks q's direction: it lies under
/// dir and dir passes between it and the tangent plane.
bool facet_blocks(const WedgeQuery& q, uint32_t triangle) {
  const Vec3& face = (*q.face_normals)[triangle];
  if (facet_tilt(face, q.n) == 0.f) return false;  // no wedge under this facet
  const float facing = glm::dot(face, q.n);
  // dir moved along n into the facet's plane: the facet under dir, if it holds that.
  const Vec3 in_plane = q.dir - (glm::dot(face, q.dir) / facing) * q.n;
  if (!points_into(*q.scene, q.scene->triangles[triangle], q.p, in_plane, q.same_position)) return false;
  // On one side of the tangent plane and on the other of the facet (turned to agree with n).
  return glm::dot(q.n, q.dir) * glm::dot(face, q.dir) * facing < 0.f;
}

bool wedge_callback(RTCPointQueryFunctionArguments* args) {
  auto* q = static_cast<WedgeQuery*>(args->userPtr);
  q->blocked = q->blocked || facet_blocks(*q, args->primID);
  return false;
}

/// Where a crease or contact point is nudged, from the triangles touching p:
/// - `fan`: those in the plane of its chosen triangle (facing the same way),
///   each adding the mean of the unit directions over its wedge at p
///   (∫ ω dθ). The sum depends on the fan's angular span only, not on how it
///   is split into triangles, so a refined mesh nudges a point the way the
///   original does; it vanishes where the face goes on all around p.
/// - `away`: the other surfaces' normals laid into the plane (a leg standing
///   on a floor: away from the leg), for that case — one per plane, so that
///   a face cut into more triangles does not weigh more.
struct FanQuery {
  const Scene* scene;
  const std::vector<Vec3>* face_normals;
  Vec3 p, plane_normal;
  float touch;       ///< p lies on a triangle when this close to it
  float near;        ///< other surfaces this close count (within the nudge's step)
  Vec3 fan{0.f}, away{0.f};
  std::vector<glm::vec4> planes;  ///< the other surfaces' planes counted in `away` (normal, offset)
};

bool fan_callback(RTCPointQueryFunctionArguments* args) {
  auto* q = static_cast<FanQuery*>(args->userPtr);
  const auto& tri = q->scene->triangles[args->primID];
  const auto& pos = q->scene->positions;
  float u, v;
  const float distance = glm::length(closest_on_triangle(q->p, pos[tri[0]], pos[tri[1]], pos[tri[2]], u, v) - q->p);
  if (distance > q->near) return false;
  const Vec3& face = (*q->face_normals)[args->primID];
  const float facing = glm::dot(face, q->plane_normal);
  if (facing < 0.9999f || distance > q->touch) {
    if (facing >= 0.9999f) return false;  // the same face, not at p
    if (facing <= -0.9999f) return false;  // (a face's back, coplanar, says nothing)
    const float offset = glm::dot(face, pos[tri[0]]);
    for (const auto& known : q->planes)
      if (glm::length(Vec3(known) - face) < 1e-4f && std::abs(known.w - offset) <= q->touch) return false;
    q->planes.emplace_back(face, offset);
    q->away += face - facing * q->plane_normal;
    return false;
  }
  for (int k = 0; k < 3; ++k) {
    const Vec3 a = pos[tri[k]], b = pos[tri[(k + 1) % 3]], c = pos[tri[(k + 2) % 3]];
    const Vec3 to_b = b - q->p, to_c = c - q->p;
    if (glm::length(a - q->p) <= q->touch) {  // p at corner a: the wedge from ab to ac
      const float lb = glm::length(to_b), lc = glm::length(to_c);
      if (!(lb > 0.f && lc > 0.f)) return false;
      // 2 sin(α/2) along the bisector, where |ub − uc| = 2 sin(α/2): no acos,
      // whose rounding near 1 would keep a full disk's sum from vanishing.
      const Vec3 ub = to_b / lb, uc = to_c / lc;
      const Vec3 bisector = ub + uc;
      if (glm::length(bisector) > 0.f) q->fan += glm::length(ub - uc) * glm::normalize(bisector);
      return false;
    }
  }
  for (int k = 0; k < 3; ++k) {
    const Vec3 a = pos[tri[k]], b = pos[tri[(k + 1) % 3]], c = pos[tri[(k + 2) % 3]];
    const Vec3 ab = b - a;
    const float len = glm::length(ab);
    if (!(len > 0.f)) continue;
    const float along = glm::dot(q->p - a, ab) / (len * len);
    if (along < 0.f || along > 1.f || glm::length(a + along * ab - q->p) > q->touch) continue;
    // p on edge ab: the half-disk toward c, whose mean direction has length 2.
    Vec3 inward = (c - a) - glm::dot(c - a, ab / len) * (ab / len);
    const float height = glm::length(inward);
    if (height > 0.f) q->fan += 2.f * inward / height;
    return false;
  }
  return false;  // p inside the triangle: no edge here (a contact in the open face)
}

/// Calls `visit` (an Embree point-query callback) for the triangles within `radius` of `p`.
void query_triangles_near(RTCScene scene, const Vec3& p, float radius, RTCPointQueryFunction visit, void* state) {
  RTCPointQuery query;
  query.x = p.x; query.y = p.y; query.z = p.z;
  query.radius = radius;
  query.time = 0.f;
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(scene, &query, &context, visit, state);
}

} // namespace

Hit RayScene::closest_point(const Vec3& p, float max_distance, const Vec3& normal_hint, float tie) const {
  ClosestQuery q{&m_scene, p, tie >= 0.f ? tie : m_epsilon, max_distance, std::numeric_limits<float>::infinity(), {}};
  query_triangles_near(m_rtc_scene, p, max_distance, closest_callback, &q);
  // In triangle order, so that near-ties (the tests below are not transitive)
  // resolve the same whichever order they were found in.
  std::sort(q.candidates.begin(), q.candidates.end(), [](const auto& a, const auto& b) { return a.triangle < b.triangle; });
  // Of the triangles within the tie of the nearest, the one whose normal
  // agrees best with the hint; agreeing equally (a crease's vertex normal
  // bisects its faces: a mirror seam), the first in the own frame's order.
  const ClosestQuery::Candidate* best = nullptr;
  float best_alignment = -2.f;
  Vec3 best_face(0.f);
  for (const auto& c : q.candidates) {
    if (c.distance > q.nearest + q.tie) continue;
    const float alignment = glm::dot(normal_hint, m_face_normals[c.triangle]);
    const Vec3 face = m_own_frame.to_own(m_face_normals[c.triangle]);
    const bool better =
        !best || alignment > best_alignment + 1e-4f ||
        (alignment >= best_alignment - 1e-4f &&
         (normal_before(face, best_face) || (!normal_before(best_face, face) && c.distance < best->distance)));
    if (better) {
      best = &c;
      best_alignment = alignment;
      best_face = face;
    }
  }
  Hit hit;
  if (best) {
    hit.triangle = best->triangle;
    hit.u = best->u;
    hit.v = best->v;
    hit.t = best->distance;
  }
  return hit;
}

bool RayScene::only_own_surface_near(const Vec3& p, const Vec3& normal, uint32_t own_triangle, float radius,
                                     ShadingPoint* fan) const {
  OwnSurfaceQuery q{&m_scene, &m_face_normals, p, normal, own_triangle, radius, radius / 20.f};
  query_triangles_near(m_rtc_scene, p, radius, own_surface_callback, &q);
  if (fan && !q.foreign) {
    fan->wedge = q.tilt > 0.f ? q.tilt * 1.001f : 0.f;  // (a hair over: in_own_wedge_slow decides)
    fan->flat_fan = q.flat();
    fan->fan_size = q.tilted_count;
    fan->fan = q.tilted;
  }
  return !q.foreign;
}

bool RayScene::inside_solid(const Vec3& p) const {
  static const Vec3 kDirections[14] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1},
                                       {0.577f, 0.577f, 0.577f}, {-0.577f, 0.577f, 0.577f}, {0.577f, -0.577f, 0.577f},
                                       {0.577f, 0.577f, -0.577f}, {-0.577f, -0.577f, 0.577f}, {-0.577f, 0.577f, -0.577f},
                                       {0.577f, -0.577f, -0.577f}, {-0.577f, -0.577f, -0.577f}};
  int back = 0;
  for (const Vec3& d : kDirections) {
    Hit hit = intersect(p, glm::normalize(d));
    if (!hit.valid()) return false;  // open to the outside
    back += glm::dot(m_face_normals[hit.triangle], d) > 0.f;
  }
  return back > 7;
}

} // namespace hilight

namespace hilight {

ShadingPoint shading_point(const RayScene& rays, const Vec3& position, const Vec3& normal) {
  const Scene& scene = rays.scene();
  Hit h = rays.closest_point(position, 1e-3f * scene.diagonal(), normal);
  if (!h.valid()) return {position, false};
  ShadingPoint smooth{position, true, h.triangle};
  if (rays.only_own_surface_near(position, normal, h.triangle, 2.f * rays.epsilon(), &smooth)) return smooth;
  // Into the chosen triangle's face, away from the crease (or the touching
  // surface), a fixed step relative to the scene (RayScene::shading_step)
  // halved until the point is still on that face. All of it is the same on
  // any tessellation of the same faces, and at any scale.
  const Vec3 plane = rays.face_normals()[h.triangle];
  const Vec3 on = position - glm::dot(position - rays.hit_position(h), plane) * plane;
  const float touch = 0.5f * rays.epsilon(), full_step = rays.shading_step();
  FanQuery fan{&scene, &rays.face_normals(), on, plane, touch, full_step};
  query_triangles_near(rays.rtc_scene(), on, fan.near, fan_callback, &fan);
  // A crease's wedges sum to at least ~0.1 (a half-disk: 2); a face going on
  // all around sums to 0 but for rounding.
  const Vec3 direction = glm::length(fan.fan) > 0.05f ? fan.fan : fan.away;
  // The face goes on all around and nothing near gives a direction (a sheet
  // of its own back a hair away: a thin slab): no crease to step off, so the
  // point stays, on any tessellation of the face.
  if (glm::length(direction) <= 1e-3f) return {on, false, h.triangle};
  const Vec3 unit = glm::normalize(direction);
  for (float step = full_step; step > touch; step *= 0.5f) {
    const Vec3 q = on + step * unit;
    const Hit c = rays.closest_point(q, 2.f * touch, plane);
    if (c.valid() && glm::dot(rays.face_normals()[c.triangle], plane) >= 0.9999f) return {q, false, c.triangle};
  }
  // No step lands on the face (a sliver): toward the triangle's centroid.
  const auto& tri = scene.triangles[h.triangle];
  Vec3 to_centroid = (scene.positions[tri[0]] + scene.positions[tri[1]] + scene.positions[tri[2]]) / 3.f - position;
  float distance = glm::length(to_centroid);
  if (!(distance > 0.f)) return {position, false, h.triangle};
  float centroid_step = std::min(std::max(0.01f * distance, rays.shading_step()), 0.1f * distance);
  return {position + to_centroid * (centroid_step / distance), false, h.triangle};
}

bool in_own_wedge_slow(const RayScene& rays, const ShadingPoint& at, const Vec3& n, const Vec3& dir) {
  if (at.flat_fan) {  // one plane all around: the facet under dir is that plane
    const Vec3& face = rays.face_normals()[at.triangle];
    return glm::dot(n, dir) * glm::dot(face, dir) * glm::dot(face, n) < 0.f;
  }
  // The triangles that made the point smooth: within the same 2ε.
  const float radius = 2.f * rays.epsilon();
  WedgeQuery q{&rays.scene(), &rays.face_normals(), at.position, n, dir, radius, radius / 20.f};
  if (at.fan_size != ShadingPoint::kFanLookedUp) {
    for (uint8_t k = 0; k < at.fan_size && !q.blocked; ++k) q.blocked = facet_blocks(q, at.fan[k]);
    return q.blocked;
  }
  query_triangles_near(rays.rtc_scene(), at.position, radius, wedge_callback, &q);
  return q.blocked;
}

ShadingPoint smooth_hit_point(const RayScene& rays, const Hit& hit, float side) {
  const Scene& scene = rays.scene();
  const auto& tri = scene.triangles[hit.triangle];
  const Vec3 p = rays.hit_position(hit);
  const float b[3] = {1.f - hit.u - hit.v, hit.u, hit.v};
  Vec3 lifted(0.f);
  for (int k = 0; k < 3; ++k) {
    const Vec3 n = side * scene.normals[tri[k]];
    // Toward the vertex's tangent plane, and only outward: a convex part's
    // facets lie below the smooth surface, never above it.
    const float below = std::min(0.f, glm::dot(p - scene.positions[tri[k]], n));
    lifted += b[k] * (p - below * n);
  }
  return {lifted, true, hit.triangle};
}

} // namespace hilight
