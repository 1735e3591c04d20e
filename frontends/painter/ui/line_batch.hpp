#pragma once
/// Overlays drawn over the scene each frame: line segments and round points
/// (light markers, spot cones, the brush ring, shadow candidates). Parts
/// hidden behind surfaces are drawn faintly, so lights inside a room stay
/// visible from outside it.
#include "ui/gl_program.hpp"

#include <glm/glm.hpp>
#include <memory>
#include <vector>

namespace hilight::painter::ui {

class LineBatch {
public:
  LineBatch();
  ~LineBatch();
  LineBatch(const LineBatch&) = delete;
  LineBatch& operator=(const LineBatch&) = delete;

  void clear();
  void line(const glm::vec3& a, const glm::vec3& b, const glm::vec4& colour);
  /// A screen-sized dot of `size_px` pixels.
  void point(const glm::vec3& p, const glm::vec4& colour, float size_px);
  /// A circle of `radius` around `centre` in the plane normal to `normal`.
  void circle(const glm::vec3& centre, const glm::vec3& normal, float radius, const glm::vec4& colour, int segments = 48);
  void draw(const glm::mat4& view_projection);
  /// True if the lines or points differ from those of the last draw().
  bool changed_since_draw() const;

private:
  struct Vertex {
    glm::vec3 position;
    glm::vec4 colour;
    float size;
  };
  void draw_pass(GLenum mode, const std::vector<Vertex>& vertices, float alpha_scale);

  std::vector<Vertex> m_lines, m_points;
  std::vector<Vertex> m_drawn_lines, m_drawn_points;
  GLuint m_vao = 0, m_buffer = 0;
  std::unique_ptr<GlProgram> m_program;
};

} // namespace hilight::painter::ui
