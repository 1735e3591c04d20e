#pragma once
/// The 3D view rendered once into an offscreen framebuffer and copied to the
/// window each frame. Software OpenGL (llvmpipe) spends most of a frame on
/// the scene's triangles; frames that change only the panels (a progress bar
/// while a solve runs) then cost a copy, and leave the cores to the solve.
#include "ui/gl.hpp"

namespace hilight::painter::ui {

class SceneFramebuffer {
public:
  SceneFramebuffer() = default;
  ~SceneFramebuffer();
  SceneFramebuffer(const SceneFramebuffer&) = delete;
  SceneFramebuffer& operator=(const SceneFramebuffer&) = delete;

  /// (Re)allocates for the size; true if it did (the content is then stale).
  bool resize(int width, int height);
  /// Subsequent drawing goes into the offscreen buffer.
  void bind() const;
  /// Copies it to the window's back buffer (and rebinds the window's framebuffer).
  void blit_to_window() const;

private:
  void release();
  GLuint m_framebuffer = 0, m_colour = 0, m_depth = 0;
  int m_width = 0, m_height = 0;
};

} // namespace hilight::painter::ui
