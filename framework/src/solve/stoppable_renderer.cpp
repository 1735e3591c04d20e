#include "hilight/solve/stoppable_renderer.hpp"

#include "hilight/image.hpp"

namespace hilight {

std::vector<Rgb> StoppableRenderer::illuminate(const SurfacePoints& points, std::span<const Light> lights) {
  check();
  return m_inner.illuminate(points, lights);
}

std::vector<Rgb> StoppableRenderer::unit_responses(const SurfacePoints& points, std::span<const Light> lights, Transport transport) {
  check();
  return m_inner.unit_responses(points, lights, transport);
}

Image StoppableRenderer::render_image(const Camera& camera, std::span<const Light> lights, int width, int height) {
  check();
  return m_inner.render_image(camera, lights, width, height);
}

} // namespace hilight
