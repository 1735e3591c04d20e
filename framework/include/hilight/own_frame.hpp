#pragma once
/// A scene's own frame (issue 19): the centre of its smallest enclosing ball
/// and the principal axes of its surface (area-weighted second moments about
/// that centre), each signed so that the surface's third moment along it is
/// positive, and right-handed. It moves, turns and scales with the scene, so
/// what is laid out in it — the bounce's random streams and sample frames —
/// is the same for the same scene placed anyhow. Where the surface is
/// symmetric (two equal moments, or no skew along an axis) the scene does
/// not decide the axes, and a turned copy may get others.
#include "hilight/math.hpp"

namespace hilight {

struct Scene;

struct OwnFrame {
  Vec3 centre{0.f};
  glm::mat3 axes{1.f};  ///< columns: the frame's axes, in world coordinates
  /// A world direction (or offset from the centre) in the frame's coordinates.
  Vec3 to_own(const Vec3& world) const { return glm::transpose(axes) * world; }
  /// A direction given in the frame's coordinates, in the world's.
  Vec3 to_world(const Vec3& own) const { return axes * own; }
};

OwnFrame own_frame(const Scene& scene);

} // namespace hilight
