#pragma once
/// Screen → world: the surface point under a window pixel, as the user sees
/// it. Faces turned away from the eye are culled in the view (one sees into a
/// room through its near walls), so picking passes through them too.
#include "core/region.hpp"
#include "core/view_clip.hpp"
#include "ui/orbit_camera.hpp"

#include <optional>

namespace hilight::painter::ui {

/// The first front-facing triangle along `ray` that `visible` shows (its
/// `t` counts from where the last culled layer was passed), nullopt on a miss.
std::optional<Hit> front_hit(const RayScene& rays, const Ray& ray, const Visibility& visible);

/// First front-facing surface along `ray` that `visible` shows (the section
/// and cutaway hide surfaces from picking as from the eye), nullopt on a miss.
std::optional<SurfacePick> pick_front_face(const RayScene& rays, const Ray& ray, const Visibility& visible);

} // namespace hilight::painter::ui
