#pragma once
/// The painter's window: GLFW with an OpenGL 3.3 core context, and Dear ImGui
/// bound to it. Construction fails with a one-line InputError when there is no
/// display or no suitable OpenGL, so the launcher prints it and exits cleanly.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <string>

namespace hilight::painter::ui {

class Window {
public:
  /// `visible` false: an offscreen-style hidden window (headless replay still
  /// needs a display server, e.g. Xvfb, but shows nothing).
  Window(int width, int height, const std::string& title, bool visible);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return m_window; }
  bool should_close() const;
  void request_close();
  /// Framebuffer size in pixels (what glViewport and screenshots use).
  void framebuffer_size(int& width, int& height) const;
  /// Starts an ImGui frame (after polling events).
  void begin_frame();
  /// Draws ImGui into the back buffer without presenting (screenshots read it).
  void render_imgui();
  void present();

private:
  GLFWwindow* m_window = nullptr;
  bool m_imgui = false;
};

} // namespace hilight::painter::ui
