#include "core/view_clip.hpp"

#include <algorithm>

namespace hilight::painter {

namespace {

/// Cut away: the triangle's plane separates eye and focus, and the triangle
/// reaches in front of the focus along the view.
bool cut_away(const Scene& scene, const std::array<uint32_t, 3>& tri, const Vec3& eye, const Vec3& focus, const Vec3& view,
              float focus_depth, float tolerance) {
  const Vec3& a = scene.positions[tri[0]];
  const Vec3& b = scene.positions[tri[1]];
  const Vec3& c = scene.positions[tri[2]];
  const Vec3 cross = glm::cross(b - a, c - a);
  const float length = glm::length(cross);
  if (!(length > 0.f)) return false;
  const Vec3 n = cross / length;
  const float eye_side = glm::dot(n, eye - a), focus_side = glm::dot(n, focus - a);
  // A surface through the focus (within the tolerance) is what one looks at.
  const bool separates = (eye_side > tolerance && focus_side < -tolerance) || (eye_side < -tolerance && focus_side > tolerance);
  if (!separates) return false;
  const float nearest = std::min({glm::dot(a - eye, view), glm::dot(b - eye, view), glm::dot(c - eye, view)});
  return nearest < focus_depth;
}

} // namespace

Visibility Visibility::compute(const Scene& scene, const ViewClip& clip, const Vec3& eye, const Vec3& focus) {
  Visibility out;
  out.m_section = clip.section;
  if (!clip.any()) return out;
  const size_t triangles = scene.triangles.size(), vertices = scene.positions.size();
  out.m_triangles.assign(triangles, 1);
  out.m_vertices.assign(vertices, 0);
  const float tolerance = 1e-4f * scene.diagonal();
  const Vec3 to_focus = focus - eye;
  const float focus_depth = glm::length(to_focus);
  const bool cutaway = clip.cutaway && focus_depth > 0.f;
  const Vec3 view = cutaway ? to_focus / focus_depth : Vec3(0.f, 0.f, -1.f);
  auto below = [&](uint32_t v) { return !clip.section || scene.positions[v].y <= *clip.section; };
  for (size_t t = 0; t < triangles; ++t) {
    const auto& tri = scene.triangles[t];
    if (cutaway && cut_away(scene, tri, eye, focus, view, focus_depth, tolerance)) {
      out.m_triangles[t] = 0;
      continue;
    }
    if (!below(tri[0]) && !below(tri[1]) && !below(tri[2])) {
      out.m_triangles[t] = 0;
      continue;
    }
    for (uint32_t v : tri) out.m_vertices[v] = out.m_vertices[v] || below(v);
  }
  return out;
}

} // namespace hilight::painter
