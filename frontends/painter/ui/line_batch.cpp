#include "ui/line_batch.hpp"

#include <cmath>
#include <cstddef>
#include <cstring>

namespace hilight::painter::ui {

namespace {

const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 colour;
layout(location = 2) in float size;
uniform mat4 view_projection;
uniform float alpha_scale;
out vec4 v_colour;
void main() {
  v_colour = vec4(colour.rgb, colour.a * alpha_scale);
  gl_PointSize = size;
  gl_Position = view_projection * vec4(position, 1.0);
}
)";

const char* kFragmentShader = R"(#version 330 core
in vec4 v_colour;
out vec4 frag;
uniform float round_points;
void main() {
  if (round_points > 0.5 && length(gl_PointCoord - vec2(0.5)) > 0.5) discard;
  frag = v_colour;
}
)";

constexpr float kTwoPi = 6.28318530718f;

} // namespace

LineBatch::LineBatch() {
  m_program = std::make_unique<GlProgram>(kVertexShader, kFragmentShader);
  glGenVertexArrays(1, &m_vao);
  glGenBuffers(1, &m_buffer);
  glBindVertexArray(m_vao);
  glBindBuffer(GL_ARRAY_BUFFER, m_buffer);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, colour)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, size)));
  glBindVertexArray(0);
}

LineBatch::~LineBatch() {
  glDeleteBuffers(1, &m_buffer);
  glDeleteVertexArrays(1, &m_vao);
}

void LineBatch::clear() {
  m_lines.clear();
  m_points.clear();
}

void LineBatch::line(const glm::vec3& a, const glm::vec3& b, const glm::vec4& colour) {
  m_lines.push_back({a, colour, 1.f});
  m_lines.push_back({b, colour, 1.f});
}

void LineBatch::point(const glm::vec3& p, const glm::vec4& colour, float size_px) { m_points.push_back({p, colour, size_px}); }

void LineBatch::circle(const glm::vec3& centre, const glm::vec3& normal, float radius, const glm::vec4& colour,
                       int segments) {
  glm::vec3 n = glm::normalize(normal);
  glm::vec3 helper = std::abs(n.y) < 0.9f ? glm::vec3(0.f, 1.f, 0.f) : glm::vec3(1.f, 0.f, 0.f);
  glm::vec3 u = glm::normalize(glm::cross(n, helper)), v = glm::cross(n, u);
  for (int i = 0; i < segments; ++i) {
    float a0 = kTwoPi * float(i) / float(segments), a1 = kTwoPi * float(i + 1) / float(segments);
    line(centre + radius * (std::cos(a0) * u + std::sin(a0) * v), centre + radius * (std::cos(a1) * u + std::sin(a1) * v),
         colour);
  }
}

void LineBatch::draw_pass(GLenum mode, const std::vector<Vertex>& vertices, float alpha_scale) {
  if (vertices.empty()) return;
  m_program->set("alpha_scale", alpha_scale);
  m_program->set("round_points", mode == GL_POINTS ? 1.f : 0.f);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(), GL_STREAM_DRAW);
  glDrawArrays(mode, 0, GLsizei(vertices.size()));
}

namespace {

template <typename T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

} // namespace

bool LineBatch::changed_since_draw() const { return !same_bytes(m_lines, m_drawn_lines) || !same_bytes(m_points, m_drawn_points); }

void LineBatch::draw(const glm::mat4& view_projection) {
  m_drawn_lines = m_lines;
  m_drawn_points = m_points;
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_PROGRAM_POINT_SIZE);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  m_program->use();
  m_program->set("view_projection", view_projection);
  glBindVertexArray(m_vao);
  glBindBuffer(GL_ARRAY_BUFFER, m_buffer);
  // Hidden parts first, faint; then the visible parts on top.
  glDepthFunc(GL_GREATER);
  draw_pass(GL_LINES, m_lines, 0.3f);
  draw_pass(GL_POINTS, m_points, 0.3f);
  glDepthFunc(GL_LEQUAL);
  draw_pass(GL_LINES, m_lines, 1.f);
  draw_pass(GL_POINTS, m_points, 1.f);
  glBindVertexArray(0);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glDisable(GL_BLEND);
}

} // namespace hilight::painter::ui
