#include "hilight/solve/luminaire_renderer.hpp"

#include "hilight/image.hpp"

#include <sstream>

namespace hilight {

Lighting as_luminaires(const Lighting& lights, const Light& luminaire) {
  Lighting out;
  out.reserve(lights.size());
  for (const Light& l : lights) {
    if (l.type != LightType::Point) {
      out.push_back(l);
      continue;
    }
    Light lum = luminaire;
    lum.position = l.position;
    lum.intensity = l.intensity;
    out.push_back(std::move(lum));
  }
  return out;
}

Lighting as_points(const Lighting& lights, const Light& luminaire) {
  Lighting out;
  out.reserve(lights.size());
  for (const Light& l : lights)
    // An area template (its shape given: --area-light, --luminaire-size) comes back too.
    out.push_back(l.type == luminaire.type && l.profile_path == luminaire.profile_path ? Light::point(l.position, l.intensity) : l);
  return out;
}

std::vector<Rgb> LuminaireRenderer::illuminate(const SurfacePoints& points, std::span<const Light> lights) {
  return m_inner.illuminate(points, substitute(lights));
}

std::vector<Rgb> LuminaireRenderer::unit_responses(const SurfacePoints& points, std::span<const Light> lights, Transport transport) {
  return m_inner.unit_responses(points, substitute(lights), transport);
}

Image LuminaireRenderer::render_image(const Camera& camera, std::span<const Light> lights, int width, int height) {
  return m_inner.render_image(camera, substitute(lights), width, height);
}

std::string LuminaireRenderer::settings_key() const {
  std::ostringstream key;
  key << m_inner.settings_key() << "|luminaire " << m_luminaire.profile_path << " aim " << m_luminaire.direction.x << ","
      << m_luminaire.direction.y << "," << m_luminaire.direction.z << " spin " << m_luminaire.spin_deg;
  if (is_area(m_luminaire.type))
    key << " " << to_string(m_luminaire.type) << " up " << m_luminaire.up.x << "," << m_luminaire.up.y << "," << m_luminaire.up.z
        << " size " << m_luminaire.size[0] << "x" << m_luminaire.size[1];
  return key.str();
}

} // namespace hilight
