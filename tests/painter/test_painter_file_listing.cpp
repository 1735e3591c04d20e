// The painter's file browser lists a folder as a designer expects of a file
// dialog (core/file_listing.hpp): folders first, then the files of the kind
// asked for (any case of their extension), by name, hidden entries left out.
#include "core/file_listing.hpp"
#include "../support.hpp"

#include <catch2/catch.hpp>

namespace fs = std::filesystem;
using namespace hilight::painter;

namespace {

std::vector<std::string> names(const FolderListing& listing) {
  std::vector<std::string> out;
  for (const FolderEntry& e : listing.entries) out.push_back(e.folder ? e.name + "/" : e.name);
  return out;
}

} // namespace

TEST_CASE("painter: the file browser lists folders, then the files of the kind asked for", "[painter][files]") {
  const fs::path dir = test::output_dir("painter_file_listing");
  for (const char* name : {"b-target.ply", "a-lights.JSON", "notes.txt", ".hidden.ply", "room.OBJ", "shot.png", "scene.glb"})
    test::write_text(dir / name, "x");
  fs::create_directories(dir / "later");
  fs::create_directories(dir / "Earlier");
  fs::create_directories(dir / ".cache");

  const FolderListing targets = list_folder(dir, target_kinds());
  CHECK(targets.error.empty());
  CHECK(targets.folder == fs::absolute(dir).lexically_normal());
  CHECK(names(targets) == std::vector<std::string>{"Earlier/", "later/", "b-target.ply", "scene.glb"});
  CHECK(names(list_folder(dir, lights_kinds())) == std::vector<std::string>{"Earlier/", "later/", "a-lights.JSON", "scene.glb"});
  CHECK(names(list_folder(dir, scene_kinds())) == std::vector<std::string>{"Earlier/", "later/", "b-target.ply", "room.OBJ", "scene.glb"});
  CHECK(names(list_folder(dir, image_kinds())) == std::vector<std::string>{"Earlier/", "later/", "shot.png"});
  CHECK(names(list_folder(dir, FileKinds{})).size() == 8);  // every file and folder but the hidden ones
  // A folder given with a trailing slash or "..": the same folder, shown without them.
  CHECK(list_folder(dir / "later" / "..", target_kinds()).folder == fs::absolute(dir).lexically_normal());
  CHECK(list_folder(dir.string() + "/", target_kinds()).folder == fs::absolute(dir).lexically_normal());
  // A folder that is not there: no entries, and why.
  const FolderListing missing = list_folder(dir / "gone", target_kinds());
  CHECK(missing.entries.empty());
  CHECK_THAT(missing.error, Catch::Contains("cannot read") && Catch::Contains("gone"));
  CHECK(target_kinds().accepts("x.PLY"));
  CHECK_FALSE(target_kinds().accepts("x.ply.txt"));
}
