#pragma once
/// "Objects" of a scene for the shadow tools: connected pieces of mesh that
/// share a material. Scenes keep no object ids, but a loaded model's objects
/// usually carry their own material and the builders give each box its own,
/// so a box resting on a floor stays apart from the floor even where their
/// vertices touch. Connectivity is by vertex position (welded), because the
/// tessellation splits vertices at creases (a box's faces share no index).
#include "hilight/scene.hpp"

#include <cstdint>
#include <vector>

namespace hilight::painter {

class SceneObjects {
public:
  explicit SceneObjects(const Scene& scene);

  size_t count() const { return m_centres.size(); }
  /// Object of triangle t.
  uint32_t object_of_triangle(size_t t) const { return m_triangle_object[t]; }
  /// Object of vertex v (of the first triangle that uses it).
  uint32_t object_of_vertex(size_t v) const { return m_vertex_object[v]; }
  /// Centre of the object's bounding box (the paper's "occluder centre").
  const Vec3& centre(uint32_t object) const { return m_centres[object]; }
  const Bounds& bounds(uint32_t object) const { return m_bounds[object]; }
  /// Material name of the object (for labels in the UI).
  const std::string& name(uint32_t object) const { return m_names[object]; }
  /// Triangles of the object.
  std::vector<uint32_t> triangles(uint32_t object) const;

private:
  std::vector<uint32_t> m_triangle_object, m_vertex_object;
  std::vector<Vec3> m_centres;
  std::vector<Bounds> m_bounds;
  std::vector<std::string> m_names;
};

} // namespace hilight::painter
