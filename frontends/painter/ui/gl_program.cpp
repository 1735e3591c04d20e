#include "ui/gl_program.hpp"

#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>
#include <vector>

namespace hilight::painter::ui {

namespace {

GLuint compile(GLenum kind, const std::string& source) {
  GLuint shader = glCreateShader(kind);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(size_t(length) + 1, '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    throw std::runtime_error(std::string("painter shader does not compile: ") + log.data());
  }
  return shader;
}

} // namespace

GlProgram::GlProgram(const std::string& vertex_source, const std::string& fragment_source) {
  GLuint vs = compile(GL_VERTEX_SHADER, vertex_source);
  GLuint fs = compile(GL_FRAGMENT_SHADER, fragment_source);
  m_program = glCreateProgram();
  glAttachShader(m_program, vs);
  glAttachShader(m_program, fs);
  glLinkProgram(m_program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(m_program, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(m_program, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(size_t(length) + 1, '\0');
    glGetProgramInfoLog(m_program, length, nullptr, log.data());
    glDeleteProgram(m_program);
    throw std::runtime_error(std::string("painter shaders do not link: ") + log.data());
  }
}

GlProgram::~GlProgram() { glDeleteProgram(m_program); }

void GlProgram::set(const char* name, const glm::mat4& value) const {
  glUniformMatrix4fv(glGetUniformLocation(m_program, name), 1, GL_FALSE, glm::value_ptr(value));
}

void GlProgram::set(const char* name, float value) const { glUniform1f(glGetUniformLocation(m_program, name), value); }

} // namespace hilight::painter::ui
