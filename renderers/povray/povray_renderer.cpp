#include "povray_renderer.hpp"

#include "hilight/error.hpp"
#include "hilight/io/image_io.hpp"
#include "povray_process.hpp"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <stdexcept>

namespace hilight::povray {

namespace fs = std::filesystem;

namespace {
Lighting scaled_lights(std::span<const Light> lights, float scale) {
  Lighting out(lights.begin(), lights.end());
  for (auto& l : out) l.intensity *= scale;
  return out;
}
} // namespace

void PovrayRenderer::set_scene(std::shared_ptr<const Scene> scene) {
  m_scene = std::move(scene);
  m_rays = std::make_unique<RayScene>(*m_scene);
}

std::string PovrayRenderer::settings_key() const {
  std::ostringstream key;
  key << "povray/bounces=" << m_settings.pov.bounces << "/count=" << m_settings.pov.radiosity_count
      << "/error_bound=" << m_settings.pov.error_bound << "/pretrace_end=" << m_settings.pov.pretrace_end;
  return key.str();
}

float PovrayRenderer::exposure_scale(std::span<const Light> lights) const {
  float strongest = 0.f;
  for (const auto& l : lights) strongest = std::max(strongest, std::max(l.intensity.r, std::max(l.intensity.g, l.intensity.b)));
  if (!(strongest > 0.f)) return 1.f;
  // A light at a quarter of the diagonal gives radiance ~ I / (π (diag/4)²):
  // scale that to ~1, far from half-float underflow and overflow.
  float quarter = 0.25f * m_scene->diagonal();
  return float(kPi) * quarter * quarter / strongest;
}

std::vector<Rgb> PovrayRenderer::bake(const SurfacePoints& points, std::span<const Light> lights, int bounces) {
  if (!m_scene) throw std::logic_error("PovrayRenderer: set_scene was not called");
  const size_t m = points.size();
  std::vector<Rgb> out(m, Rgb(0.f));
  if (m == 0 || lights.empty()) return out;
  const float scale = exposure_scale(lights);
  const Lighting scaled = scaled_lights(lights, scale);

  TempFolder folder;
  const fs::path pov = folder.path() / "bake.pov";
  {
    std::ofstream file(pov);
    PovSettings settings = m_settings.pov;
    settings.bounces = bounces;
    write_pov_scene(file, *m_scene, scaled, settings);
    // One camera triangle per point: centred `lift` above the point along its
    // normal, wound so that its (right-handed) normal points away from the
    // surface; mesh_camera shoots its ray against that normal, at the point.
    const float lift = 1e-4f * m_scene->diagonal(), size = 0.25f * lift;
    file << std::setprecision(9) << "camera { mesh_camera { 1 0 mesh {\n";
    for (size_t i = 0; i < m; ++i) {
      Vec3 p = shading_point(*m_rays, points.positions[i], points.normals[i]);
      Vec3 n = points.normals[i];
      Vec3 t = glm::normalize(std::abs(n.x) < 0.9f ? glm::cross(n, Vec3(1, 0, 0)) : glm::cross(n, Vec3(0, 1, 0)));
      Vec3 b = glm::cross(n, t);  // (t, b, n) right-handed: counter-clockwise corners give normal +n
      Vec3 c = p + lift * n;
      Vec3 v0 = c + size * t, v1 = c + size * (-0.5f * t + 0.8660254f * b), v2 = c + size * (-0.5f * t - 0.8660254f * b);
      file << "triangle { <" << v0.x << ',' << v0.y << ',' << v0.z << ">, <" << v1.x << ',' << v1.y << ',' << v1.z << ">, <"
           << v2.x << ',' << v2.y << ',' << v2.z << "> }\n";
    }
    file << "} } location <0,0,0> }\n";
    if (!file) throw std::runtime_error("povray: cannot write " + pov.string());
  }
  // One row: mesh_camera maps face i to pixel i of the first row for sure;
  // its mapping over several rows did not match row-major order (tested).
  const size_t width = m, height = 1;
  run_povray(m_settings.executable,
             {"-D", "-V", "-A", "+FE", "+W" + std::to_string(width), "+H" + std::to_string(height), "+Obake.exr", "+Ibake.pov"},
             folder.path(), m_settings.timeout_seconds);
  Image image = read_exr(folder.path() / "bake.exr");
  if (size_t(image.width) != width || size_t(image.height) != height) throw std::runtime_error("povray: unexpected image size");
  size_t missed = 0;
  for (size_t i = 0; i < m; ++i) {
    Rgb v = image.at(int(i % width), int(i / width));
    if (v.r < 0.f) {  // the background marker: the ray hit nothing
      ++missed;
      continue;
    }
    out[i] = v / scale;
  }
  if (missed * 100 > m) throw std::runtime_error("povray: " + std::to_string(missed) + " of " + std::to_string(m) + " points were not seen by their baking rays");
  return out;
}

std::vector<Rgb> PovrayRenderer::illuminate(const SurfacePoints& points, std::span<const Light> lights) {
  return bake(points, lights, m_settings.pov.bounces);
}

std::vector<Rgb> PovrayRenderer::unit_responses(const SurfacePoints& points, std::span<const Light> lights, Transport transport) {
  // POV-Ray cannot separate lights within one run: one bake per light.
  const size_t m = points.size();
  std::vector<Rgb> out(m * lights.size());
  for (size_t j = 0; j < lights.size(); ++j) {
    Light unit = lights[j];
    unit.intensity = Rgb(1.f);
    std::vector<Rgb> r;
    if (transport == Transport::DirectOnly || m_settings.pov.bounces == 0) {
      r = transport == Transport::IndirectOnly ? std::vector<Rgb>(m, Rgb(0.f)) : bake(points, std::span<const Light>(&unit, 1), 0);
    } else {
      r = bake(points, std::span<const Light>(&unit, 1), 1);
      if (transport == Transport::IndirectOnly) {
        std::vector<Rgb> direct = bake(points, std::span<const Light>(&unit, 1), 0);
        for (size_t i = 0; i < m; ++i) r[i] -= direct[i];
      }
    }
    std::copy(r.begin(), r.end(), out.begin() + std::ptrdiff_t(j * m));
  }
  return out;
}

Image PovrayRenderer::render_image(const Camera& camera, std::span<const Light> lights, int width, int height) {
  if (!m_scene) throw std::logic_error("PovrayRenderer: set_scene was not called");
  const float scale = exposure_scale(lights);
  const Lighting scaled = scaled_lights(lights, scale);
  TempFolder folder;
  {
    std::ofstream file(folder.path() / "image.pov");
    write_pov_scene(file, *m_scene, scaled, m_settings.pov);
    write_pov_camera(file, camera, width, height);
  }
  run_povray(m_settings.executable,
             {"-D", "-V", "-A", "+FE", "+W" + std::to_string(width), "+H" + std::to_string(height), "+Oimage.exr", "+Iimage.pov"},
             folder.path(), m_settings.timeout_seconds);
  Image image = read_exr(folder.path() / "image.exr");
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    bool hit = image.pixels[i].r >= 0.f;
    image.covered[i] = hit;
    image.pixels[i] = hit ? image.pixels[i] / scale : Rgb(0.f);
  }
  return image;
}

} // namespace hilight::povray
