#include "povray_renderer.hpp"

#include "hilight/error.hpp"
#include "hilight/io/image_io.hpp"
#include "povray_process.hpp"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <algorithm>
#include <limits>
#include <stdexcept>

namespace hilight::povray {

namespace fs = std::filesystem;

namespace {
/// A triangle of radius r centred at c, wound so that its right-handed
/// normal is n; in double precision, since receivers sit closer to the mesh
/// than a float can tell apart.
void write_camera_triangle(std::ostream& file, const DVec3& c, const Vec3& normal, double r) {
  const DVec3 n(normal);
  DVec3 t = glm::normalize(std::abs(n.x) < 0.9 ? glm::cross(n, DVec3(1, 0, 0)) : glm::cross(n, DVec3(0, 1, 0)));
  DVec3 b = glm::cross(n, t);  // (t, b, n) right-handed: counter-clockwise corners give normal +n
  DVec3 v0 = c + r * t, v1 = c + r * (-0.5 * t + 0.8660254037844386 * b), v2 = c + r * (-0.5 * t - 0.8660254037844386 * b);
  file << std::setprecision(15) << "triangle { <" << v0.x << ',' << v0.y << ',' << v0.z << ">, <" << v1.x << ',' << v1.y << ','
       << v1.z << ">, <" << v2.x << ',' << v2.y << ',' << v2.z << "> }\n";
}

Lighting scaled_lights(std::span<const Light> lights, float scale) {
  Lighting out(lights.begin(), lights.end());
  for (auto& l : out) l.intensity *= scale;
  return out;
}
} // namespace

void PovrayRenderer::set_scene(std::shared_ptr<const Scene> scene) {
  const float diagonal = scene->diagonal();
  int exponent = 0;
  if (diagonal > 0.f && std::isfinite(diagonal)) std::frexp(diagonal / 8.f, &exponent);  // size/8 in [2^(e-1), 2^e)
  m_pov_scale = std::ldexp(1.f, 1 - exponent);
  if (m_pov_scale != 1.f) {
    auto scaled = std::make_shared<Scene>(*scene);
    for (auto& p : scaled->positions) p *= m_pov_scale;
    scaled->update_bounds();
    scene = std::move(scaled);
  }
  m_scene = std::move(scene);
  m_rays = RayScene::shared(m_scene);
}

SurfacePoints PovrayRenderer::to_pov(const SurfacePoints& points) const {
  SurfacePoints out = points;
  for (auto& p : out.positions) p *= m_pov_scale;
  return out;
}

Lighting PovrayRenderer::to_pov(std::span<const Light> lights) const {
  Lighting out(lights.begin(), lights.end());
  for (auto& l : out) {
    l.position *= m_pov_scale;
    l.size *= m_pov_scale;  // an area or line source scales with the scene
    l.intensity *= m_pov_scale * m_pov_scale;
  }
  return out;
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

std::vector<Rgb> PovrayRenderer::bake(const SurfacePoints& world_points, std::span<const Light> world_lights, int bounces) {
  if (!m_scene) throw std::logic_error("PovrayRenderer: set_scene was not called");
  const SurfacePoints points = to_pov(world_points);
  const Lighting lights = to_pov(world_lights);
  std::vector<Rgb> out = bake_direct(points, lights);
  if (bounces != 0 && points.size() > 0 && !lights.empty()) {
    // The bounce: POV-Ray's radiosity on the mesh itself (receivers would
    // gather it at a surface that is not in the scene), as the difference of
    // a run with and one without it, so it carries no direct light.
    // `bounces` reflections (radiosity recursion_limit; all = 20).
    std::vector<Rgb> with = bake_on_mesh(points, lights, bounces), without = bake_on_mesh(points, lights, 0);
    for (size_t i = 0; i < out.size(); ++i) out[i] += with[i] - without[i];
  }
  return out;
}

std::vector<Rgb> PovrayRenderer::bake_on_mesh(const SurfacePoints& points, std::span<const Light> lights, int bounces) {
  const size_t m = points.size();
  std::vector<Rgb> out(m, Rgb(0.f));
  const float scale = exposure_scale(lights);
  const Lighting scaled = scaled_lights(lights, scale);
  TempFolder folder;
  const fs::path pov = folder.path() / "bake.pov";
  {
    std::ofstream file(pov);
    PovSettings settings = m_settings.pov;
    settings.bounces = bounces;
    write_pov_scene(file, *m_scene, scaled, settings);
    // One camera triangle per point, `lift` off the surface along its normal,
    // shooting at the surface ε inside the point's triangle (a ray aimed at a
    // mesh vertex can slip between the fan's triangles).
    const float lift = 1e-4f * m_scene->diagonal(), size = 0.25f * lift;
    file << std::setprecision(9) << "camera { mesh_camera { 1 0 mesh {\n";
    for (size_t i = 0; i < m; ++i) {
      const ShadingPoint at = shading_point(*m_rays, points.positions[i], points.normals[i]);
      Vec3 p = at.position;
      if (at.smooth && at.triangle != RTC_INVALID_GEOMETRY_ID) {
        const auto& tri = m_scene->triangles[at.triangle];
        Vec3 to_centroid = (m_scene->positions[tri[0]] + m_scene->positions[tri[1]] + m_scene->positions[tri[2]]) / 3.f - p;
        float distance = glm::length(to_centroid);
        if (distance > 0.f) p += to_centroid * (std::min(m_rays->epsilon(), 0.1f * distance) / distance);
      }
      write_camera_triangle(file, DVec3(p + lift * points.normals[i]), points.normals[i], size);
    }
    file << "} } location <0,0,0> }\n";
    if (!file) throw std::runtime_error("povray: cannot write " + pov.string());
  }
  const Image image = run_bake(folder.path(), m);
  size_t missed = 0;
  for (size_t i = 0; i < m; ++i) {
    Rgb v = image.at(int(i), 0);
    if (v.r < 0.f) {  // the background marker: the ray hit nothing
      ++missed;
      continue;
    }
    out[i] = v / scale;
  }
  if (missed * 100 > m) throw std::runtime_error("povray: " + std::to_string(missed) + " of " + std::to_string(m) + " points were not seen by their baking rays");
  return out;
}

std::vector<Rgb> PovrayRenderer::bake_direct(const SurfacePoints& points, std::span<const Light> lights) {
  const size_t m = points.size();
  if (m == 0 || lights.empty()) return std::vector<Rgb>(m, Rgb(0.f));
  // POV-Ray cannot leave out one light at one point: each light that a
  // smooth point's wedge blocks (in_own_wedge) is baked on its own, with
  // the receiver on that light's side of such a point black. An area
  // source is tested at its centre.
  std::vector<ShadingPoint> at(m);
  for (size_t i = 0; i < m; ++i) at[i] = shading_point(*m_rays, points.positions[i], points.normals[i]);
  Lighting plain;
  std::vector<std::pair<size_t, std::vector<uint8_t>>> alone;
  for (size_t j = 0; j < lights.size(); ++j) {
    std::vector<uint8_t> dark(2 * m, 0);
    bool any = false;
    for (size_t i = 0; i < m; ++i) {
      const Vec3 d = lights[j].position - at[i].position;
      const float length = glm::length(d);
      if (!(length > 0.f) || !in_own_wedge(*m_rays, at[i], points.normals[i], d / length)) continue;
      dark[2 * i + (glm::dot(points.normals[i], d) >= 0.f ? 0 : 1)] = 1;
      any = true;
    }
    if (any) alone.emplace_back(j, std::move(dark));
    else plain.push_back(lights[j]);
  }
  std::vector<Vec3> shaded(m);
  for (size_t i = 0; i < m; ++i) shaded[i] = at[i].position;
  std::vector<Rgb> out = plain.empty() ? std::vector<Rgb>(m, Rgb(0.f)) : bake_direct_run(points, shaded, plain, {});
  for (const auto& [j, dark] : alone) {
    const std::vector<Rgb> one = bake_direct_run(points, shaded, lights.subspan(j, 1), dark);
    for (size_t i = 0; i < m; ++i) out[i] += one[i];
  }
  return out;
}

std::vector<Rgb> PovrayRenderer::bake_direct_run(const SurfacePoints& points, const std::vector<Vec3>& at,
                                                 std::span<const Light> lights, const std::vector<uint8_t>& dark) {
  const size_t m = points.size();
  std::vector<Rgb> out(m, Rgb(0.f));
  const float scale = exposure_scale(lights);
  const Lighting scaled = scaled_lights(lights, scale);
  const float diagonal = m_scene->diagonal();

  TempFolder folder;
  const fs::path pov = folder.path() / "bake.pov";
  {
    std::ofstream file(pov);
    PovSettings settings = m_settings.pov;
    settings.bounces = 0;
    settings.double_illuminate = false;
    // A point's value is the sum over its two sides (rendering model), and
    // POV-Ray lights the side of a surface that faces its camera ray. Each
    // point gets two receivers: tiny white flat triangles with the point's
    // own normal, 10⁻⁸ × diagonal (or 8 float ulps) off its shading point on either side, that
    // cast no shadow and that radiosity rays do not see. A receiver's flat
    // normal decides the side of each light as the point's shading normal
    // does; its shadow rays start at the shading point and POV-Ray ignores
    // hits closer than 10⁻⁶ (and, for shadows, 10⁻³), so the point's own
    // facets do not shadow it (a smooth point) — the model's "skip the first
    // ε"; the mesh's inside_vector keeps real blockers behind those facets
    // (pov_export.cpp). Albedo multiplies after.
    // Off the surface by more than a float's rounding of the shading point
    // (8 ulps of the largest coordinate), else the mesh can hide a receiver.
    float largest = 0.f;
    for (const auto& p : m_scene->positions) largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    const float offset = std::max(1e-8f * diagonal, 8.f * std::numeric_limits<float>::epsilon() * largest);
    const float receiver = 1e-4f * diagonal;
    const float lift = 5e-5f * diagonal, size = 0.25f * receiver;
    // A union of triangles, not a mesh: POV-Ray keeps a mesh's vertices in
    // single precision, which cannot hold the receivers off the surface.
    write_pov_scene(file, *m_scene, scaled, settings);
    for (const int shade : {1, 0}) {  // white receivers, then the black ones
      bool any = false;
      for (size_t i = 0; i < 2 * m; ++i) any |= (dark.empty() || !dark[i]) == bool(shade);
      if (!any) continue;
      file << "union {\n";
      for (size_t i = 0; i < m; ++i)
        for (int side = 0; side < 2; ++side) {
          if ((dark.empty() || !dark[2 * i + side]) != bool(shade)) continue;
          const float sign = side == 0 ? 1.f : -1.f;
          write_camera_triangle(file, DVec3(at[i]) + double(sign * offset) * DVec3(points.normals[i]), sign * points.normals[i], receiver);
        }
      file << "texture { pigment { color rgb " << shade << " } finish { diffuse 1 ambient 0 emission 0 specular 0 phong 0 } }\n"
           << "no_shadow no_radiosity no_reflection }\n";
    }
    // One camera triangle per receiver, `lift` out along its normal and wound
    // so that its normal points away from the surface; mesh_camera shoots its
    // ray against that normal, at the receiver: pixel 2i is the side the
    // point's normal points to, 2i+1 the other.
    file << "camera { mesh_camera { 1 0 mesh {\n";
    for (size_t i = 0; i < m; ++i)
      for (float side : {1.f, -1.f}) write_camera_triangle(file, DVec3(at[i]) + double(side * lift) * DVec3(points.normals[i]), side * points.normals[i], size);
    file << "} } location <0,0,0> }\n";
    if (!file) throw std::runtime_error("povray: cannot write " + pov.string());
  }
  const Image image = run_bake(folder.path(), 2 * m);
  size_t missed = 0;
  for (size_t i = 0; i < m; ++i)
    for (int side = 0; side < 2; ++side) {
      Rgb v = image.at(int(2 * i + side), 0);
      if (v.r < 0.f) {  // the background marker: the ray hit nothing
        ++missed;
        continue;
      }
      out[i] += points.albedo[i] * v / scale;
    }
  if (missed * 100 > 2 * m) throw std::runtime_error("povray: " + std::to_string(missed) + " of " + std::to_string(2 * m) + " receivers were not seen by their baking rays");
  return out;
}

Image PovrayRenderer::run_bake(const fs::path& folder, size_t pixels) const {
  // One row: mesh_camera maps face i to pixel i of the first row for sure;
  // its mapping over several rows did not match row-major order (tested).
  run_povray(m_settings.executable,
             {"-D", "-V", "-A", "+FE", "+W" + std::to_string(pixels), "+H1", "+Obake.exr", "+Ibake.pov"}, folder,
             m_settings.timeout_seconds);
  Image image = read_exr(folder / "bake.exr");
  if (size_t(image.width) != pixels || image.height != 1) throw std::runtime_error("povray: unexpected image size");
  return image;
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
      r = bake(points, std::span<const Light>(&unit, 1), m_settings.pov.bounces);
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
  const Lighting pov_lights = to_pov(lights);
  const float scale = exposure_scale(pov_lights);
  const Lighting scaled = scaled_lights(pov_lights, scale);
  Camera pov_camera = camera;
  pov_camera.eye *= m_pov_scale;
  pov_camera.target *= m_pov_scale;
  TempFolder folder;
  {
    std::ofstream file(folder.path() / "image.pov");
    write_pov_scene(file, *m_scene, scaled, m_settings.pov);
    write_pov_camera(file, pov_camera, width, height);
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
