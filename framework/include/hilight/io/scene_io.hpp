#pragma once
/// Loading scenes through assimp (OBJ+MTL, PLY, glTF/GLB and the rest).
#include "hilight/scene.hpp"

#include <filesystem>

namespace hilight {

struct SceneLoadOptions {
  /// Longest edge allowed after tessellation, in scene units; <= 0 picks
  /// kDefaultEdgeFraction of the scene diagonal.
  float max_edge = 0.f;
  /// The most vertices the tessellation may make (`--max-vertices`): a scene
  /// that would make more fails before committing the memory, naming it.
  size_t max_vertices = 10'000'000;
  /// The file's length unit (`--unit mm|cm|m|in|ft`) for formats that do not
  /// say (OBJ, PLY, STL, OFF, ...); empty: metres. glTF is in metres by its
  /// specification and assimp brings IFC to metres from its unit assignment:
  /// another unit for them is an InputError. The scene is computed in
  /// metres (scene_origin.hpp); `max_edge` is in the file's unit.
  std::string unit;
};

constexpr float kDefaultEdgeFraction = 1.f / 40.f;

/// Loads, validates and tessellates. Throws InputError naming the file.
Scene load_scene(const std::filesystem::path& path, const SceneLoadOptions& options = {});

/// Validates and tessellates an in-memory mesh (scene builders, tests); the
/// same checks and the same deterministic tessellation as load_scene.
Scene finish_scene(Scene raw, const SceneLoadOptions& options);

} // namespace hilight
