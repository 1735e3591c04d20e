#pragma once
/// Where lights may stand, before the designer's rules: the scene's box,
/// grown where the scene is open (Scene::light_bounds() is the result).
#include "hilight/scene.hpp"

#include <array>

namespace hilight {

/// Sides of a box, in the order side_openness() reports them.
enum class Side { MinusX, PlusX, MinusY, PlusY, MinusZ, PlusZ };

/// How open each side of the scene's box is: the share of a 32x32 grid over
/// that face whose view straight in meets no surface within a quarter of the
/// box's depth. A wall flush with the face: 0; a gable roof, a terrain
/// around a house, a product, a stage seen from above: above kOpenSide.
std::array<float, 6> side_openness(const Scene& scene);

/// A side at least this open may have lights beyond it (a room, closed on
/// every side, never does; a house with a terrain or a roof, a product do).
constexpr float kOpenSide = 0.1f;
/// How far beyond an open side, as a share of the diagonal: key and fill
/// lights of a product shot stand about one diagonal from its centre.
constexpr float kOpenMargin = 0.5f;

/// Scene::light_bounds() grown by kOpenMargin of the diagonal beyond every
/// side at least kOpenSide open: where a solve looks when the lights inside
/// cannot explain the target (a product lit from outside). Equal to
/// light_bounds() for a scene closed on every side.
Bounds open_light_bounds(const Scene& scene);

} // namespace hilight
