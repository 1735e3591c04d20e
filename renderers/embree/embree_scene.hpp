#pragma once
/// RAII wrapper of an Embree device and the BVH of one hilight Scene, with the
/// two queries the renderer needs. Inline so the hot loops have no call
/// overhead beyond Embree's own.
#include "hilight/scene.hpp"

#include <embree3/rtcore.h>

namespace hilight::embree {

struct Hit {
  uint32_t triangle = RTC_INVALID_GEOMETRY_ID;
  float u = 0.f, v = 0.f, t = 0.f;
  bool valid() const { return triangle != RTC_INVALID_GEOMETRY_ID; }
};

class EmbreeScene {
public:
  explicit EmbreeScene(const Scene& scene);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  const Scene& scene() const { return m_scene; }
  /// Offset used to lift ray origins off the surface (scene-relative).
  float epsilon() const { return m_epsilon; }

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

  RTCScene rtc_scene() const { return m_rtc_scene; }

private:
  const Scene& m_scene;
  RTCDevice m_device = nullptr;
  RTCScene m_rtc_scene = nullptr;
  float m_epsilon = 1e-4f;
};

} // namespace hilight::embree
