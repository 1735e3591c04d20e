#include "ui/screen_pick.hpp"

namespace hilight::painter::ui {

std::optional<SurfacePick> pick_front_face(const RayScene& rays, const Ray& ray) {
  Vec3 origin = ray.origin;
  float skip = 4.f * rays.epsilon();
  // A handful of culled layers at most (a wall, a ceiling): then give up.
  for (int layer = 0; layer < 16; ++layer) {
    Hit hit = rays.intersect(origin, ray.direction);
    if (!hit.valid()) return std::nullopt;
    Vec3 position = rays.hit_position(hit);
    if (glm::dot(rays.face_normals()[hit.triangle], ray.direction) < 0.f) return SurfacePick{position, rays.hit_normal(hit)};
    origin = position + skip * ray.direction;
  }
  return std::nullopt;
}

std::optional<SurfacePick> pick_pixel(const RayScene& rays, const OrbitCamera& camera, float x, float y, float width,
                                      float height) {
  return pick_front_face(rays, camera.ray_through(x, y, width, height));
}

} // namespace hilight::painter::ui
