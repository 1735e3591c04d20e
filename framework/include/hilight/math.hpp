#pragma once
/// Vector types shared by the whole code base (glm), and axis-aligned bounds.
#include <cmath>
#include <glm/glm.hpp>
#include <limits>

namespace hilight {

using Vec3 = glm::vec3;
using DVec3 = glm::dvec3;
/// Linear RGB triple: albedo, intensity (W/sr) or radiance, by context.
using Rgb = glm::vec3;

constexpr double kPi = 3.14159265358979323846;

struct Bounds {
  Vec3 lo{std::numeric_limits<float>::max()};
  Vec3 hi{-std::numeric_limits<float>::max()};

  void extend(const Vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  bool empty() const { return lo.x > hi.x; }
  Vec3 center() const { return 0.5f * (lo + hi); }
  Vec3 extent() const { return hi - lo; }
  float diagonal() const { return empty() ? 0.f : glm::length(hi - lo); }
  bool contains(const Vec3& p) const {
    return p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x <= hi.x && p.y <= hi.y && p.z <= hi.z;
  }
};

inline bool is_finite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace hilight
