#include "ui/screen_pick.hpp"

namespace hilight::painter::ui {

std::optional<Hit> front_hit(const RayScene& rays, const Ray& ray, const Visibility& visible) {
  Vec3 origin = ray.origin;
  float skip = 4.f * rays.epsilon();
  // A handful of culled layers at most (a wall, a ceiling): then give up;
  // hidden by a section or cutaway, a whole storey may be in the way.
  const int layers = visible.all_visible() ? 16 : 256;
  for (int layer = 0; layer < layers; ++layer) {
    Hit hit = rays.intersect(origin, ray.direction);
    if (!hit.valid()) return std::nullopt;
    Vec3 position = rays.hit_position(hit);
    if (glm::dot(rays.face_normals()[hit.triangle], ray.direction) < 0.f && visible.point(hit.triangle, position)) return hit;
    origin = position + skip * ray.direction;
  }
  return std::nullopt;
}

std::optional<SurfacePick> pick_front_face(const RayScene& rays, const Ray& ray, const Visibility& visible) {
  const std::optional<Hit> hit = front_hit(rays, ray, visible);
  if (!hit) return std::nullopt;
  return SurfacePick{rays.hit_position(*hit), rays.hit_normal(*hit)};
}

} // namespace hilight::painter::ui
