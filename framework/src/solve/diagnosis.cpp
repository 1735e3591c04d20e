#include "hilight/solve/diagnosis.hpp"

#include "hilight/solve/seeder.hpp"

#include <tbb/parallel_for.h>

namespace hilight {

Unreachable find_unreachable(const Target& target, const LightSpace& space, size_t max_points) {
  // A 16-cell grid (0.75 m in a 12 m flat) and every room's own places: an
  // 8-cell grid over a flat of several rooms can miss a small room, and its
  // lit points would be blamed (issue 33).
  const std::vector<Vec3> places = free_places_in_every_room(space, 16);
  const RayScene& rays = space.rays();
  const size_t n = target.size(), stride = std::max<size_t>(1, n / std::max<size_t>(1, max_points));
  std::vector<size_t> points;
  for (size_t i = 0; i < n; i += stride) points.push_back(i);
  std::vector<double> energy(points.size(), 0.0), unreached(points.size(), 0.0);
  tbb::parallel_for(size_t(0), points.size(), [&](size_t k) {
    const size_t i = points[k];
    const DVec3 v(target.value[i]);
    energy[k] = double(target.weight[i]) * glm::dot(v, v);
    if (!(energy[k] > 0)) return;
    const Vec3& p = target.points.positions[i];
    const Vec3& normal = target.points.normals[i];
    for (const Vec3& place : places) {
      Vec3 to = place - p;
      const float distance = glm::length(to);
      if (!(distance > 0.f)) continue;
      to /= distance;
      // Lit from either side (two-sided surfaces): start on the side facing the place,
      // and a step toward it: a point on a crease (a floor's edge at a wall) lies in the
      // other face's plane, and a ray starting there would hit that face at once.
      const Vec3 origin = p + (glm::dot(normal, to) >= 0.f ? 1.f : -1.f) * rays.epsilon() * normal + rays.epsilon() * to;
      if (!rays.occluded(origin, to, distance - rays.epsilon())) return;
    }
    unreached[k] = energy[k];
  });
  Unreachable found;
  double total = 0, lost = 0;
  for (size_t k = 0; k < points.size(); ++k) {
    total += energy[k], lost += unreached[k];
    if (unreached[k] > 0) found.points.push_back(uint32_t(points[k]));
  }
  found.share = total > 0 ? lost / total : 0.0;
  return found;
}

double unreachable_share(const Target& target, const LightSpace& space, size_t max_points) {
  return find_unreachable(target, space, max_points).share;
}

} // namespace hilight
