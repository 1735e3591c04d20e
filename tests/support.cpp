#include "support.hpp"

#include "hilight/fixtures/scene_builders.hpp"
#include "hilight/io/ply_reader.hpp"

#include <cstdlib>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <iostream>
#include <regex>

#include <array>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace test {

namespace fs = std::filesystem;

double dbar(const std::vector<hilight::Rgb>& a, const std::vector<hilight::Rgb>& reference) {
  double num = 0, den = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    const hilight::DVec3 d = hilight::DVec3(a[i]) - hilight::DVec3(reference[i]);
    num += glm::dot(d, d);
    den += glm::dot(hilight::DVec3(reference[i]), hilight::DVec3(reference[i]));
  }
  return std::sqrt(num / den);
}

bool skip_without_renderer(const std::string& name) {
  // Not built in this configuration (e.g. ism-vulkan without libvulkan-dev):
  // a skip. A module that was built but failed to load is a failure (the
  // registry's error names why).
  const std::string file = "hilight-renderer-" + name + ".so";
  const bool built = std::any_of(registry().modules().begin(), registry().modules().end(),
                                 [&](const auto& m) { return m->path.filename() == file; });
  if (!built) {
    std::cout << "SKIPPED: the " << name << " renderer was not built in this configuration" << std::endl;
    return true;
  }
  std::string why = registry().renderer_unavailable_reason(name);
  if (!why.empty()) std::cout << "SKIPPED: " << name << " renderer unavailable: " << why << std::endl;
  return !why.empty();
}

bool skip_without_display() {
  const char* display = std::getenv("DISPLAY");
  if (display && *display) return false;
  std::cout << "SKIPPED: no display (run the tests under xvfb-run)" << std::endl;
  return true;
}

hilight::Registry& registry() {
  static hilight::Registry reg = [] {
    hilight::Registry r;
    r.load_directory(HILIGHT_PLUGIN_DIR, "installed");
    // Plugins built outside the tree (tests/sdk/test_example_plugin.sh) join
    // through HILIGHT_PLUGIN_PATH, as they join the launcher.
    for (const auto& dir : hilight::Registry::default_search_dirs(HILIGHT_BINARY))
      if (dir.origin == "HILIGHT_PLUGIN_PATH") r.load_directory(dir.path, dir.origin);
    return r;
  }();
  return reg;
}

std::unique_ptr<hilight::Renderer> make_renderer(const std::string& name, std::shared_ptr<const hilight::Scene> scene,
                                                 const std::vector<std::string>& settings) {
  auto renderer = registry().create_renderer(name, hilight::Properties::from_assignments(settings));
  renderer->set_scene(std::move(scene));
  return renderer;
}

std::shared_ptr<const hilight::Scene> finish(hilight::Scene raw, float max_edge) {
  return std::make_shared<const hilight::Scene>(hilight::finish_scene(std::move(raw), {max_edge}));
}

std::shared_ptr<const hilight::Scene> open_corner() {
  hilight::Scene raw;
  hilight::builders::add_quad(raw, {0, 0, 0}, {0, 0, 10}, {10, 0, 10}, {10, 0, 0}, hilight::Rgb(0.7f), "floor");
  hilight::builders::add_quad(raw, {0, 0, 0}, {10, 0, 0}, {10, 5, 0}, {0, 5, 0}, hilight::Rgb(0.6f, 0.65f, 0.7f), "back wall");
  hilight::builders::add_quad(raw, {0, 0, 0}, {0, 5, 0}, {0, 5, 10}, {0, 0, 10}, hilight::Rgb(0.5f), "side wall");
  return finish(std::move(raw), 0.4f);
}

std::vector<hilight::Rgb> ply_colours(const fs::path& path) {
  const hilight::PlyVertices v = hilight::read_ply_vertices(path);
  std::vector<hilight::Rgb> out(v.count);
  for (size_t i = 0; i < v.count; ++i)
    out[i] = hilight::Rgb(float(v.properties.at("red")[i]), float(v.properties.at("green")[i]), float(v.properties.at("blue")[i]));
  return out;
}

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

RunResult run_hilight(const std::vector<std::string>& args, unsigned long long address_space) {
  return run_hilight(args, Environment{}, address_space);
}

namespace {

bool g_cli_own_bounces = false;

/// `args` with --bounces 1 for render, solve and export when the test does
/// not say (support.hpp, CliOwnBounces).
std::vector<std::string> with_suite_bounces(const std::vector<std::string>& args) {
  if (g_cli_own_bounces || args.empty() || (args[0] != "render" && args[0] != "solve" && args[0] != "export")) return args;
  for (const auto& a : args)
    if (a == "--bounces" || a.rfind("--bounces=", 0) == 0 || a == "--help" || a == "-h") return args;
  std::vector<std::string> out = args;
  out.insert(out.end(), {"--bounces", "1"});
  return out;
}

bool g_cli_own_placement = false;

/// `args` with --place anywhere for a painted solve (not criteria, a .json
/// target) and the painter when the test does not say (support.hpp, CliOwnPlacement).
std::vector<std::string> with_suite_placement(const std::vector<std::string>& args) {
  if (g_cli_own_placement || args.empty() || (args[0] != "solve" && args[0] != "paint")) return args;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "anywhere" || args[i] == "--help" || args[i] == "-h") return args;
    if (args[i] == "--target" && i + 1 < args.size() && args[i + 1].size() >= 5 && args[i + 1].substr(args[i + 1].size() - 5) == ".json") return args;
  }
  std::vector<std::string> out = args;
  out.insert(out.end(), {"--place", "anywhere"});
  return out;
}

RunResult spawn_hilight(const std::vector<std::string>& args, const Environment& env, unsigned long long address_space,
                        double interrupt_after, int interrupt_signal) {
  // Output goes through files, not pipes, so large outputs cannot deadlock.
  static int counter = 0;
  fs::path dir = output_dir("run_hilight_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  fs::path out_path = dir / "stdout.txt", err_path = dir / "stderr.txt";
  // The child's environment, built before fork (no allocation in the child).
  std::vector<std::string> environment;
  for (char** e = environ; *e; ++e) {
    const std::string entry = *e;
    bool replaced = false;
    for (const auto& [name, value] : env) replaced |= entry.rfind(name + "=", 0) == 0;
    if (!replaced) environment.push_back(entry);
  }
  for (const auto& [name, value] : env) environment.push_back(name + "=" + value);
  std::vector<char*> envp;
  for (auto& entry : environment) envp.push_back(entry.data());
  envp.push_back(nullptr);
  std::vector<std::string> copy = with_suite_placement(with_suite_bounces(args));  // before fork: the child allocates nothing
  pid_t pid = ::fork();
  if (pid == 0) {
    if (address_space) {
      struct rlimit lim = {rlim_t(address_space), rlim_t(address_space)};
      ::setrlimit(RLIMIT_AS, &lim);
    }
    int out = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    int in = ::open("/dev/null", O_RDONLY);
    ::dup2(out, 1);
    ::dup2(err, 2);
    ::dup2(in, 0);
    std::vector<char*> argv;
    std::string bin = HILIGHT_BINARY;
    argv.push_back(bin.data());
    for (auto& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execve(bin.c_str(), argv.data(), envp.data());
    ::_exit(127);
  }
  int status = 0;
  struct rusage usage = {};
  bool waited = false;
  if (interrupt_after > 0) {  // poll until it ends or the time comes, then signal it
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(interrupt_after);
    while (!waited && std::chrono::steady_clock::now() < until) {
      waited = ::wait4(pid, &status, WNOHANG, &usage) == pid;
      if (!waited) ::usleep(2000);
    }
    if (!waited) ::kill(pid, interrupt_signal);
  }
  if (!waited) ::wait4(pid, &status, 0, &usage);
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = read_file(out_path);
  r.err = read_file(err_path);
  r.max_rss_kb = usage.ru_maxrss;
  return r;
}

} // namespace

RunResult run_hilight(const std::vector<std::string>& args, const Environment& env, unsigned long long address_space) {
  return spawn_hilight(args, env, address_space, 0.0, 0);
}

RunResult run_hilight_interrupted(const std::vector<std::string>& args, double seconds, int signal) {
  return spawn_hilight(args, {}, 0, seconds, signal);
}

CliOwnBounces::CliOwnBounces() { g_cli_own_bounces = true; }
CliOwnBounces::~CliOwnBounces() { g_cli_own_bounces = false; }
CliOwnPlacement::CliOwnPlacement() { g_cli_own_placement = true; }
CliOwnPlacement::~CliOwnPlacement() { g_cli_own_placement = false; }

fs::path output_dir(const std::string& test_name) {
  fs::path dir = fs::path(HILIGHT_TEST_OUTPUT_DIR) / test_name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

size_t line_count(const std::string& text) {
  size_t n = 0;
  for (char c : text) n += c == '\n';
  if (!text.empty() && text.back() != '\n') ++n;
  return n;
}

bool skip_without_chromium() {
  if (std::system("chromium --version > /dev/null 2>&1") == 0) return false;
  std::cout << "SKIPPED: chromium is not installed (setup.sh installs it)" << std::endl;
  return true;
}

BrowserPage open_in_chromium(const std::filesystem::path& html) {
  const auto dom = html.parent_path() / (html.stem().string() + ".dom.html"), log = html.parent_path() / (html.stem().string() + ".chromium.log");
  const std::string command = "chromium --headless --no-sandbox --disable-gpu --enable-logging=stderr --v=0 --dump-dom 'file://" +
                              std::filesystem::absolute(html).string() + "' > '" + dom.string() + "' 2> '" + log.string() + "'";
  if (std::system(command.c_str()) != 0) return {};
  return {read_file(dom), read_file(log)};
}

bool page_is_clean(const BrowserPage& page) {
  // The report's own script sets data-images-ok once every embedded image decoded.
  return page.dom.find("data-images-ok=\"true\"") != std::string::npos &&
         !std::regex_search(page.log, std::regex("CONSOLE[^\\n]*(Uncaught|rror)")) && page.log.find("Uncaught") == std::string::npos;
}

} // namespace test
