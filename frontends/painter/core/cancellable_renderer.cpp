#include "core/cancellable_renderer.hpp"

namespace hilight::painter {

std::vector<Rgb> CancellableRenderer::illuminate(const SurfacePoints& points, std::span<const Light> lights) {
  check();
  return m_inner.illuminate(points, lights);
}

std::vector<Rgb> CancellableRenderer::unit_responses(const SurfacePoints& points, std::span<const Light> lights,
                                                     Transport transport) {
  check();
  return m_inner.unit_responses(points, lights, transport);
}

Image CancellableRenderer::render_image(const Camera& camera, std::span<const Light> lights, int width, int height) {
  check();
  return m_inner.render_image(camera, lights, width, height);
}

} // namespace hilight::painter
