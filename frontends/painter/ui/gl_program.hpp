#pragma once
/// A linked GLSL program from vertex + fragment source; compile and link
/// failures throw std::runtime_error with the driver's log.
#include "ui/gl.hpp"

#include <glm/glm.hpp>
#include <string>

namespace hilight::painter::ui {

class GlProgram {
public:
  GlProgram(const std::string& vertex_source, const std::string& fragment_source);
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  void use() const { glUseProgram(m_program); }
  void set(const char* name, const glm::mat4& value) const;
  void set(const char* name, float value) const;

private:
  GLuint m_program = 0;
};

} // namespace hilight::painter::ui
