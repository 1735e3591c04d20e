#pragma once
/// The `paint` command of the launcher.
#include "hilight/registry.hpp"

#include <string>
#include <vector>

namespace hilight::painter {

int run_paint(const std::vector<std::string>& args, Registry& registry);

} // namespace hilight::painter
