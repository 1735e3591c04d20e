#pragma once
/// A lighting configuration: point lights, spotlights, luminaires with a
/// measured light distribution, and area and line sources (rendering model in
/// docs/rendering-model.md). Intensity is radiant intensity per channel, W/sr
/// (a luminaire's: at the peak of its distribution; an area or line source's:
/// along its normal, or at its profile's peak).
#include "hilight/math.hpp"
#include "hilight/photometry.hpp"

#include <memory>
#include <string>
#include <vector>

namespace hilight {

enum class LightType { Point, Spot, Luminaire, Rectangle, Disk, Line };

/// Rectangles, disks and lines: sources with an extent, integrated over it.
inline bool is_area(LightType type) { return type == LightType::Rectangle || type == LightType::Disk || type == LightType::Line; }

struct Light {
  LightType type = LightType::Point;
  Vec3 position{0.f};
  Rgb intensity{1.f};
  Vec3 direction{0.f, -1.f, 0.f}; ///< spot only; unit length
  float cutoff_deg = 30.f;        ///< spot only: half-angle of the cone
  float falloff_deg = 0.f;        ///< spot only: width of the soft edge inside the cutoff
  /// Luminaire only: its photometry (IES/EULUMDAT), aimed along `direction`
  /// (its nadir, γ = 0) with its C = 0 plane turned `spin_deg` about it from
  /// the reference (luminaire_frame()); `profile_path` is where it came from.
  std::shared_ptr<const Photometry> profile;
  std::string profile_path;
  float spin_deg = 0.f;
  /// Area and line sources: `position` is the centre, `direction` the
  /// emitting side's normal, `up` the axis of size[0] (a rectangle's first
  /// side, a line's length; a disk's only orients its profile), `size` the
  /// rectangle's [w, h], the disk's [diameter, 0], the line's [length, 0].
  /// Lambertian (intensity × cos θ, front side only) without a profile; with
  /// one, every part of the opening emits the profile's shape, its C = 0
  /// plane along `up` (LM-63's length, EULUMDAT's C0–C180 axis).
  Vec3 up{0.f, 0.f, 1.f};
  glm::vec2 size{0.f};

  static Light point(const Vec3& position, const Rgb& intensity) {
    Light l;
    l.position = position;
    l.intensity = intensity;
    return l;
  }
  /// Every field equal (the painter's undo compares states exactly).
  bool operator==(const Light&) const = default;

  /// An area or line source (see `up` and `size`); `up` is made
  /// perpendicular to `direction`.
  static Light area(LightType type, const Vec3& position, const Vec3& direction, const Vec3& up, glm::vec2 size,
                    const Rgb& intensity);

  static Light spot(const Vec3& position, const Vec3& direction, float cutoff_deg, const Rgb& intensity,
                    float falloff_deg = 0.f) {
    Light l;
    l.type = LightType::Spot;
    l.position = position;
    l.direction = glm::normalize(direction);
    l.cutoff_deg = cutoff_deg;
    l.falloff_deg = falloff_deg;
    l.intensity = intensity;
    return l;
  }
};

using Lighting = std::vector<Light>;

/// A luminaire's axes: `nadir` (γ = 0), `c0` (the C = 0 plane's horizontal
/// direction) and `c90` = c0 × nadir (counter-clockwise seen from behind the
/// nadir, as type C angles run). The reference c0 is the world +X projected
/// off the nadir (+Z when the nadir is along X), then turned by spin_deg.
struct LuminaireFrame {
  Vec3 nadir{0.f, -1.f, 0.f}, c0{1.f, 0.f, 0.f}, c90{0.f, 0.f, -1.f};
  static LuminaireFrame of(const Light& light);
  /// Type C angles (degrees) of the unit direction `to_point` from the luminaire.
  void angles(const Vec3& to_point, double& c_deg, double& gamma_deg) const;
};

/// A luminaire's intensity towards unit direction `to_point` over its peak,
/// in [0, 1] (the profile's shape; its `intensity` is the scale).
float luminaire_factor(const Light& light, const LuminaireFrame& frame, const Vec3& to_point);

/// For renderers without measured distributions (POV-Ray): a luminaire's
/// profile averaged over C (so made rotationally symmetric about its aim) as
/// a point light and spotlights every 5° of γ, downward and upward, each the
/// step between two samples (signed: a profile may rise with γ). Between
/// the samples the spots' smoothstep edges interpolate. An area or line
/// source is first cut into 16 parts (area_light_elements), each expanded so.
/// Other lights as they are.
Lighting luminaire_as_spots(const Light& light);

/// A spotlight's cone as cosines, so hot loops need no trigonometry; one
/// definition of the soft edge for every renderer (docs/rendering-model.md).
struct SpotCone {
  float cos_cutoff = -1.f;  ///< dark below this cosine
  float cos_inner = -1.f;   ///< full intensity at and above this cosine

  static SpotCone of(const Light& light);
  /// Angular factor for the cosine between the spot's direction and the unit
  /// direction from the light to the point: smoothstep in the cosine between
  /// the cone's edge and its full-intensity core.
  float factor(float cos_alpha) const {
    if (cos_alpha < cos_cutoff) return 0.f;
    if (cos_alpha >= cos_inner) return 1.f;
    const float t = (cos_alpha - cos_cutoff) / (cos_inner - cos_cutoff);
    return t * t * (3.f - 2.f * t);
  }
};

/// The area or line source's opening: its centre, unit normal and the two
/// in-plane axes scaled to half its sides (`half_v` zero for a line; a disk's
/// radius on both).
struct AreaFrame {
  Vec3 centre{0.f}, normal{0.f, -1.f, 0.f}, half_u{0.f}, half_v{0.f};
  static AreaFrame of(const Light& light);
};

/// Why an area or line source is malformed ("" when it is fine): a size
/// that is not positive or finite, a direction that is not unit length, an
/// `up` along the direction.
std::string area_light_problem(const Light& light);

/// Centres of `count` (about; fewer when the shape does not divide so)
/// equal parts of an area or line source: a grid of cells as square as the
/// sides allow, equal-area rings of equal sectors, equal segments.
std::vector<Vec3> area_element_centres(const Light& light, int count);

/// An area or line source cut into `count` (about) equal parts, each a
/// luminaire at the part's centre carrying its share of the intensity
/// (Lambertian: a cos γ profile over the front side; else the light's
/// profile), aimed and oriented as the light: for renderers that light from
/// points (POV-Ray through luminaire_as_spots, ism-vulkan). Other lights as they are.
Lighting area_light_elements(const Light& light, int count);

/// A luminaire made an area or line source of its file's luminous opening
/// (Photometry::opening_*), aimed and turned as it was: a disk, a rectangle
/// with `up` along C0, or a line along the opening's only side. False (and
/// unchanged) when the file gives no opening.
bool with_luminous_opening(Light& luminaire);

/// The cosine distribution (cd ∝ cos γ to 90°, dark beyond) on a 1° grid.
std::shared_ptr<const Photometry> lambertian_profile();

const char* to_string(LightType type);
/// The type named as in lights files ("point", ..., "line"); false if unknown.
bool light_type_from_string(const std::string& name, LightType& type);

} // namespace hilight
