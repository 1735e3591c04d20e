// The `unshadowed` renderer: hilight's rendering model (docs/rendering-model.md)
// with every light visible from every point: no shadows, no bounce. A test
// double for solver work and an example of a plugin built outside the tree
// against an installed hilight (docs/plugins.md).
//
// | property | default | meaning                                          |
// |----------|---------|--------------------------------------------------|
// | bounces  | 0       | 0 only: direct light (every renderer reads it)   |
// | gain     | 1       | a factor on every value (1: the rendering model) |
#include <hilight/error.hpp>
#include <hilight/plugin.hpp>
#include <hilight/ray_scene.hpp>
#include <hilight/registry.hpp>
#include <hilight/scene.hpp>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <span>
#include <string>
#include <vector>

namespace {

using namespace hilight;

/// A light with its spot cone or luminaire frame worked out once per call,
/// not once per point.
struct PreparedLight {
  const Light* light;
  SpotCone cone;
  LuminaireFrame frame;

  explicit PreparedLight(const Light& l) : light(&l) {
    if (l.type == LightType::Spot) cone = SpotCone::of(l);
    if (l.type == LightType::Luminaire) frame = LuminaireFrame::of(l);
  }

  /// Irradiance at `p` (unit normal `n`) at unit intensity: the two-sided
  /// cosine |n·ω| over the squared distance, times the angular factor.
  float unit_irradiance(const Vec3& p, const Vec3& n) const {
    const Vec3 d = light->position - p;
    const float dist2 = glm::dot(d, d);
    if (dist2 <= 0.f) return 0.f;
    const Vec3 w = d / std::sqrt(dist2);
    float angular = 1.f;
    if (light->type == LightType::Spot) angular = cone.factor(glm::dot(light->direction, -w));
    if (light->type == LightType::Luminaire) angular = luminaire_factor(*light, frame, -w);
    return std::abs(glm::dot(n, w)) * angular / dist2;
  }
};

std::vector<PreparedLight> prepare(std::span<const Light> lights) { return {lights.begin(), lights.end()}; }

class UnshadowedRenderer final : public Renderer {
public:
  explicit UnshadowedRenderer(float gain) : m_gain(gain) {}

  void set_scene(std::shared_ptr<const Scene> scene) override {
    m_scene = std::move(scene);
    m_rays = std::make_unique<RayScene>(*m_scene);  // first hits for images only
  }

  std::vector<Rgb> illuminate(const SurfacePoints& points, std::span<const Light> lights) override {
    const std::vector<PreparedLight> prepared = prepare(lights);
    std::vector<Rgb> out(points.size());
    for (size_t i = 0; i < points.size(); ++i) out[i] = lit(points.albedo[i], points.positions[i], points.normals[i], prepared);
    return out;
  }

  std::vector<Rgb> unit_responses(const SurfacePoints& points, std::span<const Light> lights, Transport transport) override {
    std::vector<Rgb> out(points.size() * lights.size(), Rgb(0.f));
    if (transport == Transport::IndirectOnly) return out;  // no bounce
    for (size_t j = 0; j < lights.size(); ++j) {
      const PreparedLight light(lights[j]);
      for (size_t i = 0; i < points.size(); ++i)
        out[j * points.size() + i] = radiance(points.albedo[i], light.unit_irradiance(points.positions[i], points.normals[i]));
    }
    return out;
  }

  std::string settings_key() const override { return "unshadowed/gain=" + std::to_string(m_gain); }

  Image render_image(const Camera& camera, std::span<const Light> lights, int width, int height) override {
    if (!m_rays) throw std::logic_error("unshadowed: set_scene was not called");
    const std::vector<PreparedLight> prepared = prepare(lights);
    Image image(width, height);
    const Camera::Basis b = camera.basis();
    const float aspect = float(width) / float(height);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const float sx = (2.f * (float(x) + 0.5f) / float(width) - 1.f) * b.tan_half_fov * aspect;
        const float sy = (1.f - 2.f * (float(y) + 0.5f) / float(height)) * b.tan_half_fov;
        const Vec3 dir = glm::normalize(b.forward + sx * b.right + sy * b.up);
        const Hit hit = m_rays->intersect(camera.eye, dir);
        if (!hit.valid()) continue;
        image.at(x, y) = lit(m_scene->triangle_albedo(hit.triangle), m_rays->hit_position(hit), m_rays->hit_normal(hit), prepared);
        image.covered[size_t(y) * width + x] = 1;
      }
    return image;
  }

private:
  /// Lambertian: outgoing radiance = albedo / π × irradiance.
  Rgb radiance(const Rgb& albedo, float irradiance) const { return albedo * float(m_gain / M_PI) * irradiance; }
  /// The radiance of a point under all the lights.
  Rgb lit(const Rgb& albedo, const Vec3& p, const Vec3& n, const std::vector<PreparedLight>& lights) const {
    Rgb value(0.f);
    for (const PreparedLight& light : lights) value += radiance(albedo, light.unit_irradiance(p, n)) * light.light->intensity;
    return value;
  }

  float m_gain;
  std::shared_ptr<const Scene> m_scene;
  std::unique_ptr<RayScene> m_rays;
};

std::unique_ptr<Renderer> create(const Properties& properties) {
  // Every renderer reads `bounces` (docs/plugins.md); this one has direct light only.
  if (properties.get_int("bounces", 0) != 0) throw InputError("renderer unshadowed: bounces must be 0 (it has no bounce)");
  const double gain = properties.get_double("gain", 1.0);
  if (!(gain > 0.0) || !std::isfinite(gain)) throw InputError("renderer unshadowed: gain must be a positive number");
  return std::make_unique<UnshadowedRenderer>(float(gain));
}

void register_unshadowed(PluginRegistrar& registrar) { registrar.renderer(create); }

} // namespace

HILIGHT_PLUGIN("renderer", HILIGHT_PLUGIN_NAME, UNSHADOWED_VERSION, "example out-of-tree plugin: direct light without shadows",
               register_unshadowed)
