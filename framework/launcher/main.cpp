// The `hilight` launcher: loads every plugin module, then hands the command to
// the frontend module that owns it. It knows no command itself.
#include "hilight/edit_distance.hpp"
#include "hilight/error.hpp"
#include "hilight/plugin.hpp"
#include "hilight/registry.hpp"
#include "hilight/version.hpp"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace {

void print_usage(hilight::Registry& registry) {
  std::cout << "usage: hilight <command> [options]   (hilight <command> --help for its options)\n\ncommands:\n";
  for (const auto& c : registry.all_commands()) std::printf("  %-10s %s\n", c.name.c_str(), c.summary.c_str());
  if (registry.all_commands().empty())
    std::cout << "  (no frontend module found; is lib/hilight/ beside bin/, or HILIGHT_PLUGIN_PATH set?)\n";
}

/// "; did you mean 'solve'?" for a slip of a key or two ("slove"), else "".
std::string nearest_command(hilight::Registry& registry, const std::string& given) {
  std::string best;
  size_t best_distance = 3;
  for (const auto& c : registry.all_commands()) {
    const size_t distance = hilight::edit_distance(given, c.name);
    if (distance < best_distance) best_distance = distance, best = c.name;
  }
  return best.empty() || best_distance * 3 > std::max<size_t>(3, given.size()) ? "" : "; did you mean '" + best + "'?";
}

} // namespace

int main(int argc, char** argv) {
  hilight::Registry registry;
  for (const auto& dir : hilight::Registry::default_search_dirs("/proc/self/exe")) registry.load_directory(dir.path, dir.origin);
  // Never a silent pick between two plugins of one kind and name.
  for (const auto* m : registry.shadowed())
    std::cerr << "hilight: warning: " << m->path.string() << " is not loaded: " << m->problem << "\n";

  std::string command = argc > 1 ? argv[1] : "";
  if (command.empty() || command == "--help" || command == "-h" || command == "help") {
    print_usage(registry);
    return command.empty() ? hilight::kExitInputError : 0;
  }
  if (command == "--version") {
    // The plugin ABI and build key too: what a plugin built elsewhere must match.
    std::cout << "hilight " HILIGHT_VERSION " (plugin ABI " << HILIGHT_ABI_VERSION << ", build key " HILIGHT_BUILD_KEY ")\n";
    return 0;
  }
  try {
    hilight::Frontend* frontend = registry.frontend_for(command);
    if (!frontend) {
      std::cerr << "hilight: unknown command '" << command << "'" << nearest_command(registry, command) << " (hilight --help lists them)\n";
      return hilight::kExitInputError;
    }
    std::vector<std::string> args(argv + 2, argv + argc);
    return frontend->run(command, args, registry);
  } catch (const hilight::InputError& e) {
    std::cerr << "hilight: error: " << e.what() << "\n";
    return hilight::kExitInputError;
  } catch (const std::bad_alloc&) {
    std::cerr << "hilight: error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "hilight: internal error: " << e.what() << "\n";
    return 1;
  }
}
