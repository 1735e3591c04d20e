#pragma once
/// A pinhole camera: eye, target, vertical field of view; +Y is up unless the
/// view is (nearly) vertical.
#include "hilight/math.hpp"

#include <string>

namespace hilight {

struct Bounds;

struct Camera {
  Vec3 eye{0.f, 0.f, 1.f};
  Vec3 target{0.f};
  float fov_deg = 50.f;

  /// Parses "ex,ey,ez,tx,ty,tz,fov"; throws InputError on anything else.
  static Camera parse(const std::string& text);
  /// A view from outside, above and to the side, that frames the bounds.
  static Camera framing(const Bounds& bounds, float aspect);

  /// Unit direction of the ray through pixel (px, py) (pixel centres at +0.5).
  struct Basis {
    Vec3 forward, right, up;
    float tan_half_fov;
  };
  Basis basis() const;
};

} // namespace hilight
