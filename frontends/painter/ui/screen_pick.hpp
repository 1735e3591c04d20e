#pragma once
/// Screen → world: the surface point under a window pixel, as the user sees
/// it. Faces turned away from the eye are culled in the view (one sees into a
/// room through its near walls), so picking passes through them too.
#include "core/region.hpp"
#include "ui/orbit_camera.hpp"

#include <optional>

namespace hilight::painter::ui {

/// First front-facing surface along `ray`, nullopt on a miss.
std::optional<SurfacePick> pick_front_face(const RayScene& rays, const Ray& ray);

/// The surface under pixel (x, y) of a width × height view.
std::optional<SurfacePick> pick_pixel(const RayScene& rays, const OrbitCamera& camera, float x, float y, float width,
                                      float height);

} // namespace hilight::painter::ui
