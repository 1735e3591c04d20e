#pragma once
/// Surface points of chosen scene vertices (for the renderer's batch calls).
#include "hilight/scene.hpp"
#include "hilight/surface_points.hpp"

#include <cstdint>
#include <vector>

namespace hilight::painter {

SurfacePoints points_of_vertices(const Scene& scene, const std::vector<uint32_t>& vertices);

} // namespace hilight::painter
