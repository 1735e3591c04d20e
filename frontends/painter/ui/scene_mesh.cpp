#include "ui/scene_mesh.hpp"

#include <stdexcept>

namespace hilight::painter::ui {

namespace {

const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 colour;
uniform mat4 view_projection;
uniform float section;  // the section's height: above it is clipped
out vec4 v_colour;
void main() {
  v_colour = colour;
  gl_ClipDistance[0] = section - position.y;
  gl_Position = view_projection * vec4(position, 1.0);
}
)";

// sRGB encoding here, so colours interpolate linearly across triangles.
const char* kFragmentShader = R"(#version 330 core
in vec4 v_colour;
out vec4 frag;
vec3 srgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}
void main() {
  vec3 c = v_colour.rgb;
  if (v_colour.a > 1.5) {  // painted light no light may reach: magenta stripes the other way
    if (mod(gl_FragCoord.x - gl_FragCoord.y, 8.0) < 3.0) c = vec3(1.0, 0.1, 0.85);
  } else if (v_colour.a > 0.5 && mod(gl_FragCoord.x + gl_FragCoord.y, 10.0) < 3.0) {
    c *= 0.45;
  }
  frag = vec4(srgb(c), 1.0);
}
)";

} // namespace

SceneMesh::SceneMesh(const Scene& scene) : m_vertex_count(scene.positions.size()) {
  m_program = std::make_unique<GlProgram>(kVertexShader, kFragmentShader);
  if (scene.triangles.size() * 3 > size_t(INT32_MAX)) throw std::runtime_error("scene too large to draw");
  glGenVertexArrays(1, &m_vao);
  glBindVertexArray(m_vao);

  glGenBuffers(1, &m_positions);
  glBindBuffer(GL_ARRAY_BUFFER, m_positions);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(scene.positions.size() * sizeof(Vec3)), scene.positions.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vec3), nullptr);

  glGenBuffers(1, &m_colours);
  glBindBuffer(GL_ARRAY_BUFFER, m_colours);
  std::vector<VertexColour> grey(m_vertex_count, VertexColour{glm::vec3(0.2f), 0.f});
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(grey.size() * sizeof(VertexColour)), grey.data(), GL_DYNAMIC_DRAW);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(VertexColour), nullptr);

  glGenBuffers(1, &m_indices);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_indices);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(scene.triangles.size() * sizeof(scene.triangles[0])),
               scene.triangles.data(), GL_STATIC_DRAW);
  m_index_count = GLsizei(scene.triangles.size() * 3);
  glBindVertexArray(0);
}

SceneMesh::~SceneMesh() {
  glDeleteBuffers(1, &m_indices);
  glDeleteBuffers(1, &m_colours);
  glDeleteBuffers(1, &m_positions);
  glDeleteVertexArrays(1, &m_vao);
}

void SceneMesh::set_colours(const std::vector<VertexColour>& colours) {
  if (colours.size() != m_vertex_count) throw std::logic_error("SceneMesh::set_colours: one colour per vertex");
  glBindBuffer(GL_ARRAY_BUFFER, m_colours);
  glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(colours.size() * sizeof(VertexColour)), colours.data());
}

void SceneMesh::set_shown_triangles(const Scene& scene, const std::vector<uint8_t>& shown) {
  // The cutaway changes with the camera: the index buffer holds only what is shown.
  std::vector<std::array<uint32_t, 3>> kept;
  if (shown.empty()) kept = scene.triangles;
  else {
    kept.reserve(scene.triangles.size());
    for (size_t t = 0; t < scene.triangles.size(); ++t)
      if (shown[t]) kept.push_back(scene.triangles[t]);
  }
  glBindVertexArray(m_vao);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_indices);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(kept.size() * sizeof(kept[0])), kept.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
  m_index_count = GLsizei(kept.size() * 3);
}

void SceneMesh::draw(const glm::mat4& view_projection) const {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glFrontFace(GL_CCW);
  m_program->use();
  m_program->set("view_projection", view_projection);
  m_program->set("section", m_section ? *m_section : 3.0e38f);
  glEnable(GL_CLIP_DISTANCE0);
  glBindVertexArray(m_vao);
  glDrawElements(GL_TRIANGLES, m_index_count, GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
  glDisable(GL_CLIP_DISTANCE0);
  glDisable(GL_CULL_FACE);
}

} // namespace hilight::painter::ui
