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

const char* to_string(LightType type);

} // namespace hilight
