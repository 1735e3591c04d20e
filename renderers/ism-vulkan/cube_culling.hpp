#pragma once
/// Which triangles each cube face around a light can show: lavapipe's cost
/// per shadow map is mostly vertex and triangle setup, so every face draws
/// only the triangles that are not wholly outside its frustum (about a sixth).
#include "triangle_raster.hpp"
#include "hilight/lighting.hpp"
#include "hilight/scene.hpp"

#include <vector>

namespace hilight::ism {

/// Appends, for each of the six faces around the light (in cube_views
/// order), the triangles not wholly outside that face's pyramid: three vertex
/// indices each to `indices`, the scene triangle to `ids`, and the face's
/// draw. A spotlight's faces outside its cone get empty draws.
void cull_to_cube_faces(const Scene& scene, const Light& light, std::vector<uint32_t>& indices, std::vector<uint32_t>& ids,
                        std::vector<RasterDraw>& draws);

} // namespace hilight::ism
