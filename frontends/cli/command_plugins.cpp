// hilight plugins: every module found, its kind, version, and whether it can run.
#include "cli_common.hpp"
#include "commands.hpp"

#include <cstdio>

namespace hilight::cli {

int run_plugins(const std::vector<std::string>& args, Registry& registry) {
  CLI::App app("List plugin modules, their versions and availability", "plugins");
  bool verbose = false;
  app.add_flag("-v,--verbose", verbose, "also print each module's path");
  if (auto code = parse_arguments(app, args)) return *code;

  if (registry.modules().empty()) {
    std::printf("no plugin modules found (looked in lib/hilight beside bin/ and HILIGHT_PLUGIN_PATH)\n");
    return 1;
  }
  std::printf("%-10s %-12s %-8s %s\n", "KIND", "NAME", "VERSION", "STATUS");
  for (const auto& m : registry.modules()) {
    std::string status;
    if (!m->loaded) status = "not loaded: " + m->problem;
    else if (std::string why = m->probe ? m->probe() : std::string(); !why.empty()) status = "unavailable: " + why;
    else status = "ok - " + m->description + (m->detail ? " (" + m->detail() + ")" : std::string());
    std::printf("%-10s %-12s %-8s %s\n", m->kind.empty() ? "?" : m->kind.c_str(), m->name.c_str(),
                m->version.empty() ? "-" : m->version.c_str(), status.c_str());
    if (verbose) std::printf("           %s\n", m->path.c_str());
  }
  return 0;
}

} // namespace hilight::cli
