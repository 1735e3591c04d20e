#pragma once
/// One function per CLI subcommand, each in its own command_<name>.cpp.
#include "hilight/registry.hpp"

#include <string>
#include <vector>

namespace hilight::cli {
int run_info(const std::vector<std::string>& args);
int run_cache(const std::vector<std::string>& args);
int run_render(const std::vector<std::string>& args, Registry& registry);
int run_plugins(const std::vector<std::string>& args, Registry& registry);
int run_solve(const std::vector<std::string>& args, Registry& registry);
int run_export(const std::vector<std::string>& args, Registry& registry);
int run_luminaire(const std::vector<std::string>& args);
int run_target(const std::vector<std::string>& args);
} // namespace hilight::cli
