#include "core/walk.hpp"

#include <algorithm>

namespace hilight::painter {

Vec3 stand_at(const RayScene& rays, const Vec3& p, const WalkSettings& settings) {
  const Hit hit = rays.intersect(p, Vec3(0.f, -1.f, 0.f));
  if (!hit.valid()) return p;
  return Vec3(p.x, rays.hit_position(hit).y + settings.eye_height, p.z);
}

namespace {

/// The eye over the floor below it, looking down from knee height: what is
/// higher (a counter the body rays missed) is not stepped onto.
Vec3 settle(const RayScene& rays, const Vec3& eye, const WalkSettings& settings) {
  const Vec3 knee = eye - Vec3(0.f, settings.eye_height - settings.step_height, 0.f);
  const Hit hit = rays.intersect(knee, Vec3(0.f, -1.f, 0.f));
  if (!hit.valid()) return eye;  // no floor below (outside a model without ground): stay level
  return Vec3(eye.x, rays.hit_position(hit).y + settings.eye_height, eye.z);
}

} // namespace

Vec3 walk_step(const RayScene& rays, const Vec3& eye, const Vec3& move, const WalkSettings& settings) {
  Vec3 rest(move.x, 0.f, move.z);
  Vec3 position = eye;
  // At most three slides (a corner stops the move; more would jitter).
  for (int slide = 0; slide < 3; ++slide) {
    const float length = glm::length(rest);
    if (!(length > 1e-6f)) break;
    const Vec3 direction = rest / length;
    float free = length;
    Vec3 wall(0.f);
    // The body from knee to eye, at four heights: a window's sill stops it as a wall does.
    const float span = settings.eye_height - settings.step_height;
    for (const float below : {0.f, span / 3.f, 2.f * span / 3.f, span}) {
      const Hit hit = rays.intersect(position - Vec3(0.f, below, 0.f), direction, length + 20.f * settings.radius);
      if (!hit.valid()) continue;
      // Stop `radius` from the wall's plane (farther back along a slanting move).
      const Vec3 normal = rays.face_normals()[hit.triangle];
      const float back = settings.radius / std::max(std::abs(glm::dot(direction, normal)), 0.05f);
      if (hit.t - back < free) {
        free = std::max(0.f, hit.t - back);
        wall = normal;
      }
    }
    position += direction * free;
    if (free >= length) break;
    // What is left slides along the wall: its component into the wall goes.
    rest = direction * (length - free);
    Vec3 across(wall.x, 0.f, wall.z);
    if (!(glm::length(across) > 1e-6f)) break;
    across = glm::normalize(across);
    rest -= across * glm::dot(rest, across);
  }
  return settle(rays, position, settings);
}

} // namespace hilight::painter
