#pragma once
/// The exposure a view is shown with (issue 36): picked from what its pixels
/// show, as `hilight render` picks a PNG's from its pixels. Walls hide the
/// rooms behind them and the frustum what lies aside: a bright room next
/// door, in the frustum but behind a wall, must not darken the room in view.
#include "core/view_clip.hpp"
#include "hilight/ray_scene.hpp"
#include "ui/orbit_camera.hpp"

#include <functional>
#include <vector>

namespace hilight::painter::ui {

/// auto_exposure of the per-vertex `radiance` where rays through a grid of
/// the view's pixels first meet a surface the view shows (front faces that
/// `visible` leaves, as picking finds them), blended from the triangle's
/// corners. `ray_through(x, y)`: the view's ray through the point (x, y) of
/// the window, both in [0, 1] from its top left. 0 when fewer than 16 rays
/// meet something, or all of it is black: too little to judge.
float view_exposure(const RayScene& rays, const std::vector<Rgb>& radiance, const std::function<Ray(float, float)>& ray_through,
                    const Visibility& visible);

} // namespace hilight::painter::ui
