#include "first_bounce.hpp"

#include "field_sums.hpp"
#include "sampling.hpp"
#include "shadow_packet.hpp"
#include "hilight/error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

namespace hilight::embree {

namespace {
/// The position on a grid of 1/4096 of the scene's size, and the normal on a
/// grid of 1/256, both in the scene's own frame: a point's identity, however
/// the scene is placed, turned or scaled (a float rounding changes it only
/// for a point within rounding of a grid line).
std::array<uint32_t, 6> point_key(const OwnFrame& frame, float size, const Vec3& p, const Vec3& n) {
  std::array<uint32_t, 6> key{};
  const float cell = size > 0.f ? size / 4096.f : 1.f;
  const Vec3 at = frame.to_own(p - frame.centre), towards = frame.to_own(n);
  for (int k = 0; k < 3; ++k) {
    // Clamped: a point far off the scene (or not finite) must not overflow the conversion.
    const float q = std::clamp(std::floor(at[k] / cell + 0.5f), -1e9f, 1e9f);
    key[k] = uint32_t(int64_t(std::isnan(q) ? 0.f : q));
    key[3 + k] = uint32_t(int32_t(std::floor(std::clamp(towards[k], -1.f, 1.f) * 256.f + 0.5f)));
  }
  return key;
}
} // namespace

BounceGather::BounceGather(const RayScene& es, const SurfacePoints& points, const std::vector<ShadingPoint>& origins, int samples,
                           uint64_t seed, ProgressStage* progress)
    : m_es(es), m_samples(samples), m_hits(points.size() * size_t(samples)) {
  if (es.scene().triangles.size() >= GatherHit::kNone)
    throw InputError("the first bounce handles at most " + std::to_string(GatherHit::kNone - 1) + " triangles (the scene has " +
                     std::to_string(es.scene().triangles.size()) + ")");
  const int per_side = samples / 2;
  const OwnFrame& frame = es.own_frame();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 64), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      // The stream depends on the point itself, not its index, so a surface
      // point gets the same gather in any point set: renders of subsets and
      // of the whole scene share random numbers (common random numbers), and
      // differences between them are differences of light, not of noise.
      // The point is read on a grid in the scene's own frame, so the same
      // scene moved, turned or scaled gets the same streams (docs/rendering-model.md).
      const Vec3 n = points.normals[i];
      uint64_t stream = mix64(seed);
      for (uint32_t b : point_key(frame, es.scene().diagonal(), points.positions[i], n)) stream = mix64(stream ^ b);
      const Vec3 own_normal = frame.to_own(n);
      for (int side = 0; side < 2; ++side) {
        const Vec3 axis = side == 0 ? n : -n;
        float rot1 = to_unit_float(stream = mix64(stream)), rot2 = to_unit_float(stream = mix64(stream));
        for (int k = 0; k < per_side; ++k) {
          float u1 = float(k + 0.5f) / float(per_side) + rot1;
          float u2 = radical_inverse2(uint32_t(k)) + rot2;
          u1 -= std::floor(u1);
          u2 -= std::floor(u2);
          // Laid out around the normal in the scene's frame, then turned back.
          const Vec3 dir = frame.to_world(cosine_direction(side == 0 ? own_normal : -own_normal, u1, u2));
          const Hit hit = es.intersect(origins[i].ray_start(dir, axis, es.epsilon()), dir);
          GatherHit& g = m_hits[i * samples + side * per_side + k];
          if (hit.valid()) {
            const bool normal_side = glm::dot(es.face_normals()[hit.triangle], dir) < 0.f;
            const Vec3 seen = (normal_side ? 1.f : -1.f) * es.face_normals()[hit.triangle];
            const auto& tri = es.scene().triangles[hit.triangle];
            uint8_t vertex_sides = 0;
            for (int v = 0; v < 3; ++v) vertex_sides |= uint8_t(glm::dot(es.scene().normals[tri[v]], seen) >= 0.f) << v;
            g = GatherHit(hit.triangle, hit.u, hit.v, normal_side, vertex_sides);
          }
        }
      }
    }
    if (progress) progress->advance(double(range.size()));
  });
  m_rays = uint64_t(points.size()) * uint64_t(samples);
  const auto& triangles = es.scene().triangles;
  std::vector<uint8_t> read(2 * es.scene().positions.size(), 0);
  for (const GatherHit& g : m_hits)
    if (g.valid())
      for (int corner = 0; corner < 3; ++corner) read[2 * triangles[g.triangle()][corner] + ((g.vertex_sides() >> corner) & 1 ? 0 : 1)] = 1;
  for (size_t k = 0; k < read.size(); ++k)
    if (read[k]) m_vertex_sides_read.push_back(uint32_t(k));
}

Rgb BounceGather::unit_indirect_irradiance(size_t i, const PreparedLight& light, const HotSpots* hot, const Vec3& x,
                                           uint64_t& rays) const {
  const Scene& scene = m_es.scene();
  // Visits each hit the gather counts (not the patches'): its hit, where
  // it is, and the normal of the side the point saw.
  auto for_each_gathered = [&](auto&& visit) {
    const GatherHit* hits = &m_hits[i * m_samples];
    for (int k = 0; k < m_samples; ++k) {
      const GatherHit& g = hits[k];
      if (!g.valid()) continue;
      const Hit hit = g.hit();
      const Vec3 y = m_es.hit_position(hit);
      const Vec3& face_normal = m_es.face_normals()[hit.triangle];
      if (hot && hot->handles(x, y, face_normal)) continue;
      visit(hit, y, g.side() * face_normal);
    }
  };
  Rgb sum(0.f);
  if (light.extended()) {  // an area source integrates its own visibility
    for_each_gathered([&](const Hit& hit, const Vec3& y, const Vec3& side_normal) {
      const float e = unit_direct_irradiance_on_side(m_es, ShadingPoint{y, false}, m_es.hit_normal(hit), side_normal, light, rays);
      if (e > 0.f) sum += scene.triangle_albedo(hit.triangle) * e;
    });
    return sum * (2.f / float(m_samples));
  }
  // A point-like light: the hits' shadow rays all end at the light, so they
  // go to Embree 16 at a time (ShadowPacket); each packet's lit hits are
  // added in hit order, as the one-ray form adds them (the same bits).
  ShadowPacket packet(m_es);
  float value[ShadowPacket::kLanes];
  uint32_t triangle[ShadowPacket::kLanes];
  auto add_lit = [&] {
    packet.trace(rays);
    for (int lane = 0; lane < packet.size(); ++lane)
      if (!packet.blocked(lane) && value[lane] > 0.f) sum += scene.triangle_albedo(triangle[lane]) * value[lane];
    packet.clear();
  };
  for_each_gathered([&](const Hit& hit, const Vec3& y, const Vec3& side_normal) {
    // A hit is no smooth point (it has no wedge): its light needs the shadow ray alone.
    ShadowRay ray;
    float e = 0.f;
    if (!unshadowed_point_irradiance_on_side(m_es, ShadingPoint{y, false}, m_es.hit_normal(hit), side_normal, light, e, ray)) return;
    value[packet.size()] = e;
    triangle[packet.size()] = hit.triangle;
    packet.add(ray);
    if (packet.full()) add_lit();
  });
  if (packet.size() > 0) add_lit();
  return sum * (2.f / float(m_samples));
}

} // namespace hilight::embree

namespace hilight::embree {

void BounceGather::interpolated_indirect_irradiance(size_t i, const float* vertex_direct, size_t stride, size_t lights,
                                                    const HotSpots* const* hot, const uint8_t* lit, size_t lit_stride,
                                                    const Vec3& x, Rgb* out) const {
  const Scene& scene = m_es.scene();
  lights = std::min(lights, kLightBlock);
  // Per light, its components apart, so the loop over lights vectorizes.
  float r[kLightBlock] = {}, g[kLightBlock] = {}, b[kLightBlock] = {}, keep[kLightBlock];
  bool any_hot = false;
  for (size_t j = 0; j < lights; ++j) any_hot |= hot[j] && !hot[j]->empty();
  const GatherHit* hits = &m_hits[i * m_samples];
  for (int k = 0; k < m_samples; ++k) {
    const GatherHit& hit = hits[k];
    if (!hit.valid()) continue;
    const auto& tri = scene.triangles[hit.triangle()];
    uint32_t entry[3];
    for (int c = 0; c < 3; ++c) entry[c] = 2 * tri[c] + ((hit.vertex_sides() >> c) & 1 ? 0u : 1u);
    if (lit && !(lit[entry[0] * lit_stride] | lit[entry[1] * lit_stride] | lit[entry[2] * lit_stride])) continue;
    const float u = hit.u(), v = hit.v(), w = 1.f - u - v;
    for (size_t j = 0; j < lights; ++j) keep[j] = 1.f;
    if (any_hot) {
      const Vec3 y = w * scene.positions[tri[0]] + u * scene.positions[tri[1]] + v * scene.positions[tri[2]];
      const Vec3& face_normal = m_es.face_normals()[hit.triangle()];
      for (size_t j = 0; j < lights; ++j)
        if (hot[j] && hot[j]->handles(x, y, face_normal)) keep[j] = 0.f;
    }
    const float* d[3];
    for (int c = 0; c < 3; ++c) d[c] = vertex_direct + entry[c] * stride;
    const Rgb albedo = scene.triangle_albedo(hit.triangle());
    for (size_t j = 0; j < lights; ++j) {
      const float e = w * d[0][j] + u * d[1][j] + v * d[2][j];
      // A skipped hit adds an exact 0 (the sums are never -0), as the one-light form skips it.
      const float s = e > 0.f && keep[j] != 0.f ? e : 0.f;
      r[j] += albedo.r * s;
      g[j] += albedo.g * s;
      b[j] += albedo.b * s;
    }
  }
  const float scale = 2.f / float(m_samples);
  for (size_t j = 0; j < lights; ++j) out[j] = Rgb(r[j], g[j], b[j]) * scale;
}

void BounceGather::field_irradiance(size_t i, int side, const Rgb* field, size_t lights, Rgb* out) const {
  std::fill(out, out + lights, Rgb(0.f));
  for_each_hit(i, side, [&](const Rgb& albedo, const uint32_t* entry, const float* weight) {
    add_interpolated(albedo, weight, field + entry[0] * lights, field + entry[1] * lights, field + entry[2] * lights, lights, out);
  });
  const float scale = 2.f / float(m_samples);
  for (size_t j = 0; j < lights; ++j) out[j] = out[j] * scale;
}

} // namespace hilight::embree
