#include "embree_scene.hpp"

#include <stdexcept>
#include <string>

namespace hilight::embree {

namespace {
void throw_device_error(RTCDevice device, const char* what) {
  throw std::runtime_error(std::string("Embree: ") + what + " failed (error " + std::to_string(int(rtcGetDeviceError(device))) + ")");
}
} // namespace

EmbreeScene::EmbreeScene(const Scene& scene) : m_scene(scene) {
  m_device = rtcNewDevice(nullptr);
  if (!m_device) throw std::runtime_error("Embree: cannot create a device");
  m_rtc_scene = rtcNewScene(m_device);
  rtcSetSceneBuildQuality(m_rtc_scene, RTC_BUILD_QUALITY_HIGH);
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
  m_epsilon = std::max(1e-6f, 1e-5f * scene.diagonal());
}

EmbreeScene::~EmbreeScene() {
  if (m_rtc_scene) rtcReleaseScene(m_rtc_scene);
  if (m_device) rtcReleaseDevice(m_device);
}

Hit EmbreeScene::intersect(const Vec3& origin, const Vec3& dir, float tfar) const {
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

Vec3 EmbreeScene::hit_position(const Hit& hit) const {
  const auto& tri = m_scene.triangles[hit.triangle];
  const auto& p = m_scene.positions;
  return (1.f - hit.u - hit.v) * p[tri[0]] + hit.u * p[tri[1]] + hit.v * p[tri[2]];
}

Vec3 EmbreeScene::hit_normal(const Hit& hit) const {
  const auto& tri = m_scene.triangles[hit.triangle];
  const auto& n = m_scene.normals;
  Vec3 s = (1.f - hit.u - hit.v) * n[tri[0]] + hit.u * n[tri[1]] + hit.v * n[tri[2]];
  float len = glm::length(s);
  return len > 0.f ? s / len : m_scene.face_normal(hit.triangle);
}

} // namespace hilight::embree
