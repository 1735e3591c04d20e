#pragma once
/// A lighting configuration: point lights and spotlights (rendering model in
/// docs/rendering-model.md). Intensity is radiant intensity per channel, W/sr.
#include "hilight/math.hpp"

#include <string>
#include <vector>

namespace hilight {

enum class LightType { Point, Spot };

struct Light {
  LightType type = LightType::Point;
  Vec3 position{0.f};
  Rgb intensity{1.f};
  Vec3 direction{0.f, -1.f, 0.f}; ///< spot only; unit length
  float cutoff_deg = 30.f;        ///< spot only: half-angle of the cone
  float falloff_deg = 0.f;        ///< spot only: width of the soft edge inside the cutoff

  static Light point(const Vec3& position, const Rgb& intensity) {
    Light l;
    l.position = position;
    l.intensity = intensity;
    return l;
  }
  /// Every field equal (the painter's undo compares states exactly).
  bool operator==(const Light&) const = default;

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

const char* to_string(LightType type);

} // namespace hilight
