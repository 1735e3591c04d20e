#pragma once
/// Shared by the tests: the real plugin registry, renderers bound to scenes,
/// running the real `hilight` launcher, and small numeric helpers.
#include "hilight/io/scene_io.hpp"
#include "hilight/registry.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace test {

/// The registry loaded from the build's plugin folder (once per process).
hilight::Registry& registry();

/// True when renderer `name` cannot run here; then prints "SKIPPED: <why>",
/// which ctest reports as a skip. Use: `if (test::skip_without_renderer("povray")) return;`
bool skip_without_renderer(const std::string& name);

/// True when no X display is set (the painter's window tests need one; CI
/// runs them under xvfb-run); then prints "SKIPPED: <why>".
/// Use: `if (test::skip_without_display()) return;`
bool skip_without_display();

/// A renderer from the registry, bound to `scene`. `settings`: "key=value".
std::unique_ptr<hilight::Renderer> make_renderer(const std::string& name, std::shared_ptr<const hilight::Scene> scene,
                                                 const std::vector<std::string>& settings = {});

/// Tessellates a builder scene the way load_scene would.
std::shared_ptr<const hilight::Scene> finish(hilight::Scene raw, float max_edge);
/// A 10 x 10 floor with two 5 m walls meeting behind it (an open corner),
/// tessellated at 0.4: the analytic renderer's scene for the solve's stages.
std::shared_ptr<const hilight::Scene> open_corner();

struct RunResult {
  int exit_code = -1;
  std::string out, err;
  long max_rss_kb = 0;  ///< the child's peak resident memory
};
/// Runs `hilight <args>` (no shell), capturing stdout and stderr.
/// `address_space` > 0 caps the child's address space (RLIMIT_AS, bytes).
RunResult run_hilight(const std::vector<std::string>& args, unsigned long long address_space = 0);
/// Environment variables set in the child only (name, value).
using Environment = std::vector<std::pair<std::string, std::string>>;
/// As above, with `env` set in the child (the test's own environment is untouched).
RunResult run_hilight(const std::vector<std::string>& args, const Environment& env, unsigned long long address_space = 0);

/// The suite's CLI tests were written for one bounce (the paper's), which
/// the library still defaults to: run_hilight adds `--bounces 1` to render,
/// solve and export unless the test names --bounces itself. A test of the
/// CLI's own default (every bounce) holds one of these while it runs.
struct CliOwnBounces {
  CliOwnBounces();
  ~CliOwnBounces();
};

/// The suite's CLI solves were written for free placement: in a building
/// (an IFC with storeys, a closed interior) the CLI and the painter now hang
/// lights from the ceiling by default (issue 34 §7), so run_hilight adds
/// `--place anywhere` to a painted solve and to `paint` unless the test says
/// `anywhere` itself. A
/// test of the building default holds one of these while it runs.
struct CliOwnPlacement {
  CliOwnPlacement();
  ~CliOwnPlacement();
};

/// Runs `hilight <args>` and sends it `signal` after `seconds` unless it has
/// ended by then. exit_code: 128 + the signal when the signal ended it.
RunResult run_hilight_interrupted(const std::vector<std::string>& args, double seconds, int signal);

/// The red, green, blue of every vertex of a PLY (what `hilight render` writes).
std::vector<hilight::Rgb> ply_colours(const std::filesystem::path& path);

/// A file's bytes ("" if it cannot be read).
std::string read_file(const std::filesystem::path& path);

/// A fresh, empty folder under the build tree for one test's files.
std::filesystem::path output_dir(const std::string& test_name);
/// Writes text to a file (test inputs).
void write_text(const std::filesystem::path& path, const std::string& text);

/// D̄ of `a` against `reference`, as the solve reports it: ‖a − ref‖ / ‖ref‖
/// over all points and channels.
double dbar(const std::vector<hilight::Rgb>& a, const std::vector<hilight::Rgb>& reference);

/// A page as headless chromium rendered it: its DOM after scripts, and the
/// browser's log (console messages). `skip_without_chromium()` first: true
/// (with "SKIPPED: ...") when chromium is not installed.
bool skip_without_chromium();
struct BrowserPage {
  std::string dom, log;
};
BrowserPage open_in_chromium(const std::filesystem::path& html);
/// The page loaded its images and logged no console error or uncaught exception.
bool page_is_clean(const BrowserPage& page);

/// Number of lines in `text` (a one-line error has exactly 1).
size_t line_count(const std::string& text);

} // namespace test
