#include "hot_spots.hpp"
#include "shadow_packet.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hilight::embree {

namespace {

constexpr int G = HotSpots::kCellsPerFace, S = HotSpots::kSubSamples;

/// The direction through (u, v) ∈ [-1, 1]² on cube face `face` (axis face/2, sign by face%2).
Vec3 cube_direction(int face, float u, float v) {
  const int axis = face / 2;
  const float sign = face % 2 ? -1.f : 1.f;
  Vec3 d(0.f);
  d[axis] = sign;
  d[(axis + 1) % 3] = u;
  d[(axis + 2) % 3] = v;
  return glm::normalize(d);
}

struct SubHit {
  bool hit = false;
  float distance = 0.f;
  Vec3 position{0.f}, normal{0.f};  ///< normal: the side facing the light
  Rgb flux{0.f};
};

} // namespace

int HotSpots::cell_of(const Vec3& world) const {
  const Vec3 d = m_frame.to_own(world);
  const Vec3 a = glm::abs(d);
  const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
  const int face = 2 * axis + (d[axis] < 0.f ? 1 : 0);
  const float u = d[(axis + 1) % 3] / a[axis], v = d[(axis + 2) % 3] / a[axis];
  const int i = std::clamp(int((u + 1.f) * 0.5f * float(G)), 0, G - 1), j = std::clamp(int((v + 1.f) * 0.5f * float(G)), 0, G - 1);
  return (face * G + i) * G + j;
}

HotSpots::HotSpots(const RayScene& rays, const PreparedLight& light, bool every_cell, uint64_t& cast)
    : m_light(light.position), m_frame(rays.own_frame()) {
  const Scene& scene = rays.scene();
  const int cells = 6 * G * G;
  std::vector<SubHit> sub(size_t(cells) * S * S);
  float nearest = std::numeric_limits<float>::max();
  const float step = 2.f / float(G * S);
  for (int c = 0; c < cells; ++c) {
    const int face = c / (G * G), i = (c / G) % G, j = c % G;
    for (int a = 0; a < S; ++a)
      for (int b = 0; b < S; ++b) {
        const float u = -1.f + (float(i * S + a) + 0.5f) * step, v = -1.f + (float(j * S + b) + 0.5f) * step;
        const Vec3 dir = m_frame.to_world(cube_direction(face, u, v));
        SubHit& s = sub[(size_t(c) * S + a) * S + b];
        ++cast;
        const Hit hit = rays.intersect(light.position, dir);
        if (!hit.valid()) continue;
        s.hit = true;
        s.distance = hit.t;
        s.position = rays.hit_position(hit);
        const Vec3& ng = rays.face_normals()[hit.triangle];
        s.normal = glm::dot(ng, dir) < 0.f ? ng : -ng;
        // E dA = I · S · dω on the first surface a direction meets.
        const float solid_angle = step * step / std::pow(1.f + u * u + v * v, 1.5f);
        s.flux = scene.triangle_albedo(hit.triangle) * (light.angular(dir) * solid_angle);
        nearest = std::min(nearest, s.distance);
      }
  }
  if (nearest == std::numeric_limits<float>::max()) return;
  // Hot: much nearer than the light's typical surface (so much brighter than
  // what the gather sees elsewhere). A light mid-room has no hot patches.
  // Over the directions that meet a surface: above an open floor half miss.
  std::vector<float> distances;
  for (const SubHit& h : sub)
    if (h.hit) distances.push_back(h.distance);
  std::nth_element(distances.begin(), distances.begin() + long(distances.size() / 2), distances.end());
  const float hot_reach = std::min(5.f * nearest, kHotFraction * distances[distances.size() / 2]);
  const float reach = every_cell ? std::numeric_limits<float>::max() : hot_reach;
  m_reach2 = reach < std::numeric_limits<float>::max() ? reach * reach : std::numeric_limits<float>::max();
  m_hot2 = hot_reach * hot_reach;
  m_cell.assign(size_t(cells), {});
  const float lift = 1e-3f * scene.diagonal();
  for (int c = 0; c < cells; ++c) {
    const SubHit* s = &sub[size_t(c) * S * S];
    // The cell's lit surfaces within reach, sorted into planes (Plane::holds,
    // first plane first); a plane met by kMinRays or more becomes a patch.
    // Gather hits are sorted by the same rule (handles()), so a patch takes
    // over exactly the hits on the surfaces whose flux it carries.
    std::array<int, S * S> plane_of;
    plane_of.fill(-1);
    int planes = 0;
    for (int seed = 0; seed < S * S && planes < kPlanesPerCell; ++seed) {
      if (plane_of[seed] != -1 || !s[seed].hit || !(s[seed].distance < reach)) continue;
      Plane& plane = m_cell[size_t(c)][size_t(planes)];
      plane.point = s[seed].position;
      plane.normal = s[seed].normal;
      plane.thickness = kPlaneTolerance * s[seed].distance;
      plane.hot = s[seed].distance < hot_reach;
      int members = 0;
      for (int k = seed; k < S * S; ++k)
        if (plane_of[k] == -1 && s[k].hit && s[k].distance < reach &&
            plane.holds(s[k].position, s[k].normal, s[k].distance < hot_reach))
          plane_of[k] = planes, ++members;
      const int index = planes++;
      Rgb flux(0.f);
      Vec3 centre(0.f), normal(0.f);
      float weight = 0.f;
      for (int k = 0; k < S * S; ++k) {
        if (plane_of[k] != index) continue;
        const float w = s[k].flux.r + s[k].flux.g + s[k].flux.b;
        flux += s[k].flux;
        centre += w * s[k].position;
        normal += w * s[k].normal;
        weight += w;
      }
      if (members < kMinRays || !(weight > 0.f) || !(glm::length(normal) > 0.f)) continue;  // too few rays to speak for it
      centre /= weight;
      normal = glm::normalize(normal);
      float radius = 0.f;
      for (int k = 0; k < S * S; ++k)
        if (plane_of[k] == index) radius = std::max(radius, glm::length(s[k].position - centre));
      // A hot patch's fireflies matter more than its point-light shadow.
      const float radii = plane.hot ? kHotNearRadii : kNearRadii;
      const float near = radii * std::max(radius, lift);
      plane.patch = int32_t(m_patches.size());
      m_patches.push_back({centre + lift * normal, normal, flux, near * near});
    }
  }
}

bool HotSpots::handles(const Vec3& x, const Vec3& y, const Vec3& face_normal) const {
  if (m_patches.empty()) return false;
  const Vec3 d = y - m_light;
  const float d2 = glm::dot(d, d);
  if (d2 >= m_reach2 || !(d2 > 0.f)) return false;
  const Vec3 n = glm::dot(face_normal, d) < 0.f ? face_normal : -face_normal;  // the side facing the light
  const bool hot = d2 < m_hot2;
  for (const Plane& plane : m_cell[size_t(cell_of(d))]) {
    if (!plane.holds(y, n, hot)) continue;
    if (plane.patch < 0) return false;
    const Vec3 w = m_patches[size_t(plane.patch)].position - x;
    return glm::dot(w, w) > m_patches[size_t(plane.patch)].near2;
  }
  return false;
}

namespace {

/// Φ cosθ_patch |cosθ_x| / (π r²), or 0 when the point is behind the patch
/// or within its near distance; `dir` and `r` are set for the shadow ray.
template <class Patch>
float patch_factor(const Patch& p, const ShadingPoint& at, const Vec3& n, Vec3& dir, float& r, float& cos_point) {
  const Vec3 w = p.position - at.position;
  const float r2 = glm::dot(w, w);
  if (!(r2 > p.near2)) return 0.f;
  r = std::sqrt(r2);
  dir = w / r;
  const float cos_patch = -glm::dot(p.normal, dir);  // the patch shines to its lit side
  cos_point = glm::dot(n, dir);
  if (cos_patch <= 0.f || cos_point == 0.f) return 0.f;
  return cos_patch * std::abs(cos_point) / (float(kPi) * r2);
}

} // namespace

bool HotSpots::sees_light(const RayScene& rays, const ShadingPoint& at, const Vec3& n, uint64_t& cast) const {
  if (m_patches.empty()) return false;
  const Vec3 w = m_light - at.position;
  const float r = glm::length(w);
  if (!(r > 2.f * rays.epsilon())) return false;
  const Vec3 dir = w / r;
  ++cast;
  return !rays.occluded(at.ray_start(dir, glm::dot(n, dir) >= 0.f ? n : -n, rays.epsilon()), dir, r - 2.f * rays.epsilon());
}

Rgb HotSpots::irradiance_seen(const ShadingPoint& at, const Vec3& n, bool sees) const {
  Rgb e(0.f);
  if (!sees) return e;
  for (const Patch& p : m_patches) {
    Vec3 dir;
    float r, cos_point;
    const float f = patch_factor(p, at, n, dir, r, cos_point);
    if (f > 0.f) e += p.flux * f;
  }
  return e;
}

Rgb HotSpots::irradiance(const RayScene& rays, const ShadingPoint& at, const Vec3& n, uint64_t& cast) const {
  // The point's shadow rays to its patches leave from one place: Embree
  // takes them 16 at a time (ShadowPacket). The seen patches' light is
  // summed in the patches' order, as one ray at a time would sum it.
  Rgb e(0.f);
  const float eps = rays.epsilon();
  ShadowPacket packet(rays);
  Rgb lane_light[ShadowPacket::kLanes];
  const auto add_seen = [&] {
    packet.trace(cast);
    for (int k = 0; k < packet.size(); ++k)
      if (!packet.blocked(k)) e += lane_light[k];
    packet.clear();
  };
  for (const Patch& p : m_patches) {
    Vec3 dir;
    float r, cos_point;
    const float f = patch_factor(p, at, n, dir, r, cos_point);
    if (!(f > 0.f)) continue;
    lane_light[packet.size()] = p.flux * f;
    packet.add(ShadowRay{at.ray_start(dir, cos_point > 0.f ? n : -n, eps), dir, r - 2.f * eps});
    if (packet.full()) add_seen();
  }
  add_seen();
  return e;
}

} // namespace hilight::embree
