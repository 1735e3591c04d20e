#pragma once
/// At a crease, the face that blocks a point's light can be a sliver seen
/// edge-on from the light, thinner than any shadow-map texel (the side of a
/// table top, from a lamp above its edge). Such faces are near the point:
/// for each point this finds the nearest triangles not in its own plane, so
/// the direct-light stage can test them along the exact ray too.
#include "hilight/scene.hpp"
#include "hilight/surface_points.hpp"

#include <cstdint>
#include <vector>

namespace hilight::ism {

constexpr uint32_t kCreaseCandidates = 16;  ///< per point; unused slots are ~0u

/// kCreaseCandidates triangle indices per point (~0u = none): the nearest
/// triangles within `reach` of the point whose plane differs from its own
/// (normal `normals[i]`).
std::vector<uint32_t> crease_candidates(const Scene& scene, const SurfacePoints& points, float reach);

} // namespace hilight::ism
