#pragma once
/// Which scene vertex a target point stands for. `hilight render` writes one
/// point per scene vertex, shaded at that vertex's position with that
/// vertex's normal; a target point that lies on a vertex must be evaluated at
/// exactly that vertex (same position, normal, albedo, shading point and
/// random streams), or the solve sees a different picture than the renderer
/// made (issue 18). The rule, also in docs/rendering-model.md:
/// - a point within kVertexMatchTolerance · diagonal of one or more vertices
///   binds to one of them: with a normal, the vertex whose normal agrees best;
///   without one, the k-th such point of the file binds to the k-th vertex at
///   that position in vertex order (a rendered target keeps vertex order, so
///   split vertices at creases pair up one to one);
/// - any other point is a surface point (closest point, hilight::bind_target).
#include "hilight/scene.hpp"

#include <cstdint>
#include <vector>

namespace hilight {

/// Fraction of the scene diagonal within which a point counts as on a vertex.
/// ASCII targets with 6 significant digits stay inside it; distinct vertices
/// of a tessellated scene are much farther apart.
constexpr float kVertexMatchTolerance = 1e-5f;

/// For each point, the vertex it stands for, or -1. `normals` may be empty
/// (no normals: file order decides among split vertices) or hold zero
/// vectors for points without one.
std::vector<int32_t> match_vertices(const Scene& scene, const std::vector<Vec3>& positions, const std::vector<Vec3>& normals);

} // namespace hilight
