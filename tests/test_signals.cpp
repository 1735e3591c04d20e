// Ctrl-C (SIGINT) or TERM during a render, a solve or a light cache build
// leaves nothing half-written (issue 15): each output is either absent or
// byte for byte what an uninterrupted run writes, and no temporary is left.
// The signals land across the run's last half, where the files are written.
#include "support.hpp"

#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>

namespace fs = std::filesystem;

namespace {

struct Outputs {
  std::vector<std::string> names;  ///< files the command writes in its folder
};

/// Every regular file below `dir` whose name says it is a temporary.
std::vector<fs::path> temporaries(const fs::path& dir) {
  std::vector<fs::path> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file() && e.path().filename().string().find(".tmp") != std::string::npos) out.push_back(e.path());
  return out;
}

/// `make_args(dir)` run whole once, then interrupted at `tries` moments over
/// the second half of its time; checks the invariants after each.
void interrupt_across(const std::string& name, const std::function<std::vector<std::string>(const fs::path&)>& make_args,
                      const std::vector<std::string>& outputs, int signal, int tries) {
  const fs::path whole = test::output_dir(name + "_whole");
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = test::run_hilight(make_args(whole));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  int interrupted = 0;
  for (int k = 0; k < tries; ++k) {
    const double at = seconds * (0.5 + 0.5 * double(k) / double(tries));
    const fs::path dir = test::output_dir(name + "_" + std::to_string(k));
    const auto cut = test::run_hilight_interrupted(make_args(dir), at, signal);
    INFO(name << ": signal " << signal << " after " << at << " s of " << seconds << " s; exit " << cut.exit_code << ": " << cut.err);
    CHECK((cut.exit_code == 0 || cut.exit_code == 128 + signal));
    interrupted += cut.exit_code == 128 + signal;
    CHECK(temporaries(dir).empty());
    for (const auto& file : outputs) {
      if (!fs::exists(dir / file)) continue;
      INFO(file);
      CHECK(test::read_file(dir / file) == test::read_file(whole / file));
    }
  }
  CHECK(interrupted > 0);  // the signals did land
}

} // namespace

TEST_CASE("Ctrl-C or TERM during a render leaves each output whole or absent, and no temporary", "[signals][cli]") {
  const std::string room = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
  const std::string lights = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room-4lights.json";
  const auto args = [&](const fs::path& dir) {
    // Direct light only on a fine mesh: a short run whose files (138k vertices) take a while to write.
    return std::vector<std::string>{"render", room, "--lights", lights, "--max-edge", "0.06", "--bounces", "0", "-o", (dir / "out.ply").string(),
                                    "-o", (dir / "out.png").string(), "-o", (dir / "out.exr").string(), "--threads", "1"};
  };
  interrupt_across("signal_render_int", args, {"out.ply", "out.png", "out.exr"}, SIGINT, 8);
  interrupt_across("signal_render_term", args, {"out.ply", "out.png", "out.exr"}, SIGTERM, 4);
}

TEST_CASE("Ctrl-C during a solve and its light cache build leaves the lights, report and cache whole or absent", "[signals][cli][slow]") {
  const std::string room = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
  const fs::path target = test::output_dir("signal_solve_target") / "target.ply";
  REQUIRE(test::run_hilight({"render", room, "--lights", std::string(HILIGHT_SOURCE_DIR) + "/scenes/room-4lights.json", "-o",
                             target.string(), "--max-edge", "0.5"})
              .exit_code == 0);
  const auto args = [&](const fs::path& dir) {
    return std::vector<std::string>{"solve", room, "--target", target.string(), "--max-edge", "0.5", "-o", (dir / "lights.json").string(),
                                    "--report-html", (dir / "report.html").string(), "--cache-dir", (dir / "cache").string(),
                                    "--threads", "1", "-q"};
  };
  interrupt_across("signal_solve", args, {"lights.json"}, SIGINT, 8);
  // The cache folder holds whole cache files only: a later solve with it reads no damaged file.
  for (int k = 0; k < 8; ++k) {
    const fs::path dir = fs::path(HILIGHT_TEST_OUTPUT_DIR) / ("signal_solve_" + std::to_string(k));
    if (!fs::exists(dir / "cache")) continue;
    const auto again = test::run_hilight(args(dir));
    INFO(again.err);
    CHECK(again.exit_code == 0);
    CHECK(again.err.find("unusable") == std::string::npos);
  }
}
