#include "hilight/plan_view.hpp"

#include "hilight/illuminance_criteria.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <tbb/parallel_for.h>

namespace hilight {

std::vector<PlanSection> plan_sections(const Scene& scene, size_t most) {
  constexpr float kBin = 0.1f, kStorey = 2.f, kEyeHeight = 1.5f, kRoomAbove = 1.f;
  // Upward-facing area by height, in 10 cm bins.
  std::map<long, double> area;
  for (size_t t = 0; t < scene.triangles.size(); ++t) {
    const auto& tri = scene.triangles[t];
    const Vec3 a = scene.positions[tri[0]], b = scene.positions[tri[1]], c = scene.positions[tri[2]];
    const Vec3 cross = glm::cross(b - a, c - a);
    const float length = glm::length(cross);
    if (!(length > 0.f) || cross.y / length < 0.9f) continue;
    area[std::lround(((a.y + b.y + c.y) / 3.f) / kBin)] += 0.5 * double(length);
  }
  double largest = 0;
  for (const auto& [bin, a] : area) largest = std::max(largest, a);
  std::vector<float> floors;
  for (const auto& [bin, a] : area) {
    const float y = float(bin) * kBin;
    if (a < 0.2 * largest || y > scene.bounds.hi.y - kRoomAbove) continue;
    // Within a storey's height of the floor below: part of that storey (a step, a landing, a desk top).
    if (floors.empty() || y - floors.back() >= kStorey) floors.push_back(y);
  }
  std::vector<PlanSection> out;
  if (floors.empty()) {
    const float over = scene.bounds.hi.y + 0.01f * scene.diagonal();
    return {PlanSection{scene.bounds.lo.y, over, std::numeric_limits<float>::infinity()}};
  }
  if (floors.size() > most) floors.resize(most);
  for (size_t k = 0; k < floors.size(); ++k) {
    const float top = k + 1 < floors.size() ? floors[k + 1] : std::numeric_limits<float>::infinity();
    out.push_back({floors[k], std::min(floors[k] + kEyeHeight, 0.5f * (floors[k] + top)), top});
  }
  return out;
}

PlanFrame::PlanFrame(const Bounds& area, int max_width) {
  const Vec3 e = area.extent();
  const float margin = 0.05f * std::max({e.x, e.z, 1e-6f});
  const float w = e.x + 2.f * margin, d = e.z + 2.f * margin;
  x0 = area.lo.x - margin;
  z0 = area.lo.z - margin;
  pixel = std::max(w / float(max_width), d / float(2 * max_width));
  width = std::clamp(int(std::ceil(w / pixel)), 1, max_width);
  height = std::clamp(int(std::ceil(d / pixel)), 1, 2 * max_width);
}

Image plan_image(const RayScene& rays, const PlanFrame& frame, float section, const std::vector<Rgb>& values,
                 std::vector<uint8_t>* cut) {
  const Scene& scene = rays.scene();
  Image image(frame.width, frame.height);
  if (cut) cut->assign(image.pixels.size(), 0);
  const Vec3 down(0.f, -1.f, 0.f);
  tbb::parallel_for(0, frame.height, [&](int py) {
    for (int px = 0; px < frame.width; ++px) {
      const Vec3 origin(frame.x0 + (float(px) + 0.5f) * frame.pixel, section, frame.z0 + (float(py) + 0.5f) * frame.pixel);
      const Hit hit = rays.intersect(origin, down);
      if (!hit.valid()) continue;
      const size_t i = size_t(py) * size_t(frame.width) + size_t(px);
      image.covered[i] = 1;
      if (glm::dot(rays.face_normals()[hit.triangle], down) > 0.f) {
        if (cut) (*cut)[i] = 1;
        continue;
      }
      const auto& tri = scene.triangles[hit.triangle];
      image.pixels[i] = (1.f - hit.u - hit.v) * values[tri[0]] + hit.u * values[tri[1]] + hit.v * values[tri[2]];
    }
  });
  return image;
}

std::optional<double> lux_below(const RayScene& rays, const std::vector<Rgb>& radiance, const std::vector<Rgb>& albedo,
                                const Vec3& p) {
  const Scene& scene = rays.scene();
  if (radiance.size() != scene.positions.size() || albedo.size() != scene.positions.size()) return std::nullopt;
  const Hit hit = rays.intersect(p, Vec3(0.f, -1.f, 0.f));
  if (!hit.valid()) return std::nullopt;
  const Vec3 at = rays.hit_position(hit);
  uint32_t nearest = scene.triangles[hit.triangle][0];
  for (uint32_t v : scene.triangles[hit.triangle])
    if (glm::length(scene.positions[v] - at) < glm::length(scene.positions[nearest] - at)) nearest = v;
  const Rgb& rho = albedo[nearest];
  Rgb irradiance_over_pi(0.f);
  for (int c = 0; c < 3; ++c) {
    if (!(rho[c] > 0.f)) return std::nullopt;  // a black surface tells nothing of the light on it
    irradiance_over_pi[c] = radiance[nearest][c] / rho[c];
  }
  const std::array<Rgb, 1> one{irradiance_over_pi};
  return lux_from_radiance(one)[0];
}

namespace {

/// E = 683 · π · luminance(radiance / albedo) at one vertex; nullopt on a black surface.
std::optional<double> lux_at_vertex(const std::vector<Rgb>& radiance, const std::vector<Rgb>& albedo, uint32_t v) {
  Rgb irradiance_over_pi(0.f);
  for (int c = 0; c < 3; ++c) {
    if (!(albedo[v][c] > 0.f)) return std::nullopt;
    irradiance_over_pi[c] = radiance[v][c] / albedo[v][c];
  }
  const std::array<Rgb, 1> one{irradiance_over_pi};
  return lux_from_radiance(one)[0];
}

} // namespace

std::vector<Rgb> vertex_lux(const std::vector<Rgb>& radiance, const std::vector<Rgb>& albedo) {
  std::vector<Rgb> out(radiance.size(), Rgb(0.f));
  if (albedo.size() != radiance.size()) return out;
  for (size_t v = 0; v < radiance.size(); ++v)
    if (const auto lux = lux_at_vertex(radiance, albedo, uint32_t(v))) out[v] = Rgb(float(*lux));
  return out;
}

std::optional<double> lux_on_floor(const RayScene& rays, const std::vector<Rgb>& radiance, const std::vector<Rgb>& albedo,
                                   const Vec3& p, float floor) {
  const Scene& scene = rays.scene();
  if (radiance.size() != scene.positions.size() || albedo.size() != scene.positions.size()) return std::nullopt;
  const Vec3 down(0.f, -1.f, 0.f);
  Vec3 from = p;
  for (int step = 0; step < 64; ++step) {  // past the things over the floor, one at a time
    const Hit hit = rays.intersect(from, down);
    if (!hit.valid()) return std::nullopt;
    const Vec3 at = from + hit.t * down;
    if (at.y < floor - kFloorTolerance) return std::nullopt;  // through a hole in the floor
    if (at.y <= floor + kFloorTolerance && rays.face_normals()[hit.triangle].y > 0.9f) {
      const auto& tri = scene.triangles[hit.triangle];
      const float w[3] = {1.f - hit.u - hit.v, hit.u, hit.v};
      double lux = 0;
      for (int k = 0; k < 3; ++k) {
        const auto corner = lux_at_vertex(radiance, albedo, tri[size_t(k)]);
        if (!corner) return std::nullopt;
        lux += double(w[k]) * *corner;
      }
      return lux;
    }
    from = at + 4.f * rays.epsilon() * down;
  }
  return std::nullopt;
}

float storey_floor(const std::vector<PlanSection>& sections, const Vec3& p) {
  float floor = sections.empty() ? p.y : sections.front().floor;
  for (const PlanSection& s : sections)
    if (s.floor <= p.y) floor = std::max(floor, s.floor);
  return floor;
}

} // namespace hilight
