#pragma once
/// Solving with a given luminaire (`hilight solve --luminaire FILE`): the
/// pipeline keeps working with point lights (positions and intensities:
/// seeding, hierarchy, cuts, refinement) and every render it asks for is of
/// that luminaire standing at those points, aimed as the template says. The
/// renderer wrapper below does the substitution, so φ, the light cache (its
/// nodes become luminaires too) and the reference's D̄ all see the luminaire.
#include "hilight/renderer.hpp"

namespace hilight {

/// Point lights as the template luminaire at their position, with their
/// intensity (W/sr at the luminaire's peak); other lights as they are.
Lighting as_luminaires(const Lighting& lights, const Light& luminaire);
/// The reverse for lights of the template's profile (fine-tune, add).
Lighting as_points(const Lighting& lights, const Light& luminaire);

class LuminaireRenderer : public Renderer {
public:
  LuminaireRenderer(Renderer& inner, Light luminaire) : m_inner(inner), m_luminaire(std::move(luminaire)) {}

  void set_scene(std::shared_ptr<const Scene> scene) override { m_inner.set_scene(std::move(scene)); }
  std::vector<Rgb> illuminate(const SurfacePoints& points, std::span<const Light> lights) override;
  std::vector<Rgb> unit_responses(const SurfacePoints& points, std::span<const Light> lights,
                                  Transport transport = Transport::All) override;
  /// The inner key and the luminaire (its profile, aim and spin): a light
  /// cache of one luminaire is not another's.
  std::string settings_key() const override;
  Image render_image(const Camera& camera, std::span<const Light> lights, int width, int height) override;
  uint64_t rays_cast() const override { return m_inner.rays_cast(); }
  void release_scratch() override { m_inner.release_scratch(); }
  /// The template the point lights become from now on.
  void set_luminaire(Light luminaire) { m_luminaire = std::move(luminaire); }

private:
  Lighting substitute(std::span<const Light> lights) const { return as_luminaires(Lighting(lights.begin(), lights.end()), m_luminaire); }
  Renderer& m_inner;
  Light m_luminaire;
};

} // namespace hilight
