#pragma once
/// Scenes built from real models that nobody here made: Debian's
/// assimp-testmodels (installed by setup.sh). Shared by tests, benchmarks
/// and the painter's tests, like hilight/scene_builders.hpp; raw meshes to
/// pass through finish_scene(). Each throws InputError naming the model
/// file when it is missing.
#include "hilight/built_scenes.hpp"
#include "hilight/scene.hpp"

#include <filesystem>

namespace hilight::builders {

/// Folder of the assimp test models: $HILIGHT_TESTMODELS, else
/// /usr/share/assimp/models.
std::filesystem::path testmodels_dir();

/// Appends `model` uniformly scaled so that its largest extent is `size`,
/// standing on y = `floor_y` (its lowest point) centred at (x, z).
void add_model(Scene& scene, const Scene& model, float x, float floor_y, float z, float size);

/// The untessellated mesh of a test model (path relative to testmodels_dir()).
Scene test_model(const std::string& relative_path);

/// Two smooth-shaded curved models (the Wuson, the spider) on a 4 x 4 floor
/// before a wall: where renderers' shading points differ (issue 11).
Scene curved_models_on_floor();

/// A 6 x 3 x 5 room furnished with real models: a table (boxes) with the
/// Wuson on it, the spider and the Cesium milk truck on the floor, a rock
/// (fels) on a cabinet. Units are metres; the ceiling is at y = 3.
Scene real_furnished_room();

/// A real product in open space: the glTF 2-cylinder engine (156k vertices,
/// in its own units), with six zones around and above it, outside its
/// bounds, where a key, a fill and a rim light stand (far lights).
BuiltScene engine_product();

} // namespace hilight::builders
