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

/// A furnished home of several rooms joined by doorways (issue 33): the
/// ground floor of the IFC house (AC14-FZK-Haus by KIT/IAI) as a flat of
/// its own. Its living room (with the stair), hall and three rooms, their
/// inner doors' leaves taken out so that doorways join them; cut at the top
/// of the upper floor's slab (y = 2.7) under a flat roof slab laid over it
/// (which closes the stair's opening); the terrain left out. Closed: floor,
/// walls with their glazed windows and doors, ceiling. Furnished with the
/// house's own bed and table and with real models of assimp-testmodels
/// (OBJ, PLY, 3DS, glTF, MS3D) on tables, a sideboard and the floor, beside
/// sofas, shelves and wardrobes made of boxes. Metres, the ceiling at 2.5.
/// Zones: where ceiling lamps hang in each room (0.15–0.4 m below it).
BuiltScene furnished_home();
/// The home's tessellations (`--max-edge`): for `hilight bench solve`
/// 258,617 render vertices and 419k triangles, the size of a real furnished
/// flat; for the tests 62,844 vertices (the default, the diagonal/40, makes
/// 109k).
constexpr float kHomeBenchEdge = 0.2f, kHomeTestEdge = 0.8f;

} // namespace hilight::builders
