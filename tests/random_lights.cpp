#include "random_lights.hpp"

#include <catch2/catch.hpp>

using namespace hilight;

namespace test {

namespace {

Rgb random_intensity(std::mt19937_64& rng, const LampRules& rules) {
  std::uniform_real_distribution<float> level(rules.min_intensity, rules.max_intensity), tint(0.7f, 1.f);
  const float l = level(rng);
  return rules.coloured ? Rgb(l * tint(rng), l * tint(rng), l * tint(rng)) : Rgb(l);
}

Vec3 random_point(const Bounds& b, std::mt19937_64& rng) {
  std::uniform_real_distribution<float> u(0.f, 1.f);
  return b.lo + Vec3(u(rng), u(rng), u(rng)) * (b.hi - b.lo);
}

bool free_at(const RayScene& rays, const Vec3& p, float clearance) {
  return rays.scene().light_bounds().contains(p) && !rays.inside_solid(p) &&
         !rays.closest_point(p, clearance).valid();
}

} // namespace

Lighting random_ceiling_lamps(const RayScene& rays, std::mt19937_64& rng, size_t count, const LampRules& rules) {
  const Scene& scene = rays.scene();
  const Bounds bounds = scene.bounds;
  std::uniform_real_distribution<float> drop(rules.min_drop, rules.max_drop);
  Lighting lamps;
  for (int attempt = 0; attempt < 20000 && lamps.size() < count; ++attempt) {
    const Vec3 p = random_point(bounds, rng);
    if (rays.inside_solid(p)) continue;
    const Hit up = rays.intersect(p, Vec3(0, 1, 0)), down = rays.intersect(p, Vec3(0, -1, 0));
    if (!up.valid() || !down.valid()) continue;
    // A ceiling faces down toward the lamp; a floor faces up.
    if (rays.face_normals()[up.triangle].y > -0.9f || rays.face_normals()[down.triangle].y < 0.9f) continue;
    if (up.t + down.t < rules.min_room_height) continue;
    const Vec3 lamp(p.x, p.y + up.t - drop(rng), p.z);
    if (!free_at(rays, lamp, 0.1f * rules.min_drop)) continue;
    bool apart = true;  // lamps of one configuration stand apart (distinct lights)
    for (const auto& l : lamps) apart &= glm::length(l.position - lamp) > 0.1f * scene.diagonal();
    if (apart) lamps.push_back(Light::point(lamp, random_intensity(rng, rules)));
  }
  REQUIRE(lamps.size() == count);
  return lamps;
}

Lighting random_free_lights(const RayScene& rays, std::mt19937_64& rng, size_t count, float clearance, const LampRules& rules) {
  const Scene& scene = rays.scene();
  const Bounds space = scene.light_bounds();
  Lighting lights;
  for (int attempt = 0; attempt < 20000 && lights.size() < count; ++attempt) {
    const Vec3 p = random_point(space, rng);
    if (!free_at(rays, p, clearance * scene.diagonal())) continue;
    bool apart = true;
    for (const auto& l : lights) apart &= glm::length(l.position - p) > 0.1f * scene.diagonal();
    if (apart) lights.push_back(Light::point(p, random_intensity(rng, rules)));
  }
  REQUIRE(lights.size() == count);
  return lights;
}

} // namespace test
