#include "ui/window.hpp"

#include "hilight/error.hpp"
#include "ui/gl.hpp"

#include <cstdlib>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#include <mutex>

namespace hilight::painter::ui {

namespace {

// GLFW calls the error callback on the thread that failed, and worker
// threads call glfwPostEmptyEvent: guard the message.
std::mutex g_glfw_error_mutex;
std::string g_last_glfw_error;

void remember_glfw_error(int /*code*/, const char* description) {
  std::lock_guard<std::mutex> lock(g_glfw_error_mutex);
  g_last_glfw_error = description ? description : "unknown";
}

std::string last_glfw_error() {
  std::lock_guard<std::mutex> lock(g_glfw_error_mutex);
  return g_last_glfw_error;
}

} // namespace

Window::Window(int width, int height, const std::string& title, bool visible) {
  // GLFW would try X11 and fail with a long message; say plainly what is wrong.
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!display || !*display) && (!wayland || !*wayland))
    throw InputError("paint: no display (DISPLAY is not set); run under X, or headless with xvfb-run -a hilight paint ...");
  glfwSetErrorCallback(remember_glfw_error);
  if (!glfwInit()) throw InputError("paint: cannot open the display '" + std::string(display ? display : "") + "': " + last_glfw_error());
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
  glfwWindowHint(GLFW_SAMPLES, 0);
  m_window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!m_window) {
    std::string why = last_glfw_error();
    glfwTerminate();
    throw InputError("paint: no OpenGL 3.3 core context on this display: " + why);
  }
  glfwMakeContextCurrent(m_window);
  glfwSwapInterval(0);  // frame pacing is ours: idle waits for events, replay runs flat out

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini beside wherever the user started us
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(m_window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  m_imgui = true;
}

Window::~Window() {
  if (m_imgui) {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  if (m_window) glfwDestroyWindow(m_window);
  glfwTerminate();
}

bool Window::should_close() const { return glfwWindowShouldClose(m_window); }

void Window::request_close() { glfwSetWindowShouldClose(m_window, GLFW_TRUE); }

void Window::framebuffer_size(int& width, int& height) const { glfwGetFramebufferSize(m_window, &width, &height); }

void Window::begin_frame() {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void Window::render_imgui() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void Window::present() { glfwSwapBuffers(m_window); }

} // namespace hilight::painter::ui
