#pragma once
/// The first bounce from patches of light (issues 11 and 32). Gather rays
/// see the direct light's pattern on the surfaces around them; where it is
/// uneven — a 1/d² hot spot over a ceiling lamp 15 cm down, a lit wall
/// beside a dim one — each point's few rays land differently and the bounce
/// is speckled (fireflies at worst). So the directions around each light are
/// split into cells (a cube map in the scene's own frame, kCellsPerFace² per
/// face, kSubSamples² rays each), and what a cell's rays meet is grouped into
/// *patches*: surfaces of one plane (normals within 0.9, offsets within
/// kPlaneTolerance of the light's distance), its hot part (below) apart
/// from the rest, so a hot spot's patch stays small. A point farther than
/// kNearRadii patch radii (kHotNearRadii from a hot patch: below) from a
/// patch receives the patch's reflected flux
/// from one virtual point light at its flux-weighted centre, with one shadow
/// ray, and its gather skips hits on that patch; a nearer point (which sees
/// the patch under a wide angle, so its gather is not noisy) gathers it as
/// before, and so do surfaces no patch holds (a cell's odd corner, a chair
/// leg). Each (point, patch) pair is counted once, so the split adds no
/// light and loses none. The same scene turned or moved lays out the same
/// cells, turned or moved.
///
/// Every cell makes patches (`every_cell`) in the exact mode. The vertex
/// mode, which judges every patch's visibility by the light's own, keeps
/// the hot patches only: those within 5× the light's nearest-surface
/// distance and kHotFraction of its median one (16× brighter than typical).
/// Far from a hot patch its fireflies outweigh the bias of its point-light
/// shadow; elsewhere kNearRadii keeps that bias within CIE 171's 5% (case
/// 5.7, an obstruction's shadow of a lit floor).
///
/// Bias, stated: a patch's light reaches a point as from its centre — its
/// size against the distance (≤ 1/3) blurs the patch's soft shadow into a
/// point light's hard one and shifts its cosines by up to ~1/3 radian.
/// Measured against 4096-ray gathers (tests/test_bounce_noise.cpp,
/// docs/rendering-model.md): the total bounce within 1%, and the speckle
/// and the error per vertex halved at 128 rays.
/// Linear in the light's intensity and deterministic (no random numbers).
#include "direct_light.hpp"

#include <array>
#include <vector>

namespace hilight::embree {

class HotSpots {
public:
  /// The patches of `light` (unit intensity) in `rays`' scene — of every
  /// cell, or the hot ones only — and counts its rays.
  HotSpots(const RayScene& rays, const PreparedLight& light, bool every_cell, uint64_t& cast);

  bool empty() const { return m_patches.empty(); }
  size_t size() const { return m_patches.size(); }

  /// True when a gather hit at `y` (on a triangle with face normal
  /// `face_normal`) from the point at `x` is counted by a patch instead (so
  /// the gather skips it).
  bool handles(const Vec3& x, const Vec3& y, const Vec3& face_normal) const;
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
  static constexpr int kPlanesPerCell = 4;      ///< planes a cell's rays are sorted into (a room's corner: 3)
  static constexpr int kMinRays = 2;            ///< a plane met by fewer of a cell's rays stays the gather's
  static constexpr float kPlaneTolerance = 0.02f;  ///< a patch's thickness, against the light's distance
  static constexpr float kNearRadii = 8.f;      ///< nearer than this many patch radii, the gather keeps the patch
  static constexpr float kHotNearRadii = 3.f;   ///< the same for a hot patch (its fireflies outweigh its hard shadow)

private:
  struct Patch {
    Vec3 position;  ///< flux-weighted centre, lifted toward the light
    Vec3 normal;    ///< the lit side
    Rgb flux;       ///< reflected flux at unit intensity: Σ ρ · S · dω
    float near2;    ///< squared distance within which the gather keeps the patch
  };
  /// A plane a cell's rays met, in the order they were sorted: a surface
  /// point belongs to the first plane it lies on (a normal within 0.9, an
  /// offset within `thickness`), the same rule for the cell's rays and for
  /// gather hits, so a patch's flux and the hits it takes over are one set.
  struct Plane {
    Vec3 point{0.f}, normal{0.f};  ///< the normal faces the light
    float thickness = -1.f;        ///< < 0: no plane
    bool hot = false;              ///< holds the part within the hot reach, or the part beyond it
    int32_t patch = -1;            ///< -1: met by too few rays, left to the gather
    bool holds(const Vec3& y, const Vec3& n, bool y_hot) const {
      return thickness >= 0.f && y_hot == hot && glm::dot(n, normal) > 0.9f && std::abs(glm::dot(y - point, normal)) <= thickness;
    }
  };
  int cell_of(const Vec3& direction) const;

  Vec3 m_light;
  OwnFrame m_frame;                ///< the cube map's axes: the scene's own
  float m_reach2 = 0.f;            ///< squared distance within which a hit can be on a patch
  float m_hot2 = 0.f;              ///< squared distance within which a surface is hot
  std::vector<std::array<Plane, kPlanesPerCell>> m_cell;  ///< per cell: the planes its rays met
  std::vector<Patch> m_patches;
};

} // namespace hilight::embree
