#pragma once
/// What the painter's file browser shows of a folder (no window): its
/// sub-folders, then the files of the kinds asked for, each group by name,
/// hidden entries (a leading dot) left out. The browser panel draws it.
#include <filesystem>
#include <string>
#include <vector>

namespace hilight::painter {

/// The kinds of file a browser offers, by extension (lower case, with the
/// dot: ".ply"); empty: every file.
struct FileKinds {
  std::string name;                     ///< "targets (.ply .gltf .glb)"
  std::vector<std::string> extensions;
  /// `path`'s extension (any case) is one of them (always, when there are none).
  bool accepts(const std::filesystem::path& path) const;
};

/// The files and folders the browser offers, and what a scene, a target, a
/// lights file and an image may be (as the CLI reads and writes them).
FileKinds scene_kinds();
FileKinds target_kinds();
FileKinds lights_kinds();
FileKinds image_kinds();

struct FolderEntry {
  std::string name;
  bool folder = false;
};

struct FolderListing {
  std::filesystem::path folder;       ///< absolute, normalised
  std::vector<FolderEntry> entries;   ///< folders first, then files, each by name
  std::string error;                  ///< why it could not be read ("" when it could)
};

/// Lists `folder` for `kinds`. An unreadable folder gives no entries and an error.
FolderListing list_folder(const std::filesystem::path& folder, const FileKinds& kinds);

} // namespace hilight::painter
