// IsmRenderer::render_image: the camera's G-buffer from the same triangle
// raster as the shadow maps, then the pixels' surface points shaded like any
// other points (so images and per-point results agree by construction).
#include "ism_renderer.hpp"

#include "hilight/error.hpp"
#include "hilight/scene.hpp"

#include <algorithm>
#include <array>

namespace hilight::ism {

Image IsmRenderer::render_image(const Camera& camera, std::span<const Light> lights, int width, int height) {
  if (width <= 0 || height <= 0) throw InputError("renderer ism-vulkan: image size must be positive");
  const Scene& scene = *m_scene;
  SurfacePoints pixels;
  std::vector<size_t> pixel_index;
  std::vector<std::array<float, 3>> corner_weight;  // the pixel's barycentrics on its triangle
  std::vector<size_t> pixel_triangle;
  {
    std::lock_guard lock(m_mutex);
    if (!m_scene) throw std::logic_error("IsmRenderer: set_scene was not called");
    // The camera's G-buffer from the same raster as the shadow maps: the
    // triangle seen in each pixel, intersected with the pixel's ray.
    const Camera::Basis b = camera.basis();
    const float aspect = float(width) / float(height);
    RasterView view{camera.eye, b.forward, b.right / (b.tan_half_fov * aspect), -b.up / b.tan_half_fov,
                    1e-3f * scene.diagonal(), glm::length(camera.eye - scene.bounds.center()) + 2.f * scene.diagonal()};
    const VkDeviceSize bytes = VkDeviceSize(width) * height * 4;
    Buffer triangles(*m_context, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, "the image's triangles");
    begin_commands(m_cmd);
    const RasterDraw all{0, uint32_t(scene.triangles.size())};
    m_raster->record(m_cmd, std::span<const RasterView>(&view, 1), std::span<const RasterDraw>(&all, 1), m_buffers->indices,
                     m_buffers->identity_ids, uint32_t(width), uint32_t(height), triangles);
    full_barrier(m_cmd);
    submit_and_wait(m_cmd);
    m_context->throw_on_validation_errors();
    if (every_bounce_path() && !m_vertices) {
      m_vertices = std::make_unique<SurfacePoints>(SurfacePoints::from_vertices(scene));
      std::fill(m_vertices->albedo.begin(), m_vertices->albedo.end(), Rgb(1.f));
    }
    const uint32_t* tri = triangles.data<uint32_t>();
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const size_t k = size_t(y) * width + x;
        if (tri[k] == 0) continue;
        const size_t t = tri[k] - 1;
        float sx = (2.f * (float(x) + 0.5f) / float(width) - 1.f) * b.tan_half_fov * aspect;
        float sy = (1.f - 2.f * (float(y) + 0.5f) / float(height)) * b.tan_half_fov;
        const Vec3 dir = glm::normalize(b.forward + sx * b.right + sy * b.up);
        const auto& ids = scene.triangles[t];
        const Vec3 &a = scene.positions[ids[0]], e1 = scene.positions[ids[1]] - a, e2 = scene.positions[ids[2]] - a;
        const Vec3 plane = scene.face_normal(t);
        const float facing = glm::dot(plane, dir);
        if (std::abs(facing) < 1e-6f) continue;  // edge-on: no area to shade
        const Vec3 p = camera.eye + dir * (glm::dot(plane, a - camera.eye) / facing);
        // Shading normal: the vertex normals at p's barycentrics.
        Vec3 q = p - a;
        float d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
        float denom = d11 * d22 - d12 * d12;
        float u = denom > 0 ? (d22 * glm::dot(q, e1) - d12 * glm::dot(q, e2)) / denom : 0.f;
        float v = denom > 0 ? (d11 * glm::dot(q, e2) - d12 * glm::dot(q, e1)) / denom : 0.f;
        u = std::clamp(u, 0.f, 1.f);
        v = std::clamp(v, 0.f, 1.f - u);
        Vec3 n = (1.f - u - v) * scene.normals[ids[0]] + u * scene.normals[ids[1]] + v * scene.normals[ids[2]];
        n = glm::dot(n, n) > 0 ? glm::normalize(n) : scene.face_normal(t);
        pixels.positions.push_back(a + u * e1 + v * e2);
        pixels.normals.push_back(n);
        pixels.albedo.push_back(scene.triangle_albedo(t));
        pixel_index.push_back(k);
        pixel_triangle.push_back(t);
        corner_weight.push_back({1.f - u - v, u, v});
      }
  }
  std::vector<Rgb> shaded;
  if (!every_bounce_path()) {
    shaded = illuminate(pixels, lights);
  } else {
    // Every bounce: the pixels carry up to the first; the later bounces,
    // smooth, are gathered at the scene's vertices (their maps once per
    // scene) and interpolated across each pixel's triangle, as Embree's
    // vertex transport is: a pixel's own maps would cost a splat of every
    // bounce point per pixel.
    const std::vector<Rgb> near = responses(pixels, lights, Transport::All, Later::Excluded);
    const std::vector<Rgb> far = responses(*m_vertices, lights, Transport::All, Later::Only);
    const size_t n = pixels.size(), v = m_vertices->size();
    shaded.assign(n, Rgb(0.f));
    for (size_t j = 0; j < lights.size(); ++j)
      for (size_t i = 0; i < n; ++i) {
        const auto& ids = scene.triangles[pixel_triangle[i]];
        Rgb later(0.f);  // E/π at albedo 1, interpolated
        for (int c = 0; c < 3; ++c) later += corner_weight[i][c] * far[j * v + ids[c]];
        shaded[i] += lights[j].intensity * (near[j * n + i] + pixels.albedo[i] * later);
      }
  }
  Image image(width, height);
  for (size_t k = 0; k < pixel_index.size(); ++k) {
    image.pixels[pixel_index[k]] = shaded[k];
    image.covered[pixel_index[k]] = 1;
  }
  return image;
}

} // namespace hilight::ism
