#pragma once
/// Deterministic, crack-free refinement: longest-edge bisection until no edge
/// is longer than max_edge. Midpoints are shared through an edge map, so
/// neighbouring triangles split shared edges at the same vertex.
#include "hilight/scene.hpp"

namespace hilight {

/// Refines `scene` in place. Vertex order: the original vertices, then new
/// midpoints in the order they were created (triangles in order, depth first).
void tessellate(Scene& scene, float max_edge);

} // namespace hilight
