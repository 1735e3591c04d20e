#pragma once
/// The scene's triangles on the GPU with one display colour per vertex (the
/// colours change with the view mode and the lights; the geometry never does).
#include "hilight/scene.hpp"
#include "ui/gl_program.hpp"

#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <vector>

namespace hilight::painter::ui {

/// What one vertex shows: linear display RGB in [0, 1] (already exposed and
/// tone-mapped; the shader only encodes sRGB) and whether to hatch it, which
/// marks "don't care" in the target view.
struct VertexColour {
  glm::vec3 rgb{0.f};
  float hatch = 0.f;  ///< 1: "don't care" (darker stripes); kUnreachableHatch: painted light no light may reach
};
/// VertexColour::hatch of a painted point no allowed place sees: magenta stripes.
constexpr float kUnreachableHatch = 2.f;

class SceneMesh {
public:
  explicit SceneMesh(const Scene& scene);
  ~SceneMesh();
  SceneMesh(const SceneMesh&) = delete;
  SceneMesh& operator=(const SceneMesh&) = delete;

  /// One entry per scene vertex.
  void set_colours(const std::vector<VertexColour>& colours);
  /// Draws only the triangles with `shown[t]` set (the cutaway); empty: all.
  void set_shown_triangles(const Scene& scene, const std::vector<uint8_t>& shown);
  /// Clips everything above this height (the section); nullopt: nothing.
  void set_section(std::optional<float> height) { m_section = height; }
  /// Back faces are culled: rooms are wound inward, so from outside one sees
  /// in through the near walls, and each vertex's colour is that of the side
  /// its normal faces.
  void draw(const glm::mat4& view_projection) const;

private:
  GLuint m_vao = 0, m_positions = 0, m_colours = 0, m_indices = 0;
  GLsizei m_index_count = 0;
  size_t m_vertex_count = 0;
  std::optional<float> m_section;
  std::unique_ptr<GlProgram> m_program;
};

} // namespace hilight::painter::ui
