#pragma once
/// A test double for the Renderer interface: direct light only, in closed
/// form, nothing occludes — |n·ω| · cone / d² · albedo/π, no ray tracer
/// behind it. Pipeline stages (seeding, hierarchy, cuts, refinement,
/// fine-tune, add) get fast unit tests whose only physics is this formula.
#include "hilight/image.hpp"
#include "hilight/renderer.hpp"
#include "hilight/scene.hpp"
#include "hilight/math.hpp"

#include <cmath>

namespace test {

class AnalyticRenderer final : public hilight::Renderer {
public:
  void set_scene(std::shared_ptr<const hilight::Scene> scene) override { m_scene = std::move(scene); }

  std::vector<hilight::Rgb> illuminate(const hilight::SurfacePoints& points, std::span<const hilight::Light> lights) override {
    std::vector<hilight::Rgb> out(points.size(), hilight::Rgb(0.f));
    const std::vector<hilight::Rgb> phi = unit_responses(points, lights);
    for (size_t j = 0; j < lights.size(); ++j)
      for (size_t i = 0; i < points.size(); ++i) out[i] += lights[j].intensity * phi[j * points.size() + i];
    return out;
  }

  std::vector<hilight::Rgb> unit_responses(const hilight::SurfacePoints& points, std::span<const hilight::Light> lights,
                                           hilight::Transport transport = hilight::Transport::All) override {
    const size_t m = points.size();
    std::vector<hilight::Rgb> out(lights.size() * m, hilight::Rgb(0.f));
    if (transport == hilight::Transport::IndirectOnly) return out;  // no bounce in this world
    for (size_t j = 0; j < lights.size(); ++j) {
      const hilight::Light& l = lights[j];
      const hilight::SpotCone cone = hilight::SpotCone::of(l);
      for (size_t i = 0; i < m; ++i) {
        const hilight::Vec3 d = l.position - points.positions[i];
        const float d2 = glm::dot(d, d);
        if (!(d2 > 0.f)) continue;
        const hilight::Vec3 w = d / std::sqrt(d2);
        const float angular = l.type == hilight::LightType::Spot ? cone.factor(glm::dot(glm::normalize(l.direction), -w)) : 1.f;
        out[j * m + i] = points.albedo[i] * float(1.0 / hilight::kPi) * (std::abs(glm::dot(points.normals[i], w)) * angular / d2);
      }
    }
    return out;
  }

  std::string settings_key() const override { return "analytic-test-double"; }

  hilight::Image render_image(const hilight::Camera&, std::span<const hilight::Light>, int width, int height) override {
    return hilight::Image(width, height);
  }

private:
  std::shared_ptr<const hilight::Scene> m_scene;
};

} // namespace test
