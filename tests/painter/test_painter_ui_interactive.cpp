// The interactive window driven like a designer drives it: real X input
// events (the XTest extension, loaded at run time) paint a stroke, orbit the
// camera, undo and quit; the session recording shows each, with the stroke's
// automatic fine-tune. The test runs its own Xvfb, so no other test's window
// can catch the events. Skipped without Xvfb or libXtst. The file browser
// opens another scene and the recording goes on there.
#include "../support.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"

#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <dlfcn.h>
#include <fcntl.h>
#include <functional>
#include <iostream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

/// The few Xlib / XTest calls the test needs, looked up at run time (the
/// test binary does not link X).
class FakeInput {
public:
  /// Not ready() without a display of its own: "" would open $DISPLAY instead.
  explicit FakeInput(const std::string& display) {
    if (display.empty()) return;
    m_x11 = ::dlopen("libX11.so.6", RTLD_NOW | RTLD_LOCAL);
    m_xtst = ::dlopen("libXtst.so.6", RTLD_NOW | RTLD_LOCAL);
    if (!m_x11 || !m_xtst) return;
    m_open = reinterpret_cast<void* (*)(const char*)>(::dlsym(m_x11, "XOpenDisplay"));
    m_close = reinterpret_cast<int (*)(void*)>(::dlsym(m_x11, "XCloseDisplay"));
    m_flush = reinterpret_cast<int (*)(void*)>(::dlsym(m_x11, "XFlush"));
    m_keysym = reinterpret_cast<unsigned long (*)(const char*)>(::dlsym(m_x11, "XStringToKeysym"));
    m_keycode = reinterpret_cast<unsigned char (*)(void*, unsigned long)>(::dlsym(m_x11, "XKeysymToKeycode"));
    m_motion = reinterpret_cast<int (*)(void*, int, int, int, unsigned long)>(::dlsym(m_xtst, "XTestFakeMotionEvent"));
    m_button = reinterpret_cast<int (*)(void*, unsigned, int, unsigned long)>(::dlsym(m_xtst, "XTestFakeButtonEvent"));
    m_key = reinterpret_cast<int (*)(void*, unsigned, int, unsigned long)>(::dlsym(m_xtst, "XTestFakeKeyEvent"));
    if (m_open && m_close && m_flush && m_keysym && m_keycode && m_motion && m_button && m_key) m_display = m_open(display.c_str());
  }
  ~FakeInput() {
    if (m_display) m_close(m_display);
  }
  FakeInput(const FakeInput&) = delete;
  FakeInput& operator=(const FakeInput&) = delete;

  bool ready() const { return m_display != nullptr; }
  void move(int x, int y) { m_motion(m_display, -1, x, y, 0); pause(40ms); }
  void button(unsigned b, bool down) { m_button(m_display, b, down, 0); pause(60ms); }
  /// Held over several frames: ImGui 1.86 misses a key pressed and released within one.
  void key(const char* name, bool down) { m_key(m_display, m_keycode(m_display, m_keysym(name)), down, 0); pause(100ms); }
  void tap(const char* name) { key(name, true); key(name, false); }
  void drag(unsigned b, int x0, int y0, int x1, int y1, int steps) {
    move(x0, y0);
    button(b, true);
    for (int i = 1; i <= steps; ++i) move(x0 + (x1 - x0) * i / steps, y0 + (y1 - y0) * i / steps);
    button(b, false);
  }

private:
  void pause(std::chrono::milliseconds ms) {
    m_flush(m_display);
    std::this_thread::sleep_for(ms);
  }
  void* m_x11 = nullptr;
  void* m_xtst = nullptr;
  void* m_display = nullptr;
  void* (*m_open)(const char*) = nullptr;
  int (*m_close)(void*) = nullptr;
  int (*m_flush)(void*) = nullptr;
  unsigned long (*m_keysym)(const char*) = nullptr;
  unsigned char (*m_keycode)(void*, unsigned long) = nullptr;
  int (*m_motion)(void*, int, int, int, unsigned long) = nullptr;
  int (*m_button)(void*, unsigned, int, unsigned long) = nullptr;
  int (*m_key)(void*, unsigned, int, unsigned long) = nullptr;
};

/// An Xvfb of the test's own, on a display number the server picks (-displayfd).
class PrivateXServer {
public:
  PrivateXServer() {
    int fds[2];
    if (::pipe(fds) != 0) return;
    m_pid = ::fork();
    if (m_pid == 0) {
      ::close(fds[0]);
      int null = ::open("/dev/null", O_RDWR);
      ::dup2(null, 0);
      ::dup2(null, 1);
      ::dup2(null, 2);
      const std::string fd = std::to_string(fds[1]);
      ::execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1280x1024x24", "-noreset", "-nolisten", "tcp",
               static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(fds[1]);
    // The server writes its display number and a newline once it accepts clients.
    std::string number;
    char c = 0;
    while (m_pid > 0 && ::read(fds[0], &c, 1) == 1 && c != '\n') number += c;
    ::close(fds[0]);
    if (!number.empty()) m_display = ":" + number;
  }
  ~PrivateXServer() {
    if (m_pid > 0) {
      ::kill(m_pid, SIGTERM);
      ::waitpid(m_pid, nullptr, 0);
    }
  }
  PrivateXServer(const PrivateXServer&) = delete;
  PrivateXServer& operator=(const PrivateXServer&) = delete;
  /// ":N", or "" if the server did not start.
  const std::string& display() const { return m_display; }

private:
  pid_t m_pid = -1;
  std::string m_display;
};

/// Starts `hilight <args>` on `display` without waiting (stdout/stderr to files in `dir`).
pid_t spawn_hilight(const std::vector<std::string>& args, const std::string& display, const fs::path& dir) {
  pid_t pid = ::fork();
  if (pid == 0) {
    ::setenv("DISPLAY", display.c_str(), 1);
    int out = ::open((dir / "stdout.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    int err = ::open((dir / "stderr.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out, 1);
    ::dup2(err, 2);
    std::vector<std::string> copy = args;
    std::string bin = HILIGHT_BINARY;
    std::vector<char*> argv{bin.data()};
    for (auto& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(bin.c_str(), argv.data());
    ::_exit(127);
  }
  return pid;
}

/// Waits up to `limit` for `done()`, checking every 50 ms.
bool wait_for(const std::function<bool()>& done, std::chrono::milliseconds limit) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < end) {
    if (done()) return true;
    std::this_thread::sleep_for(50ms);
  }
  return done();
}

/// Ctrl-Q, then waits for the painter to exit (killed after 15 s): true when it quit by itself.
bool quit_with_ctrl_q(FakeInput& input, pid_t pid, int& status) {
  input.key("Control_L", true);
  input.tap("q");
  input.key("Control_L", false);
  const bool quit = wait_for([&] { return ::waitpid(pid, &status, WNOHANG) == pid; }, 15s);
  if (!quit) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
  }
  return quit;
}

/// True (and says why) when the test cannot drive a window: no Xvfb of its own, or no XTest.
bool skip_without_input(const PrivateXServer& server, const FakeInput& input) {
  if (server.display().empty()) std::cout << "SKIPPED: cannot start Xvfb" << std::endl;
  else if (!input.ready()) std::cout << "SKIPPED: no XTest (libXtst.so.6) to send input events" << std::endl;
  return !input.ready();
}

} // namespace

TEST_CASE("painter ui: mouse and keys paint, fine-tune, orbit, undo and quit", "[painter-ui]") {
  PrivateXServer server;
  FakeInput input(server.display());
  if (skip_without_input(server, input)) return;
  const fs::path dir = test::output_dir("painter_ui_interactive");
  const fs::path recording = dir / "session.json";
  const pid_t pid = spawn_hilight({"paint", HILIGHT_SOURCE_DIR "/scenes/room.obj", "--lights",
                                   HILIGHT_SOURCE_DIR "/scenes/room-4lights.json", "--size", "1280x800", "--record",
                                   recording.string(), "--set", "bounce_samples=16", "--cache-dir", (dir / "cache").string()},
                                  server.display(), dir);
  REQUIRE(pid > 0);
  auto recorded = [&](const std::string& text) { return test::read_file(recording).find(text) != std::string::npos; };
  auto finish = [&] {
    int status = 0;
    const bool exited = wait_for([&] { return ::waitpid(pid, &status, WNOHANG) == pid; }, 15s);
    if (!exited) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
    }
    return exited && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  // The starting lights are recorded before the window opens; give it time to show.
  if (!wait_for([&] { return recorded("load_lights"); }, 15s)) {
    ::kill(pid, SIGKILL);
    finish();
    FAIL("the painter did not start: " << test::read_file(dir / "stderr.txt"));
  }
  std::this_thread::sleep_for(1500ms);

  // A brush stroke on the floor, right of the panel (the framed room fills
  // the middle of the window; xvfb-run's screen must hold 1280x800).
  input.tap("b");
  input.drag(1, 500, 560, 540, 570, 6);
  const bool stroke = wait_for([&] { return recorded("\"stroke\""); }, 10s);
  const bool fine_tune = wait_for([&] { return recorded("fine_tune"); }, 10s);
  // Right drag orbits; releasing records where the camera ended.
  input.drag(3, 900, 300, 950, 310, 5);
  const bool camera = wait_for([&] { return recorded("\"camera\""); }, 10s);
  // Ctrl+Z after the fine-tune's result (a job still running would be undone under it).
  std::this_thread::sleep_for(3s);
  input.key("Control_L", true);
  input.tap("z");
  input.key("Control_L", false);
  const bool undo = wait_for([&] { return recorded("\"undo\""); }, 10s);
  input.key("Control_L", true);
  input.tap("q");
  input.key("Control_L", false);
  const int exit_code = finish();

  INFO("recording: " << test::read_file(recording));
  INFO("stderr: " << test::read_file(dir / "stderr.txt"));
  CHECK(stroke);
  CHECK(fine_tune);
  CHECK(camera);
  CHECK(undo);
  CHECK(exit_code == 0);
  // The recording replays (the fine-tune too) without the window's help.
  const char* outer = std::getenv("DISPLAY");
  const std::string outer_display = outer ? outer : "";
  ::setenv("DISPLAY", server.display().c_str(), 1);
  const test::RunResult replay = test::run_hilight({"paint", HILIGHT_SOURCE_DIR "/scenes/room.obj", "--script", recording.string(),
                                                    "--size", "1280x800", "--set", "bounce_samples=16", "--cache-dir",
                                                    (dir / "cache").string(), "--exit", "--no-record"});
  if (outer) ::setenv("DISPLAY", outer_display.c_str(), 1);
  else ::unsetenv("DISPLAY");
  INFO("replay: " << replay.err);
  CHECK(replay.exit_code == 0);
}

TEST_CASE("painter ui: a double click and the building keys record the focus, cutaway, section, plan and a walk, and the recording replays",
          "[painter-ui][building]") {
  PrivateXServer server;
  FakeInput input(server.display());
  if (skip_without_input(server, input)) return;
  const fs::path dir = test::output_dir("painter_ui_building_keys");
  const fs::path recording = dir / "session.json";
  const pid_t pid = spawn_hilight({"paint", HILIGHT_SOURCE_DIR "/scenes/room.obj", "--size", "1280x800", "--record", recording.string()},
                                  server.display(), dir);
  REQUIRE(pid > 0);
  auto recorded = [&](const std::string& text) { return test::read_file(recording).find(text) != std::string::npos; };
  int status = 0;
  // Nothing is recorded before the first key: give the window time to show.
  std::this_thread::sleep_for(4000ms);
  // A double click on the floor (right of the panel) focuses its room; its
  // first click's dab is taken back.
  input.move(520, 565);
  for (int click = 0; click < 2; ++click) {
    input.button(1, true);
    input.button(1, false);
  }
  const bool focus = wait_for([&] { return recorded("\"focus\""); }, 10s);
  input.move(900, 400);  // over the view, not a panel
  input.tap("c");
  const bool cutaway = wait_for([&] { return recorded("\"cutaway\""); }, 10s);
  input.tap("k");
  input.tap("Prior");  // Page Up raises the section
  const bool section = wait_for([&] { return recorded("\"section\""); }, 10s);
  input.tap("t");
  input.tap("t");
  const bool plan = wait_for([&] { return recorded("\"plan\""); }, 10s);
  input.tap("v");
  const bool walk = wait_for([&] { return recorded("\"walk\""); }, 10s);
  // Hold W: the eye walks forward; let go: where it ended is one camera action.
  input.key("w", true);
  std::this_thread::sleep_for(700ms);
  input.key("w", false);
  const bool walked = wait_for([&] { return recorded("\"camera\""); }, 10s);
  input.tap("v");
  std::this_thread::sleep_for(300ms);
  const bool quit = quit_with_ctrl_q(input, pid, status);
  const std::string text = test::read_file(recording);
  INFO("recording: " << text);
  INFO("stderr: " << test::read_file(dir / "stderr.txt"));
  CHECK(focus);
  CHECK(text.find("\"undo\"") < text.find("\"focus\""));  // the click's dab undone, then the focus
  CHECK(cutaway);
  CHECK(section);
  CHECK(plan);
  CHECK(walk);
  CHECK(walked);
  CHECK(quit);
  CHECK(text.find("\"on\":false") != std::string::npos);  // the plan and the walk were left again
  const char* outer = std::getenv("DISPLAY");
  const std::string outer_display = outer ? outer : "";
  ::setenv("DISPLAY", server.display().c_str(), 1);
  const test::RunResult replay = test::run_hilight({"paint", HILIGHT_SOURCE_DIR "/scenes/room.obj", "--script", recording.string(),
                                                    "--size", "1280x800", "--exit", "--no-record"});
  if (outer) ::setenv("DISPLAY", outer_display.c_str(), 1);
  else ::unsetenv("DISPLAY");
  INFO("replay: " << replay.err);
  CHECK(replay.exit_code == 0);
}

TEST_CASE("painter ui: a brush value typed out of range is clamped, recorded, and never quits", "[painter-ui]") {
  PrivateXServer server;
  FakeInput input(server.display());
  if (skip_without_input(server, input)) return;
  const fs::path dir = test::output_dir("painter_ui_typed_brush");
  const fs::path recording = dir / "session.json";
  const pid_t pid = spawn_hilight({"paint", HILIGHT_SOURCE_DIR "/scenes/room.obj", "--lights", HILIGHT_SOURCE_DIR "/scenes/room-4lights.json",
                                   "--size", "1280x800", "--record", recording.string(), "--set", "bounce_samples=16",
                                   "--cache-dir", (dir / "cache").string()},
                                  server.display(), dir);
  REQUIRE(pid > 0);
  auto recorded = [&](const std::string& text) { return test::read_file(recording).find(text) != std::string::npos; };
  int status = 0;
  auto exited = [&] { return ::waitpid(pid, &status, WNOHANG) == pid; };
  if (!wait_for([&] { return recorded("load_lights"); }, 15s)) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
    FAIL("the painter did not start: " << test::read_file(dir / "stderr.txt"));
  }
  std::this_thread::sleep_for(1500ms);
  // Ctrl+click the radius slider (the Tools panel's first slider at the
  // window's top left), type 0, Enter: the typed value is below the range.
  input.move(120, 136);
  input.key("Control_L", true);
  input.button(1, true);
  input.button(1, false);
  input.key("Control_L", false);
  input.tap("0");
  input.tap("Return");
  const bool brush = wait_for([&] { return recorded("\"brush\""); }, 10s);
  std::this_thread::sleep_for(500ms);
  const bool alive = !exited();
  const bool quit = quit_with_ctrl_q(input, pid, status);
  const std::string text = test::read_file(recording);
  INFO("recording: " << text);
  INFO("stderr: " << test::read_file(dir / "stderr.txt"));
  CHECK(brush);
  CHECK(alive);
  CHECK(quit);
  CHECK((WIFEXITED(status) && WEXITSTATUS(status) == 0));
  // The recorded radius is the slider's least (0.002 x the diagonal), not 0; the recording replays.
  CHECK(text.find("\"radius\":0.0,") == std::string::npos);
  CHECK(text.find("\"radius\":0,") == std::string::npos);
  const char* outer = std::getenv("DISPLAY");
  const std::string outer_display = outer ? outer : "";
  ::setenv("DISPLAY", server.display().c_str(), 1);
  const test::RunResult replay = test::run_hilight({"paint", HILIGHT_SOURCE_DIR "/scenes/room.obj", "--script", recording.string(),
                                                    "--size", "1280x800", "--set", "bounce_samples=16", "--cache-dir",
                                                    (dir / "cache").string(), "--exit", "--no-record"});
  if (outer) ::setenv("DISPLAY", outer_display.c_str(), 1);
  else ::unsetenv("DISPLAY");
  INFO("replay: " << replay.err);
  CHECK(replay.exit_code == 0);
}

TEST_CASE("painter ui: the file browser opens another scene, painting goes on there, and the recording replays", "[painter-ui][open-scene]") {
  PrivateXServer server;
  FakeInput input(server.display());
  if (skip_without_input(server, input)) return;
  const fs::path dir = test::output_dir("painter_ui_file_browser");
  // The scenes in a folder of their own: the browser opens in the scene's folder and lists scenes only.
  const fs::path scenes = dir / "scenes";
  fs::create_directories(scenes);
  for (const char* name : {"room.obj", "room.mtl"}) fs::copy_file(fs::path(HILIGHT_SOURCE_DIR) / "scenes" / name, scenes / name);
  fs::copy_file(hilight::builders::testmodels_dir() / "OBJ/WusonOBJ.obj", scenes / "a-wuson.obj");
  const fs::path recording = dir / "session.json";
  const pid_t pid = spawn_hilight({"paint", (scenes / "room.obj").string(), "--size", "1280x800", "--record", recording.string(),
                                   "--set", "bounce_samples=16", "--no-cache"},
                                  server.display(), dir);
  REQUIRE(pid > 0);
  auto recorded = [&](const std::string& text) { return test::read_file(recording).find(text) != std::string::npos; };
  int status = 0;
  std::this_thread::sleep_for(4000ms);
  // The Files header (the panel's layout is ImGui's, fixed for this window),
  // its "Open scene..." button, the browser's first file (a-wuson.obj), Open.
  input.move(58, 591);
  input.button(1, true);
  input.button(1, false);
  input.move(60, 614);
  input.button(1, true);
  input.button(1, false);
  std::this_thread::sleep_for(500ms);
  input.move(450, 121);
  input.button(1, true);
  input.button(1, false);
  input.move(780, 419);
  input.button(1, true);
  input.button(1, false);
  const bool opened = wait_for([&] { return recorded("\"open_scene\""); }, 15s);
  // The window starts again on the Wuson, seen from outside: a stroke across its middle.
  std::this_thread::sleep_for(4000ms);
  input.move(900, 400);
  input.tap("b");
  input.drag(1, 620, 390, 660, 410, 6);
  const bool painted = wait_for([&] {
    const std::string text = test::read_file(recording);
    const size_t open = text.find("\"open_scene\"");
    return open != std::string::npos && text.find("\"stroke\"", open) != std::string::npos;
  }, 10s);
  input.move(900, 400);
  const bool quit = quit_with_ctrl_q(input, pid, status);
  const std::string text = test::read_file(recording);
  INFO("recording: " << text);
  INFO("stderr: " << test::read_file(dir / "stderr.txt"));
  CHECK(opened);
  CHECK(text.find("a-wuson.obj") != std::string::npos);
  CHECK(painted);
  CHECK(quit);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  // The recording replays from the room: the open, then the Wuson's stroke.
  const char* outer = std::getenv("DISPLAY");
  const std::string outer_display = outer ? outer : "";
  ::setenv("DISPLAY", server.display().c_str(), 1);
  const test::RunResult replay = test::run_hilight({"paint", (scenes / "room.obj").string(), "--script", recording.string(), "--size",
                                                    "1280x800", "--no-cache", "--exit", "--no-record"});
  if (outer) ::setenv("DISPLAY", outer_display.c_str(), 1);
  else ::unsetenv("DISPLAY");
  INFO("replay: " << replay.err);
  CHECK(replay.exit_code == 0);
}
