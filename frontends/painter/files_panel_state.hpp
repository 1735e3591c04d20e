#pragma once
// The Files panel's fields, its file browser, and the status line, log and help below it.
#include "core/file_listing.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace hilight::painter {

/// What the file browser was opened for.
enum class FilePurpose { OpenScene, OpenTarget, SaveTarget, OpenLights, SaveLights, Screenshot };

struct FileBrowserState {
  std::optional<FilePurpose> purpose;  ///< open while set
  std::filesystem::path folder;        ///< shown (the last one used, else the working folder)
  std::string name;                    ///< the file name chosen or typed
  std::string folder_text;             ///< the folder field, as typed
  FolderListing listing;
  bool stale = true;                   ///< list the folder again
};

struct FilesPanelState {
  std::string target_path, lights_path, screenshot_path;
  FileBrowserState browser;
};

struct StatusState {
  std::vector<std::string> log;
  std::string line;
  bool show_help = false;
};

} // namespace hilight::painter
