#pragma once
// The Files panel's fields and the status line, log and help below it.
#include <string>
#include <vector>

namespace hilight::painter {

struct FilesPanelState {
  std::string target_path, lights_path, screenshot_path;
};

struct StatusState {
  std::vector<std::string> log;
  std::string line;
  bool show_help = false;
};

} // namespace hilight::painter
