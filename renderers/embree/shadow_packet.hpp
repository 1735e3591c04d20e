#pragma once
/// Shadow rays traced 16 at a time (rtcOccluded16): the first bounce's
/// gather hits all send theirs to the same light, and Embree walks a packet
/// of them down the BVH together where one ray at a time would walk it 16
/// times. A lane's answer is the one rtcOccluded1 gives the same ray.
#include "direct_light.hpp"
#include "hilight/ray_scene.hpp"

#include <embree3/rtcore.h>

namespace hilight::embree {

class ShadowPacket {
public:
  static constexpr int kLanes = 16;

  explicit ShadowPacket(const RayScene& es) : m_es(es) { clear(); }

  int size() const { return m_size; }
  bool full() const { return m_size == kLanes; }
  /// Queues `ray` in the next lane.
  void add(const ShadowRay& ray) {
    const int k = m_size++;
    m_rays.org_x[k] = ray.origin.x;
    m_rays.org_y[k] = ray.origin.y;
    m_rays.org_z[k] = ray.origin.z;
    m_rays.dir_x[k] = ray.dir.x;
    m_rays.dir_y[k] = ray.dir.y;
    m_rays.dir_z[k] = ray.dir.z;
    m_rays.tnear[k] = 0.f;
    m_rays.tfar[k] = ray.tfar;
    m_rays.mask[k] = 0xFFFFFFFFu;
    m_rays.flags[k] = 0;
    m_rays.time[k] = 0.f;
    m_valid[k] = -1;
  }
  /// Traces the queued lanes (counted in `rays`); blocked() then answers.
  void trace(uint64_t& rays) {
    if (m_size == 0) return;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcOccluded16(m_valid, m_es.rtc_scene(), &context, &m_rays);
    rays += uint64_t(m_size);
  }
  bool blocked(int lane) const { return m_rays.tfar[lane] < 0.f; }
  void clear() {
    m_size = 0;
    for (int k = 0; k < kLanes; ++k) m_valid[k] = 0;
  }

private:
  const RayScene& m_es;
  int m_size = 0;
  alignas(64) int m_valid[kLanes];
  RTCRay16 m_rays;
};

} // namespace hilight::embree
