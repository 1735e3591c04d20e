#include "ui/orbit_camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace hilight::painter::ui {

namespace {

float radians(float deg) { return deg * float(kPi) / 180.f; }
float degrees(float rad) { return rad * 180.f / float(kPi); }

} // namespace

OrbitCamera OrbitCamera::framing(const Bounds& bounds, float aspect) {
  return from_camera(Camera::framing(bounds, aspect), bounds.diagonal(), bounds.center());
}

OrbitCamera OrbitCamera::from_camera(const Camera& camera, float scene_diagonal, const Vec3& scene_centre) {
  OrbitCamera c;
  c.m_scene_diagonal = scene_diagonal > 0.f && std::isfinite(scene_diagonal) ? scene_diagonal : 1.f;
  c.m_scene_centre = is_finite(scene_centre) ? scene_centre : Vec3(0.f);
  c.m_target = is_finite(camera.target) ? camera.target : c.m_scene_centre;
  c.m_fov_deg = std::isfinite(camera.fov_deg) ? std::clamp(camera.fov_deg, 5.f, 120.f) : 50.f;
  // In double: the offset of far-apart finite points may overflow float.
  const DVec3 offset = DVec3(camera.eye) - DVec3(camera.target);
  const double length = glm::length(offset);
  const DVec3 d = length > 0.0 && std::isfinite(length) ? offset / length : DVec3(0.0, 0.0, 1.0);
  c.m_distance = float(std::clamp(std::isfinite(length) ? length : 0.0, 1e-4 * c.m_scene_diagonal,
                                  double(kMaxReach) * c.m_scene_diagonal));
  c.m_pitch_deg = std::clamp(degrees(float(std::asin(std::clamp(d.y, -1.0, 1.0)))), -80.f, 80.f);
  c.m_yaw_deg = degrees(float(std::atan2(d.x, d.z)));
  c.keep_near_scene();
  return c;
}

void OrbitCamera::keep_near_scene() {
  const DVec3 offset = DVec3(m_target) - DVec3(m_scene_centre);
  const double length = glm::length(offset);
  const double reach = double(kMaxReach) * m_scene_diagonal;
  if (!std::isfinite(length)) m_target = m_scene_centre;
  else if (length > reach) m_target = Vec3(DVec3(m_scene_centre) + offset * (reach / length));
}

Vec3 OrbitCamera::eye() const {
  float yaw = radians(m_yaw_deg), pitch = radians(m_pitch_deg);
  Vec3 d(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
  return m_target + m_distance * d;
}

Camera OrbitCamera::to_camera() const {
  Camera c;
  c.eye = eye();
  c.target = m_target;
  c.fov_deg = m_fov_deg;
  return c;
}

void OrbitCamera::orbit(float yaw_deg, float pitch_deg) {
  if (!std::isfinite(yaw_deg) || !std::isfinite(pitch_deg)) return;
  m_yaw_deg = std::fmod(m_yaw_deg + yaw_deg, 360.f);
  m_pitch_deg = std::clamp(m_pitch_deg + pitch_deg, -80.f, 80.f);
}

void OrbitCamera::pan(float right_fraction, float up_fraction) {
  Camera::Basis b = to_camera().basis();
  float height = 2.f * m_distance * std::tan(radians(m_fov_deg) / 2.f);
  const Vec3 moved = m_target + height * (right_fraction * b.right + up_fraction * b.up);
  if (is_finite(moved)) m_target = moved;
  keep_near_scene();
}

void OrbitCamera::zoom(float factor) {
  if (!(factor > 0.f) || !std::isfinite(factor)) return;
  m_distance = std::clamp(m_distance * factor, 1e-3f * m_scene_diagonal, 20.f * m_scene_diagonal);
}

glm::mat4 OrbitCamera::view() const { return glm::lookAt(eye(), m_target, Vec3(0.f, 1.f, 0.f)); }

glm::mat4 OrbitCamera::projection(float aspect) const {
  // Near plane relative to the orbit distance keeps depth precision where one looks.
  float near_plane = std::max(1e-4f * m_scene_diagonal, 0.01f * m_distance);
  float far_plane = m_distance + 4.f * m_scene_diagonal;
  return glm::perspective(radians(m_fov_deg), aspect, near_plane, far_plane);
}

Ray OrbitCamera::ray_through(float x, float y, float width, float height) const {
  Camera::Basis b = to_camera().basis();
  float aspect = width / std::max(height, 1.f);
  float sx = (2.f * x / width - 1.f) * b.tan_half_fov * aspect;
  float sy = (1.f - 2.f * y / height) * b.tan_half_fov;
  return {eye(), glm::normalize(b.forward + sx * b.right + sy * b.up)};
}

} // namespace hilight::painter::ui
