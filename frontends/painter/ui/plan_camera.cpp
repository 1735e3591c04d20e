#include "ui/plan_camera.hpp"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

namespace hilight::painter::ui {

PlanCamera::PlanCamera(const Bounds& area, float scene_diagonal) {
  const Vec3 c = area.center();
  const float margin = 1.05f;
  m_half_x = std::max(0.5f * (area.hi.x - area.lo.x) * margin, 1e-3f);
  m_half_z = std::max(0.5f * (area.hi.z - area.lo.z) * margin, 1e-3f);
  // Above everything in the scene, so nothing is cut by the near plane (the section cuts).
  const float d = std::max(scene_diagonal, 1e-3f);
  m_eye = Vec3(c.x, area.hi.y + d, c.z);
  m_bottom = area.lo.y;
  m_depth = (m_eye.y - area.lo.y) + 2.f * d;
}

glm::vec2 PlanCamera::half_extent(float aspect) const {
  // x across the window, z up it: widen whichever is short for the window's shape.
  const float a = std::max(aspect, 1e-3f);
  return {std::max(m_half_x, m_half_z * a), std::max(m_half_z, m_half_x / a)};
}

glm::mat4 PlanCamera::view() const { return glm::lookAt(m_eye, target(), Vec3(0.f, 0.f, -1.f)); }

glm::mat4 PlanCamera::projection(float aspect) const {
  const glm::vec2 h = half_extent(aspect);
  return glm::ortho(-h.x, h.x, -h.y, h.y, 1e-3f * m_depth, m_depth);
}

Ray PlanCamera::ray_through(float x, float y, float width, float height, float aspect) const {
  const glm::vec2 h = half_extent(aspect);
  const float sx = (2.f * x / std::max(width, 1.f) - 1.f) * h.x;
  const float sy = (1.f - 2.f * y / std::max(height, 1.f)) * h.y;  // up the window is −Z
  return {m_eye + Vec3(sx, 0.f, -sy), Vec3(0.f, -1.f, 0.f)};
}

} // namespace hilight::painter::ui
