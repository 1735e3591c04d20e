#include "core/shadow_erase.hpp"

#include "core/vertex_points.hpp"
#include "hilight/error.hpp"

#include <algorithm>
#include <cmath>

namespace hilight::painter {

namespace {

/// Spot factor S(α) of docs/rendering-model.md (1 for point lights).
float spot_factor(const Light& light, const Vec3& to_point_unit) {
  if (light.type != LightType::Spot) return 1.f;
  return SpotCone::of(light).factor(glm::dot(light.direction, to_point_unit));
}

/// The object whose surface first blocks the way from a surface point to the
/// light (or none): the light must be in front of the surface and reach it.
struct Blocker {
  bool reached = false;   ///< the light would light the point without occluders
  bool blocked = false;
  uint32_t object = 0;
  Vec3 at{0.f};
};

Blocker first_blocker(const SceneObjects& objects, const RayScene& rays, const Light& light, const Vec3& position,
                      const Vec3& normal) {
  Blocker b;
  const ShadingPoint at = shading_point(rays, position, normal);
  Vec3 to_light = light.position - at.position;
  const float distance = glm::length(to_light);
  if (!(distance > 0.f)) return b;
  to_light /= distance;
  const Vec3 start = at.ray_start(to_light, normal, rays.epsilon());
  if (glm::dot(to_light, normal) <= 0.f || spot_factor(light, -to_light) <= 0.f) return b;
  b.reached = true;
  Hit hit = rays.intersect(start, to_light, distance);
  if (!hit.valid()) return b;
  b.blocked = true;
  b.object = objects.object_of_triangle(hit.triangle);
  b.at = rays.hit_position(hit);
  return b;
}

} // namespace

std::vector<ShadowPair> find_shadow_pairs(const SceneObjects& objects, const RayScene& rays, const Lighting& lights,
                                          const SurfacePick& click) {
  std::vector<ShadowPair> pairs;
  for (size_t j = 0; j < lights.size(); ++j) {
    Blocker b = first_blocker(objects, rays, lights[j], click.position, click.normal);
    if (b.blocked) pairs.push_back({b.object, j, b.at});
  }
  return pairs;
}

std::vector<uint32_t> shadowed_vertices(const SceneObjects& objects, const RayScene& rays, const Lighting& lights,
                                        const ShadowPair& pair) {
  if (pair.light >= lights.size()) throw InputError("erase shadow", "no light " + std::to_string(pair.light));
  const Scene& scene = rays.scene();
  std::vector<uint32_t> result;
  for (uint32_t v = 0; v < scene.positions.size(); ++v) {
    Blocker b = first_blocker(objects, rays, lights[pair.light], scene.positions[v], scene.normals[v]);
    if (b.blocked && b.object == pair.occluder) result.push_back(v);
  }
  return result;
}

std::vector<uint32_t> erase_shadow(Document& document, const SceneObjects& objects, Renderer& renderer,
                                   const ShadowPair& pair) {
  const Scene& scene = document.scene();
  const Lighting lights = document.state().lights;
  std::vector<uint32_t> vertices = shadowed_vertices(objects, document.rays(), lights, pair);
  if (vertices.empty()) return vertices;
  const SurfacePoints points = points_of_vertices(scene, vertices);
  const std::vector<Rgb> current = renderer.illuminate(points, lights);
  const Light& light = lights[pair.light];
  document.apply("erase shadow", [&](PaintState& s) {
    for (size_t i = 0; i < vertices.size(); ++i) {
      const uint32_t v = vertices[i];
      // The light's direct contribution as if nothing blocked it (rendering model).
      const Vec3 start = shading_point(document.rays(), scene.positions[v], scene.normals[v]).position;
      Vec3 to_light = light.position - start;
      const float d2 = glm::dot(to_light, to_light);
      to_light /= std::sqrt(d2);
      const float cos_theta = std::abs(glm::dot(to_light, scene.normals[v]));
      const Rgb unshadowed = points.albedo[i] / float(kPi) * light.intensity * cos_theta * spot_factor(light, -to_light) / d2;
      const Rgb base = s.weight[v] > 0.f ? s.psi[v] : current[i];
      s.psi[v] = base + unshadowed;
      s.weight[v] = std::max(s.weight[v], 1.f);
    }
  });
  return vertices;
}

} // namespace hilight::painter
