#pragma once
/// The first diffuse bounce by gathering: every point casts N rays over both
/// hemispheres (two-sided surfaces; N/2 cosine-weighted on each side, from
/// Hammersley points rotated per point, the rotation seeded by the point's
/// position and normal, both read in the scene's own frame, own_frame.hpp,
/// where each hemisphere's tangent frame is built too: the same scene turned
/// gathers along the same rays, turned). The hits are kept, so each light
/// then costs N shadow rays per point and no further intersection tests:
///   E_ind(x) = ∫_{S²} L(y(ω)) |cos θ| dω  ≈  (2/N) Σ_k albedo(y_k) · E_dir(y_k)
/// (each hemisphere's estimate is π/(N/2) Σ L, and L(y) = albedo(y)/π · E_dir(y)).
/// The radiance a hit y sends back is that of y's side facing the gathering
/// point: ρ/π times the direct light arriving on that side only. So the
/// inside of a closed object, lit on no side, sends nothing (no light leaks
/// through solids), while a lone sheet lit from one side glows on that side.
/// Unbiased for any N; the error falls as N grows (tests show it).
#include "direct_light.hpp"
#include "hot_spots.hpp"
#include "hilight/progress.hpp"
#include "hilight/ray_scene.hpp"
#include "hilight/surface_points.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace hilight::embree {

class BounceGather {
public:
  /// `origins`: where each point is shaded (hilight::shading_point), so rays
  /// from a point on a crease do not start on the neighbouring face's plane
  /// and rays from a smooth point skip its own facets.
  /// `progress`: advanced by one per point gathered (hilight/progress.hpp).
  BounceGather(const RayScene& es, const SurfacePoints& points, const std::vector<ShadingPoint>& origins, int samples,
               uint64_t seed, ProgressStage* progress = nullptr);

  int samples() const { return m_samples; }
  /// The (vertex, side) values interpolated_indirect_irradiance reads, as
  /// 2·vertex + (0: the side its normal points to, 1: the other), ascending:
  /// the only direct light the interpolated mode needs computed.
  const std::vector<uint32_t>& vertex_sides_read() const { return m_vertex_sides_read; }
  uint64_t rays_cast() const { return m_rays; }

  /// Indirect irradiance (RGB, per unit light intensity) at point i, shaded
  /// at `x`, from its gather hits — less those the light's hot patches count
  /// instead (`hot` may be null; add hot->irradiance() for their share).
  Rgb unit_indirect_irradiance(size_t i, const PreparedLight& light, const HotSpots* hot, const Vec3& x, uint64_t& rays) const;
  /// The same for up to kLightBlock lights at once, with the direct
  /// irradiance at each hit interpolated from `vertex_direct` instead of
  /// shadow rays: per (vertex, side) — 2·vertex + (0: the side its normal
  /// points to, 1: the other) — the block's lights, `stride` floats apart,
  /// light 0 of the block first. The hits are decoded once for all the
  /// block's lights (issue 33); each light's sum runs in hit order. `hot[j]`
  /// is light j's patches (null: none). `lit` (null: all lit) says per vertex
  /// side, `lit_stride` bytes apart, whether any of the block's lights
  /// reaches it: a hit whose three corners are dark adds nothing and is
  /// passed by. Writes out[0..lights).
  static constexpr size_t kLightBlock = 16;
  void interpolated_indirect_irradiance(size_t i, const float* vertex_direct, size_t stride, size_t lights,
                                        const HotSpots* const* hot, const uint8_t* lit, size_t lit_stride, const Vec3& x,
                                        Rgb* out) const;
  /// Irradiance at point i gathered from `lights` fields of irradiance given
  /// per (vertex, side) as vertex_sides_read() indexes it, interpolated across
  /// each hit triangle: (2/N) Σ ρ(y) F_j(y), over hemisphere `side` (0: the
  /// point's normal side, 1: the other; kBothSides: the whole sphere), into
  /// out[j]. Entry-major (MultiBounce's layout): the lights' values at vertex
  /// side e from field[e · lights], so one walk over the hits serves all.
  /// The further bounces read the light already bounced from this (multi_bounce.hpp).
  static constexpr int kBothSides = 2;
  void field_irradiance(size_t i, int side, const Rgb* field, size_t lights, Rgb* out) const;
  /// Visits each valid hit of point i's hemisphere `side` (as above) with the
  /// hit triangle's albedo, its three field entries and their barycentric
  /// weights: visit(albedo, const uint32_t entry[3], const float weight[3]).
  template <class Visit>
  void for_each_hit(size_t i, int side, Visit&& visit) const {
    const Scene& scene = m_es.scene();
    const int per_side = m_samples / 2;
    const int begin = side == 1 ? per_side : 0, end = side == 0 ? per_side : m_samples;
    const GatherHit* hits = &m_hits[i * size_t(m_samples)];
    for (int k = begin; k < end; ++k) {
      const GatherHit& hit = hits[k];
      if (!hit.valid()) continue;
      const auto& tri = scene.triangles[hit.triangle()];
      const float u = hit.u(), v = hit.v();
      uint32_t entry[3];
      for (int c = 0; c < 3; ++c) entry[c] = 2 * tri[c] + ((hit.vertex_sides() >> c) & 1 ? 0u : 1u);
      const float weight[3] = {1.f - u - v, u, v};
      visit(scene.triangle_albedo(hit.triangle()), entry, weight);
    }
  }

private:
  const RayScene& m_es;
  int m_samples;
  uint64_t m_rays = 0;
  /// A gather ray's hit and which side of the hit triangle it saw, in 8
  /// bytes (128 of them a vertex: 250 MB over a 400k-triangle building's
  /// vertices, where 20 bytes made 640 MB): the triangle and four flags share
  /// one word; the barycentrics are kept in 16 bits each (the hit moves
  /// within its triangle by at most 1/131,070 of its edges).
  struct GatherHit {
    static constexpr uint32_t kTriangleBits = 28, kNone = (1u << kTriangleBits) - 1;
    uint32_t packed = kNone;  ///< triangle | seen side (bit 28) | vertex sides (bits 29-31)
    uint16_t u16 = 0, v16 = 0;
    GatherHit() = default;
    GatherHit(uint32_t triangle, float u, float v, bool normal_side, uint8_t vertex_sides)
        : packed(triangle | uint32_t(normal_side) << kTriangleBits | uint32_t(vertex_sides & 7u) << (kTriangleBits + 1)),
          u16(unorm(u)), v16(unorm(v)) {}
    static uint16_t unorm(float x) { return uint16_t(std::lround(std::clamp(x, 0.f, 1.f) * 65535.f)); }
    float u() const { return float(u16) * (1.f / 65535.f); }
    float v() const { return float(v16) * (1.f / 65535.f); }
    bool valid() const { return triangle() != kNone; }
    uint32_t triangle() const { return packed & kNone; }
    Hit hit() const {
      Hit h;
      h.triangle = triangle();
      h.u = u();
      h.v = v();
      return h;
    }
    /// +1: the side the face normal points to; -1: the other.
    float side() const { return packed >> kTriangleBits & 1u ? 1.f : -1.f; }
    /// Bit k: the seen side is the side vertex k's normal points to (so the
    /// interpolated mode reads that vertex's "normal side" value).
    uint8_t vertex_sides() const { return uint8_t(packed >> (kTriangleBits + 1)); }
  };
  static_assert(sizeof(GatherHit) == 8);
  std::vector<GatherHit> m_hits;  ///< point-major, m * samples
  std::vector<uint32_t> m_vertex_sides_read;
};

} // namespace hilight::embree
