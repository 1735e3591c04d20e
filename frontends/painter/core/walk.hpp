#pragma once
/// Walk mode's movement (issue 20): a first-person eye at eye height over
/// the floor, moved horizontally and stopped by walls. Collisions use the
/// scene's ray tracer, the same geometry LightSpace tests free space with:
/// the eye never passes through a surface. Scenes are +Y up, in metres.
#include "hilight/ray_scene.hpp"

namespace hilight::painter {

struct WalkSettings {
  float eye_height = 1.6f;   ///< above the floor
  float radius = 0.2f;       ///< the eye keeps this far from walls
  float step_height = 0.35f; ///< lower obstacles (a stair's step) are climbed, not walls
};

/// The eye over the floor below `p`: eye_height above the first surface
/// straight down from `p` (`p` unchanged if there is none).
Vec3 stand_at(const RayScene& rays, const Vec3& p, const WalkSettings& settings = {});

/// Moves the eye by `move` (its horizontal part; y is ignored): as far as
/// the walls allow, checked at four heights from the knee (`step_height`
/// above the floor) to the eye, so a window's sill stops it too, stopping
/// `radius` from the wall's plane; the rest of the move slides along the
/// wall. Then the eye stands on the floor below its knee (a lower step is
/// climbed, a counter is not).
Vec3 walk_step(const RayScene& rays, const Vec3& eye, const Vec3& move, const WalkSettings& settings = {});

} // namespace hilight::painter
