#include "core/file_listing.hpp"

#include <algorithm>
#include <cctype>

namespace hilight::painter {

namespace {

std::string lower(std::string text) {
  for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

} // namespace

bool FileKinds::accepts(const std::filesystem::path& path) const {
  if (extensions.empty()) return true;
  const std::string ext = lower(path.extension().string());
  return std::find(extensions.begin(), extensions.end(), ext) != extensions.end();
}

// Scenes: what hilight reads through assimp and IfcPlusPlus, the formats a designer meets.
FileKinds scene_kinds() {
  return {"scenes (.obj .gltf .glb .fbx .ply .dae .3ds .stl .ifc)",
          {".obj", ".gltf", ".glb", ".fbx", ".ply", ".dae", ".3ds", ".stl", ".ifc", ".blend", ".off"}};
}
FileKinds target_kinds() { return {"targets (.ply .gltf .glb)", {".ply", ".gltf", ".glb"}}; }
FileKinds lights_kinds() { return {"lights (.json .gltf .glb)", {".json", ".gltf", ".glb"}}; }
FileKinds image_kinds() { return {"images (.png)", {".png"}}; }

FolderListing list_folder(const std::filesystem::path& folder, const FileKinds& kinds) {
  namespace fs = std::filesystem;
  FolderListing listing;
  std::error_code ec;
  listing.folder = fs::absolute(folder, ec).lexically_normal();
  if (ec) listing.folder = folder;
  // "a/b/" normalises to "a/b/": the browser shows and joins it without the slash.
  if (listing.folder.has_relative_path() && listing.folder.filename().empty()) listing.folder = listing.folder.parent_path();
  fs::directory_iterator it(listing.folder, fs::directory_options::skip_permission_denied, ec);
  if (ec) {
    listing.error = "cannot read " + listing.folder.string() + ": " + ec.message();
    return listing;
  }
  for (; it != fs::directory_iterator(); it.increment(ec)) {
    if (ec) break;
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    std::error_code type_error;
    const bool folder_entry = it->is_directory(type_error);
    if (type_error) continue;  // a dangling link
    if (!folder_entry && !kinds.accepts(it->path())) continue;
    listing.entries.push_back({name, folder_entry});
  }
  if (ec) listing.error = "cannot read all of " + listing.folder.string() + ": " + ec.message();
  std::sort(listing.entries.begin(), listing.entries.end(), [](const FolderEntry& a, const FolderEntry& b) {
    if (a.folder != b.folder) return a.folder;
    return a.name < b.name;
  });
  return listing;
}

} // namespace hilight::painter
