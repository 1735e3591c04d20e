// A smooth point keeps the tilted facets of its own fan (ShadingPoint::fan),
// so that its wedge test (docs/rendering-model.md, "The wedge") needs no
// look-up of the triangles near it: the kept fan must give the very answers
// the look-up gives, on real curved models, and a fan too large to keep is
// still looked up.
#include "hilight/fixtures/real_model_scenes.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/ray_scene.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

using namespace hilight;

namespace {

/// A unit direction leaving the tangent plane of `n` at an elevation below
/// `wedge` (the only ones the wedge test looks at), on either side.
Vec3 near_tangent(const Vec3& n, float wedge, std::mt19937_64& rng) {
  const Vec3 helper = std::abs(n.x) < 0.9f ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  const Vec3 t = glm::normalize(glm::cross(n, helper)), b = glm::cross(n, t);
  std::uniform_real_distribution<float> turn(0.f, 6.2831853f), height(-1.f, 1.f);
  const float phi = turn(rng), s = wedge * height(rng);
  return glm::normalize(std::sqrt(1.f - s * s) * (std::cos(phi) * t + std::sin(phi) * b) + s * n);
}

} // namespace

TEST_CASE("wedge: a smooth point's kept fan answers as the look-up of its triangles does, on real curved models",
          "[wedge][geometry]") {
  const Scene scene = finish_scene(builders::curved_models_on_floor(), {});
  const RayScene rays(scene);
  std::mt19937_64 rng(3201);
  size_t kept = 0, looked_up = 0, tested = 0, blocked = 0;
  for (size_t v = 0; v < scene.positions.size(); ++v) {
    const ShadingPoint at = shading_point(rays, scene.positions[v], scene.normals[v]);
    if (!at.smooth || at.wedge == 0.f || at.flat_fan) continue;
    if (at.fan_size == ShadingPoint::kFanLookedUp) {
      ++looked_up;
      continue;
    }
    ++kept;
    REQUIRE(at.fan_size > 0);
    ShadingPoint lookup = at;
    lookup.fan_size = ShadingPoint::kFanLookedUp;
    for (int k = 0; k < 16; ++k) {
      const Vec3 dir = near_tangent(scene.normals[v], at.wedge, rng);
      const bool by_fan = in_own_wedge_slow(rays, at, scene.normals[v], dir);
      INFO("vertex " << v << " direction " << dir.x << " " << dir.y << " " << dir.z);
      REQUIRE(by_fan == in_own_wedge_slow(rays, lookup, scene.normals[v], dir));
      ++tested;
      blocked += by_fan;
    }
  }
  std::printf("kept fan: %zu smooth points keep theirs, %zu look it up; %zu of %zu near-tangent directions blocked\n", kept,
              looked_up, blocked, tested);
  CHECK(kept > 1000);  // the models' smooth vertices, nearly all of them
  CHECK(looked_up < kept / 10);  // a pole or a cone tip: few
  CHECK(blocked > tested / 20);  // the test sees both answers
  CHECK(blocked < tested);
}

TEST_CASE("wedge: a fan of more facets than are kept (a cone's tip) is looked up and still blocks its wedge",
          "[wedge][geometry]") {
  // A low cone of 12 facets, its tip smooth (normal up), each facet falling
  // 0.2 over its radius of 1: the wedge lies between the level plane and them.
  Scene raw;
  raw.materials.push_back(Material{});
  raw.positions.push_back(Vec3(0.f));
  raw.normals.push_back(Vec3(0, 1, 0));
  const int sides = 12;
  for (int k = 0; k < sides; ++k) {
    const float phi = 6.2831853f * float(k) / sides;
    raw.positions.push_back(Vec3(std::cos(phi), -0.2f, std::sin(phi)));
    raw.normals.push_back(glm::normalize(Vec3(0.2f * std::cos(phi), 1.f, 0.2f * std::sin(phi))));
  }
  for (uint32_t k = 0; k < uint32_t(sides); ++k) {
    raw.triangles.push_back({0u, 1u + (k + 1) % sides, 1u + k});  // wound up
    raw.triangle_material.push_back(0);
  }
  const Scene scene = finish_scene(std::move(raw), {10.f});
  const RayScene rays(scene);
  const ShadingPoint tip = shading_point(rays, Vec3(0.f), Vec3(0, 1, 0));
  REQUIRE(tip.smooth);
  CHECK(tip.fan_size == ShadingPoint::kFanLookedUp);
  REQUIRE(tip.wedge > 0.19f);
  for (int k = 0; k < 24; ++k) {
    const float phi = 6.2831853f * (float(k) + 0.5f) / 24.f;
    const Vec3 out(std::cos(phi), 0.f, std::sin(phi));
    INFO("azimuth " << phi);
    CHECK(in_own_wedge(rays, tip, Vec3(0, 1, 0), glm::normalize(out + Vec3(0, -0.1f, 0))));   // between plane and facet
    CHECK_FALSE(in_own_wedge(rays, tip, Vec3(0, 1, 0), glm::normalize(out + Vec3(0, 0.1f, 0))));  // above the plane
    CHECK_FALSE(in_own_wedge(rays, tip, Vec3(0, 1, 0), glm::normalize(out + Vec3(0, -0.3f, 0))));  // under the facet
  }
}
