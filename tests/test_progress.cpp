// Progress of long work (issue 36 item 1): the facility (hilight/progress.hpp)
// and what the CLI shows with it: a bar with the percentage and the time left
// on a terminal (a pseudo-terminal here), nothing on a pipe unless
// --progress, and a summary whose time is the whole command's.
#include "hilight/progress.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "support.hpp"

#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <cstring>
#include <fcntl.h>
#include <iostream>
#include <filesystem>
#include <mutex>
#include <poll.h>
#include <pty.h>
#include <regex>
#include <string>
#include <sys/wait.h>
#include <tbb/parallel_for.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using namespace hilight;

/// Keeps what it is told.
struct Recorder final : ProgressReporter {
  std::mutex mutex;
  std::vector<ProgressUpdate> updates;
  std::vector<std::pair<std::string, size_t>> ended;
  int idles = 0;
  std::atomic<int> inside{0}, overlapped{0};

  void update(const ProgressUpdate& now) override {
    if (inside.fetch_add(1) != 0) overlapped.fetch_add(1);
    {
      std::lock_guard lock(mutex);
      updates.push_back(now);
    }
    inside.fetch_sub(1);
  }
  void stage_ended(const std::string& name, size_t depth, double) override {
    std::lock_guard lock(mutex);
    ended.emplace_back(name, depth);
  }
  void idle() override {
    std::lock_guard lock(mutex);
    ++idles;
  }
};

void sleep_for(double seconds) { std::this_thread::sleep_for(std::chrono::duration<double>(seconds)); }

} // namespace

TEST_CASE("Progress: a stage's fraction, its parts, and nothing without a reporter", "[progress]") {
  {
    ProgressStage quiet("no reporter", 10);
    quiet.advance(5);
    CHECK(progress_now().stages.empty());  // nothing recorded: costs an atomic load
  }
  Recorder recorder;
  ProgressReporting reporting(&recorder, 1000.0);  // no ticks: the state is read directly here
  ProgressStage outer("rendering", 4);
  outer.advance(1);
  ProgressUpdate now = progress_now();
  REQUIRE(now.stages == std::vector<std::string>{"rendering"});
  CHECK(now.fraction == Approx(0.25));
  CHECK(now.seconds_left < 0);  // too early to say
  {
    // A part of a known size fills its one unit of the parent as it goes.
    ProgressStage part("a part", 10);
    part.advance(5);
    CHECK(progress_now().fraction == Approx(0.375));
    part.advance(50);  // more than its size: never past its unit
    CHECK(progress_now().fraction == Approx(0.5));
  }
  outer.advance(1);
  CHECK(progress_now().fraction == Approx(0.5));
  {
    // Under a stage of unknown size, a part's fraction is the work's once it has run a while.
    ProgressStage unknown("solving");
    ProgressStage part("building the light cache", 4);
    part.advance(1);
    now = progress_now();
    CHECK(now.fraction == Approx(0.5 + 0.25 * 0.0));  // the part too young to show: the outer's 2 of 4
    sleep_for(0.6);
    now = progress_now();
    // Named after half a second, measured after two (short calls do not flicker).
    CHECK(now.stages == std::vector<std::string>{"rendering", "solving", "building the light cache"});
    CHECK(now.fraction == Approx(0.5));
    sleep_for(1.5);
    CHECK(progress_now().fraction == Approx((2 + 0.25) / 4));
  }
  CHECK(recorder.idles == 0);
}

TEST_CASE("Progress: a stage opened on a worker thread is a part of the work going on", "[progress]") {
  Recorder recorder;
  {
    ProgressReporting reporting(&recorder, 1000.0);
    ProgressStage root("solving");
    std::thread([&] {
      ProgressStage worker("lighting the points", 10);
      worker.advance(5);
      sleep_for(2.1);
      const ProgressUpdate now = progress_now();
      CHECK(now.stages == std::vector<std::string>{"solving", "lighting the points"});
      CHECK(now.fraction == Approx(0.5));
      CHECK(ProgressStage::current() == &worker);
    }).join();
    CHECK(ProgressStage::current() == &root);  // the worker's end leaves this thread's stages alone
  }
  std::lock_guard lock(recorder.mutex);
  // Only the outermost stage counts as a part of the command's time.
  REQUIRE(recorder.ended.size() == 2);
  CHECK(recorder.ended[0] == std::pair<std::string, size_t>("lighting the points", 1));
  CHECK(recorder.ended[1] == std::pair<std::string, size_t>("solving", 0));
}

TEST_CASE("Progress: the time left, stage times, and idle when the last stage ends", "[progress]") {
  Recorder recorder;
  {
    ProgressReporting reporting(&recorder, 0.05);
    {
      ProgressStage stage("work", 100);
      for (int k = 0; k < 30; ++k) {
        sleep_for(0.05);
        stage.advance(1);
      }
      const ProgressUpdate now = progress_now();
      CHECK(now.fraction == Approx(0.3));
      // 1.5 s for 30%: 3.5 s left, within the timer's slack.
      CHECK(now.seconds_left == Approx(3.5).margin(0.8));
      CHECK(now.elapsed >= 1.5);
    }
  }
  std::lock_guard lock(recorder.mutex);
  CHECK(recorder.idles == 1);
  REQUIRE(recorder.ended.size() == 1);
  CHECK(recorder.ended[0] == std::pair<std::string, size_t>("work", 0));
  REQUIRE(!recorder.updates.empty());
  CHECK(recorder.updates.back().stages == std::vector<std::string>{"work"});
}

TEST_CASE("Progress: advanced from many threads, reported at a bounded rate, never concurrently", "[progress]") {
  Recorder recorder;
  const auto start = std::chrono::steady_clock::now();
  {
    ProgressReporting reporting(&recorder, 0.02);
    ProgressStage stage("parallel", 4e6);
    // Millions of advances from TBB's threads: the count adds up, the reporter
    // is called by the ticker only (its rate, not the work's).
    tbb::parallel_for(0, 4000000, [&](int) { stage.advance(1); });
    sleep_for(0.2);
    CHECK(progress_now().fraction == Approx(1.0));
    CHECK(progress_now().seconds_left == 0);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::lock_guard lock(recorder.mutex);
  CHECK(recorder.overlapped.load() == 0);
  CHECK(recorder.updates.size() <= size_t(seconds / 0.02) + 2);
  CHECK(recorder.updates.size() >= 3);
}

namespace {

const std::string kHouse = (hilight::builders::testmodels_dir() / "IFC" / "AC14-FZK-Haus.ifc").string();

/// Lights inside the FZK house's ground floor.
fs::path house_lights(const fs::path& dir) {
  const fs::path path = dir / "lights.json";
  test::write_text(path, R"({"lights":[
    {"type":"point","position":[9.6,2.1,-7.0],"intensity":[5,5,5]},
    {"type":"point","position":[2.0,2.1,-7.8],"intensity":[5,5,5]},
    {"type":"point","position":[6.0,2.1,-2.0],"intensity":[5,5,5]}]})");
  return path;
}

/// A render of the house long enough to be measured (one thread, a large
/// picture from inside: a few seconds).
std::vector<std::string> long_render(const fs::path& dir, const std::string& out) {
  return {"render", kHouse, "--lights", house_lights(dir).string(), "-o", (dir / out).string(), "--bounces", "0", "--threads", "1",
          "--width", "2400", "--height", "1800", "--camera", "6,1.5,-5,9.6,1.5,-7,70"};
}

struct TerminalRun {
  int exit_code = -1;
  std::string output;  ///< stdout and stderr together, as the terminal got them
};

/// Runs hilight on a pseudo-terminal (stdin, stdout and stderr), 100 columns wide.
TerminalRun run_on_terminal(const std::vector<std::string>& args) {
  winsize size{};
  size.ws_row = 40;
  size.ws_col = 100;
  int master = -1;
  const pid_t pid = ::forkpty(&master, nullptr, nullptr, &size);
  REQUIRE(pid >= 0);
  if (pid == 0) {
    std::vector<char*> argv{const_cast<char*>(HILIGHT_BINARY)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::setenv("TERM", "xterm", 1);
    ::execv(HILIGHT_BINARY, argv.data());
    ::_exit(127);
  }
  TerminalRun run;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(master, buffer, sizeof(buffer));
    if (n > 0) {
      run.output.append(buffer, size_t(n));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    break;  // EIO once the child has closed its side
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  ::close(master);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return run;
}

} // namespace

TEST_CASE("Progress: a render on a terminal draws a bar with the percentage and the time left", "[progress][cli]") {
  if (!fs::exists(kHouse)) {
    std::cout << "SKIPPED: " << kHouse << " is missing (assimp-testmodels)" << std::endl;
    return;
  }
  const fs::path dir = test::output_dir("progress_terminal");
  const TerminalRun run = run_on_terminal(long_render(dir, "house.png"));
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK(fs::exists(dir / "house.png"));
  // Redrawn in place: carriage returns, the line cleared after each.
  CHECK_THAT(run.output, Contains("\r") && Contains("\x1b[K"));
  CHECK(std::regex_search(run.output, std::regex("rendering house\\.png.*\\[[#.]{16}\\] +[0-9]{1,3}%  [0-9]+ s left")));
  // Several percentages as it goes, rising.
  std::vector<int> percent;
  const std::regex figure("\\] +([0-9]{1,3})%");
  for (auto it = std::sregex_iterator(run.output.begin(), run.output.end(), figure); it != std::sregex_iterator(); ++it)
    percent.push_back(std::stoi((*it)[1]));
  REQUIRE(percent.size() >= 3);
  CHECK(std::is_sorted(percent.begin(), percent.end()));
  // The bar is gone before the last lines, which stand whole.
  CHECK(std::regex_search(run.output, std::regex("\r\x1b\\[Kwrote [^\r\n]*house\\.png")));
  CHECK(std::regex_search(run.output, std::regex("rendered [0-9]+ vertices, 3 lights with embree \\(bounces 0\\) in [0-9.]+ s "
                                                 "\\(rendering house\\.png [0-9.]+ s")));
  // No bar wider than the terminal (it would wrap, and \r would not take it back).
  const std::regex bar("\r(hilight: [^\r\n]*)\x1b\\[K");
  size_t bars = 0;
  for (auto it = std::sregex_iterator(run.output.begin(), run.output.end(), bar); it != std::sregex_iterator(); ++it, ++bars) {
    const std::string drawn = (*it)[1];
    size_t columns = 0;
    for (unsigned char c : drawn) columns += (c & 0xC0) != 0x80;
    CHECK(columns < 100);
  }
  CHECK(bars >= 3);
}

TEST_CASE("Progress: a pipe gets nothing, or lines with --progress, the summary names the slow part", "[progress][cli]") {
  if (!fs::exists(kHouse)) {
    std::cout << "SKIPPED: " << kHouse << " is missing (assimp-testmodels)" << std::endl;
    return;
  }
  const fs::path dir = test::output_dir("progress_pipe");
  const test::RunResult plain = test::run_hilight(long_render(dir, "plain.png"));
  INFO(plain.err);
  REQUIRE(plain.exit_code == 0);
  CHECK(plain.err.find('\r') == std::string::npos);
  CHECK(plain.err.find("hilight: progress") == std::string::npos);
  CHECK(plain.err.find('%') == std::string::npos);
  CHECK(test::line_count(plain.err) == 2);  // wrote ..., rendered ...
  // The summary's time is the whole command's, the slow part named.
  std::smatch m;
  REQUIRE(std::regex_search(plain.err, m, std::regex("in ([0-9.]+) s \\(rendering plain\\.png ([0-9.]+) s")));
  CHECK(std::stod(m[2]) <= std::stod(m[1]) + 0.05);

  auto with_lines = long_render(dir, "lines.png");
  with_lines.push_back("--progress");
  const test::RunResult lines = test::run_hilight(with_lines);
  INFO(lines.err);
  REQUIRE(lines.exit_code == 0);
  CHECK(lines.err.find('\r') == std::string::npos);
  CHECK(lines.err.find("\x1b") == std::string::npos);
  CHECK(std::regex_search(lines.err, std::regex("\nhilight: progress: rendering lines\\.png › shading the pixels: [0-9]+% \\([0-9]+ s left\\)\n")));
  // At most a line a second per stage, and each whole.
  CHECK(test::line_count(lines.err) < 40);
}
