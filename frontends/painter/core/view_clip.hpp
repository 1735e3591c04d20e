#pragma once
/// What the view hides inside a building (issue 20): a horizontal section
/// (everything above a height) and the cutaway (ceilings and walls between
/// the camera and the point it looks at, the doll's-house view). Hidden
/// surfaces stay in the scene — they cast shadows and bounce light — only
/// the view, picking and painting skip them.
#include "hilight/scene.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace hilight::painter {

struct ViewClip {
  std::optional<float> section;  ///< world height (+Y up): surfaces above it are clipped
  bool cutaway = false;

  bool any() const { return section.has_value() || cutaway; }
  bool operator==(const ViewClip&) const = default;
};

/// Which triangles and vertices the view shows, for one clip and camera.
/// Default-constructed: everything.
class Visibility {
public:
  Visibility() = default;
  /// `eye`, `focus`: the camera's eye and the point it looks at (the orbit
  /// target), which the cutaway uses. A triangle is cut away when its plane
  /// separates the eye from the focus and some corner of it is nearer the
  /// eye (along the view) than the focus: a wall or ceiling in front of the
  /// room in view. A surface through the focus (the floor one looks at) stays.
  static Visibility compute(const Scene& scene, const ViewClip& clip, const Vec3& eye, const Vec3& focus);

  bool all_visible() const { return m_triangles.empty() && !m_section; }
  /// The triangle is drawn (a triangle crossing the section is drawn clipped).
  bool triangle(uint32_t t) const { return m_triangles.empty() || m_triangles[t]; }
  /// The vertex can take paint: below the section and on a shown triangle.
  bool vertex(uint32_t v) const { return m_vertices.empty() || m_vertices[v]; }
  /// A point on triangle `t` is seen (picking: the section cuts triangles through).
  bool point(uint32_t t, const Vec3& p) const { return triangle(t) && (!m_section || p.y <= *m_section); }
  /// Per triangle, 1 = shown (empty: all).
  const std::vector<uint8_t>& triangles() const { return m_triangles; }

private:
  std::vector<uint8_t> m_triangles, m_vertices;
  std::optional<float> m_section;
};

} // namespace hilight::painter
