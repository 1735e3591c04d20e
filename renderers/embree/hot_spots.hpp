#pragma once
/// The first bounce near a light (issue 11). A lamp close to a surface (a
/// ceiling lamp 15 cm down) makes a 1/d² hot spot there; gather rays from
/// elsewhere hit it rarely and, when they do, very brightly: fireflies. So
/// the directions around each light are split into cells (a cube map,
/// kCellsPerFace² per face). The part of a cell whose surfaces are close to
/// the light — within 5× the distance to its nearest surface and 0.25× the
/// median distance to the surfaces it meets (16× brighter than typical), so
/// a light mid-room has none — is a
/// *hot patch* when nearly flat. A point farther than 3 patch radii from it
/// receives the patch's
/// reflected flux from one virtual point light at its flux-weighted centre,
/// with one shadow ray, and its gather ignores hits in that cell; a nearer
/// point (which sees the patch under a wide angle, so its gather is not
/// noisy) gathers the cell as before. Each (point, cell) pair is counted
/// once, so the split adds no light and loses none.
///
/// Bias, stated: a patch's light reaches a point as from its centre — its
/// size against the distance (≤ 1/3) blurs the patch's soft shadow into a
/// point light's hard one and shifts its cosines by up to ~1/3 radian.
/// Measured (tests/test_bounce_noise.cpp): the total bounce within 1% of a
/// 4096-ray gather, and D̄ 4.9% against it at 512 rays where the gather alone
/// is 27% off (a lamp 15 cm below a ceiling).
/// Linear in the light's intensity and deterministic (no random numbers).
#include "direct_light.hpp"

#include <vector>

namespace hilight::embree {

class HotSpots {
public:
  /// The hot patches of `light` (unit intensity) in `rays`' scene; counts its rays.
  HotSpots(const RayScene& rays, const PreparedLight& light, uint64_t& cast);

  bool empty() const { return m_patches.empty(); }
  size_t size() const { return m_patches.size(); }

  /// True when a gather hit at `y` from the point at `x` is counted by a hot
  /// patch instead (so the gather skips it).
  bool handles(const Vec3& x, const Vec3& y) const;
  /// Irradiance (RGB, unit light intensity) at the point shaded at `at` with
  /// normal `n` from the patches that handle it: Φ cosθ_patch |cosθ_x| / (π r²) · V.
  Rgb irradiance(const RayScene& rays, const ShadingPoint& at, const Vec3& n, uint64_t& cast) const;
  /// The same with one visibility for all patches: whether the point sees
  /// the light itself (the patches lie near it). The vertex mode's shortcut:
  /// one shadow ray instead of one per patch; its bias (a patch's shadow is
  /// the light's) is the reference polish's to remove.
  Rgb irradiance_seen(const ShadingPoint& at, const Vec3& n, bool sees_light) const;
  /// Whether the point shaded at `at` (normal n) sees the light: one shadow ray.
  bool sees_light(const RayScene& rays, const ShadingPoint& at, const Vec3& n, uint64_t& cast) const;

  static constexpr int kCellsPerFace = 4;   ///< cells along a cube face's edge
  static constexpr int kSubSamples = 4;     ///< sample directions along a cell's edge
  static constexpr float kHotFraction = 0.25f;  ///< hot: nearer than this × the light's median surface distance

private:
  struct Patch {
    Vec3 position;  ///< flux-weighted centre, lifted toward the light
    Vec3 normal;    ///< the lit side
    Rgb flux;       ///< reflected flux at unit intensity: Σ ρ · S · dω
    float near2;    ///< squared distance within which the gather keeps the cell
  };
  int cell_of(const Vec3& direction) const;

  Vec3 m_light;
  float m_reach2 = 0.f;            ///< squared distance within which a hit can be in a hot patch
  std::vector<int32_t> m_cell;     ///< per cell: its patch, or -1
  std::vector<Patch> m_patches;
};

} // namespace hilight::embree
