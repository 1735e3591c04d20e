#include "ui/scene_framebuffer.hpp"

#include <stdexcept>

namespace hilight::painter::ui {

SceneFramebuffer::~SceneFramebuffer() { release(); }

void SceneFramebuffer::release() {
  if (m_framebuffer) glDeleteFramebuffers(1, &m_framebuffer);
  if (m_colour) glDeleteRenderbuffers(1, &m_colour);
  if (m_depth) glDeleteRenderbuffers(1, &m_depth);
  m_framebuffer = m_colour = m_depth = 0;
}

bool SceneFramebuffer::resize(int width, int height) {
  if (m_framebuffer && width == m_width && height == m_height) return false;
  release();
  m_width = width;
  m_height = height;
  glGenRenderbuffers(1, &m_colour);
  glBindRenderbuffer(GL_RENDERBUFFER, m_colour);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glGenRenderbuffers(1, &m_depth);
  glBindRenderbuffer(GL_RENDERBUFFER, m_depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glGenFramebuffers(1, &m_framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_colour);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, m_depth);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) throw std::runtime_error("painter: the offscreen view framebuffer is incomplete");
  return true;
}

void SceneFramebuffer::bind() const { glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer); }

void SceneFramebuffer::blit_to_window() const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, m_framebuffer);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, m_width, m_height, 0, 0, m_width, m_height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace hilight::painter::ui
