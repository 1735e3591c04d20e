#include "ui/light_markers.hpp"

#include <algorithm>
#include <cmath>

namespace hilight::painter::ui {

namespace {

void add_cone(LineBatch& lines, const Light& spot, float length, const glm::vec4& colour) {
  const Vec3 axis = glm::normalize(spot.direction);
  const float half = glm::radians(std::min(spot.cutoff_deg, 89.f));
  const Vec3 centre = spot.position + length * std::cos(half) * axis;
  const float radius = length * std::sin(half);
  lines.circle(centre, axis, radius, colour, 32);
  const Vec3 helper = std::abs(axis.y) < 0.9f ? Vec3(0.f, 1.f, 0.f) : Vec3(1.f, 0.f, 0.f);
  const Vec3 u = glm::normalize(glm::cross(axis, helper)), v = glm::cross(axis, u);
  for (int i = 0; i < 8; ++i) {
    const float a = 6.2831853f * float(i) / 8.f;
    lines.line(spot.position, centre + radius * (std::cos(a) * u + std::sin(a) * v), colour);
  }
  lines.line(spot.position, spot.position + length * axis, glm::vec4(glm::vec3(colour), 0.5f * colour.a));
}

/// An area or line source's true outline, and a tick along its emitting normal.
void add_area_outline(LineBatch& lines, const Light& light, float diagonal, const glm::vec4& colour) {
  const AreaFrame f = AreaFrame::of(light);
  if (light.type == LightType::Rectangle) {
    const Vec3 c[4] = {f.centre - f.half_u - f.half_v, f.centre + f.half_u - f.half_v, f.centre + f.half_u + f.half_v,
                       f.centre - f.half_u + f.half_v};
    for (int i = 0; i < 4; ++i) lines.line(c[i], c[(i + 1) % 4], colour);
  } else if (light.type == LightType::Disk) {
    lines.circle(f.centre, f.normal, glm::length(f.half_u), colour, 32);
  } else {
    lines.line(f.centre - f.half_u, f.centre + f.half_u, colour);
  }
  lines.line(f.centre, f.centre + diagonal / 40.f * f.normal, glm::vec4(glm::vec3(colour), 0.5f * colour.a));
}

} // namespace

void add_light_markers(LineBatch& lines, const Lighting& lights, float diagonal) {
  for (const Light& light : lights) {
    const float peak = std::max({light.intensity.r, light.intensity.g, light.intensity.b, 1e-12f});
    const glm::vec3 colour = glm::clamp(light.intensity / peak, 0.f, 1.f);
    lines.point(light.position, glm::vec4(0.f, 0.f, 0.f, 1.f), 15.f);
    lines.point(light.position, glm::vec4(0.25f + 0.75f * colour, 1.f), 11.f);
    if (light.type == LightType::Spot) add_cone(lines, light, diagonal / 8.f, glm::vec4(1.f, 0.95f, 0.6f, 0.9f));
    if (is_area(light.type)) add_area_outline(lines, light, diagonal, glm::vec4(1.f, 0.95f, 0.6f, 0.9f));
  }
}

void add_spot_hint_markers(LineBatch& lines, const Lighting& hints, float diagonal) {
  for (const Light& hint : hints) add_cone(lines, hint, diagonal / 10.f, glm::vec4(1.f, 0.55f, 0.1f, 0.6f));
}

void add_shadow_estimate_markers(LineBatch& lines, const ShadowEstimate& estimate) {
  for (const RequestCandidates& request : estimate.requests) {
    for (const Vec3& c : request.casting) lines.point(c, glm::vec4(1.f, 0.9f, 0.2f, 0.8f), 5.f);
    for (uint32_t i : request.in_cone) lines.point(request.casting[i], glm::vec4(0.3f, 0.5f, 1.f, 1.f), 7.f);
    const Vec3 axis = request.occluder_centre - request.shadow_centre;
    lines.line(request.shadow_centre, request.occluder_centre + axis, glm::vec4(0.3f, 0.5f, 1.f, 0.8f));
  }
  for (const Light& light : estimate.lights) lines.point(light.position, glm::vec4(1.f), 9.f);
}

void add_box_marker(LineBatch& lines, const Bounds& box, const glm::vec4& colour) {
  const Vec3 lo = box.lo, hi = box.hi;
  auto corner = [&](int i) { return Vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z); };
  for (int i = 0; i < 8; ++i)
    for (int bit = 1; bit < 8; bit <<= 1)
      if (!(i & bit)) lines.line(corner(i), corner(i | bit), colour);
}

} // namespace hilight::painter::ui
