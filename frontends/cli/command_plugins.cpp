// hilight plugins: every module found, its kind, version, whether it can run,
// and where it was loaded from.
#include "cli_common.hpp"
#include "commands.hpp"

#include <cstdio>

namespace hilight::cli {

int run_plugins(const std::vector<std::string>& args, Registry& registry) {
  CLI::App app("List plugin modules, their versions and availability", "plugins");
  if (auto code = parse_arguments(app, args)) return *code;

  if (registry.modules().empty()) {
    std::printf("no plugin modules found (looked in HILIGHT_PLUGIN_PATH, %s and lib/hilight beside bin/)\n",
                Registry::user_plugin_dir().c_str());
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
    std::printf("           from %s%s\n", m->path.c_str(), m->origin.empty() ? "" : (" (" + m->origin + ")").c_str());
  }
  return 0;
}

} // namespace hilight::cli
