// The `hilight` launcher: loads every plugin module, then hands the command to
// the frontend module that owns it. It knows no command itself.
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
    // Edits (insert, delete, replace, swap two neighbours) from given to c.name.
    const std::string& a = given;
    const std::string& b = c.name;
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (size_t i = 1; i <= a.size(); ++i)
      for (size_t j = 1; j <= b.size(); ++j) {
        d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
        if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    if (d[a.size()][b.size()] < best_distance) best_distance = d[a.size()][b.size()], best = c.name;
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
