#pragma once
/// The plan view (issue 20): an orthographic top view of an area of the
/// scene — the whole building, or the focused rooms — with north (−Z) up.
/// Fixed by the area, so its screenshots do not depend on the orbit camera.
#include "hilight/math.hpp"
#include "ui/orbit_camera.hpp"

#include <glm/glm.hpp>

namespace hilight::painter::ui {

class PlanCamera {
public:
  /// Frames `area` (its x–z extent, with a 5% margin) seen from above.
  PlanCamera(const Bounds& area, float scene_diagonal);

  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;
  /// The straight-down ray through window pixel (x, y) (top-left origin).
  Ray ray_through(float x, float y, float width, float height, float aspect) const;
  /// Above the area, looking down at its bottom's centre (the cutaway's eye and focus).
  Vec3 eye() const { return m_eye; }
  Vec3 target() const { return Vec3(m_eye.x, m_bottom, m_eye.z); }

private:
  /// Half the extent shown at `aspect`: the area fits both ways.
  glm::vec2 half_extent(float aspect) const;
  Vec3 m_eye{0.f};
  float m_bottom = 0.f, m_half_x = 1.f, m_half_z = 1.f, m_depth = 1.f;
};

} // namespace hilight::painter::ui
