#include "ui/view_exposure.hpp"

#include "ui/screen_pick.hpp"
#include "ui/vertex_colours.hpp"

#include <optional>
#include <tbb/parallel_for.h>

namespace hilight::painter::ui {

namespace {

constexpr int kAcross = 96, kDown = 72;  ///< rays: a small picture of the view, a few milliseconds
constexpr size_t kLeastSeen = 16;

} // namespace

float view_exposure(const RayScene& rays, const std::vector<Rgb>& radiance, const std::function<Ray(float, float)>& ray_through,
                    const Visibility& visible) {
  const Scene& scene = rays.scene();
  std::vector<std::optional<Rgb>> seen(size_t(kAcross) * kDown);
  tbb::parallel_for(0, kDown, [&](int j) {
    for (int i = 0; i < kAcross; ++i) {
      const Ray ray = ray_through((float(i) + 0.5f) / kAcross, (float(j) + 0.5f) / kDown);
      const std::optional<Hit> hit = front_hit(rays, ray, visible);
      if (!hit) continue;  // the backdrop
      const auto& corner = scene.triangles[hit->triangle];
      seen[size_t(j) * kAcross + size_t(i)] =
          (1.f - hit->u - hit->v) * radiance[corner[0]] + hit->u * radiance[corner[1]] + hit->v * radiance[corner[2]];
    }
  });
  std::vector<Rgb> shown;
  for (const std::optional<Rgb>& s : seen)
    if (s) shown.push_back(*s);
  return shown.size() < kLeastSeen ? 0.f : auto_exposure(shown);
}

} // namespace hilight::painter::ui
