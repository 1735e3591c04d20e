#pragma once
// The analytic cases after CIE 171:2006 (docs/rendering-model.md,
// "Validation against physics"), as one helper every renderer's tests run:
// each case builds its scene from the case's published description, renders
// it with the renderer and settings it is given, and compares with a
// reference derived here from the geometry (closed forms, or a fine
// numerical integral written out below), never copied from CIE's tables.
// Renders give outgoing radiance L = ρ/π · E, so E = π L / ρ.
//
// Each case returns what it measured; the tests decide what a renderer must
// pass (tests/test_cie171.cpp for Embree, tests/test_cie171_renderers.cpp for
// POV-Ray and ism-vulkan).
#include "hilight/fixtures/scene_builders.hpp"
#include "support.hpp"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace cie171 {

using hilight::kPi;
using hilight::Light;
using hilight::Lighting;
using hilight::Rgb;
using hilight::Scene;
using hilight::Vec3;

/// What a case measured against its reference.
struct Result {
  double worst = 0.0;    ///< the largest |measured / reference − 1| over the case's points
  double overall = 0.0;  ///< the case's overall figure, signed: mean (or total) measured / reference − 1
  size_t points = 0;     ///< how many points the per-point figure covers
  std::string detail;    ///< the figures, for INFO/WARN
};

/// A renderer and its settings ("key=value"), and the longest edge of the
/// case's mesh as a multiple of the case's own (1: Embree's; a slower
/// renderer runs coarser meshes, with fewer points).
struct Setup {
  std::string renderer = "embree";
  std::vector<std::string> settings;
  float coarseness = 1.f;
};

/// Irradiance at every vertex from a render of `lights` (E = π L / ρ, red channel).
inline std::vector<double> irradiance(hilight::Renderer& renderer, const Scene& scene, const Lighting& lights) {
  const hilight::SurfacePoints points = hilight::SurfacePoints::from_vertices(scene);
  const std::vector<Rgb> radiance = renderer.illuminate(points, lights);
  std::vector<double> out(points.size());
  for (size_t i = 0; i < points.size(); ++i) out[i] = kPi * double(radiance[i].r) / double(points.albedo[i].r);
  return out;
}

/// The closest vertex to `p` whose normal is `n`.
inline size_t vertex_at(const Scene& scene, const Vec3& p, const Vec3& n) {
  size_t best = 0;
  float best_d = 1e30f;
  for (size_t v = 0; v < scene.positions.size(); ++v) {
    if (glm::dot(scene.normals[v], n) < 0.99f) continue;
    const float d = glm::length(scene.positions[v] - p);
    if (d < best_d) best_d = d, best = v;
  }
  return best;
}

/// Area-weighted mean of a per-vertex field over the surface (each triangle
/// its corners' mean), and the surface's area.
inline double area_mean(const Scene& scene, const std::vector<double>& field, double* area_out = nullptr) {
  double sum = 0.0, area = 0.0;
  for (const auto& t : scene.triangles) {
    const double a = 0.5 * double(glm::length(glm::cross(scene.positions[t[1]] - scene.positions[t[0]],
                                                         scene.positions[t[2]] - scene.positions[t[0]])));
    sum += a * (field[t[0]] + field[t[1]] + field[t[2]]) / 3.0;
    area += a;
  }
  if (area_out) *area_out = area;
  return sum / area;
}

/// Whether the segment a→b crosses the horizontal square |x−cx|,|z−cz| ≤ h at height y.
inline bool crosses_square(const Vec3& a, const Vec3& b, float y, float cx, float cz, float h) {
  if ((a.y - y) * (b.y - y) >= 0.f) return false;
  const float t = (y - a.y) / (b.y - a.y);
  const Vec3 p = a + t * (b - a);
  return std::abs(p.x - cx) <= h && std::abs(p.z - cz) <= h;
}

/// The configuration factor from a point on the floor (normal up) to the
/// parallel rectangle [0, x] × [0, y] a height c above it, one corner over the
/// point: integrating cos²/(π r²) over the rectangle in closed form gives
/// 1/2π [X/√(1+X²) atan(Y/√(1+X²)) + Y/√(1+Y²) atan(X/√(1+Y²))], X = x/c, Y = y/c.
/// Signed by the quadrant, so rectangles anywhere add up by inclusion-exclusion.
inline double corner_factor(double x, double y, double c) {
  const double X = std::abs(x) / c, Y = std::abs(y) / c;
  const double ax = std::sqrt(1 + X * X), ay = std::sqrt(1 + Y * Y);
  const double f = (X / ax * std::atan(Y / ax) + Y / ay * std::atan(X / ay)) / (2 * kPi);
  return (x < 0) != (y < 0) ? -f : f;
}

/// Irradiance on the floor at (px, pz) from a Lambertian rectangle [x0,x1] ×
/// [z0,z1] at height c facing down, intensity I0 along its normal: E = π L F
/// with radiance L = I0 / area.
inline double rectangle_irradiance(double px, double pz, double x0, double x1, double z0, double z1, double c, double i0) {
  const double F = corner_factor(x1 - px, z1 - pz, c) - corner_factor(x0 - px, z1 - pz, c) -
                   corner_factor(x1 - px, z0 - pz, c) + corner_factor(x0 - px, z0 - pz, c);
  return kPi * i0 / ((x1 - x0) * (z1 - z0)) * F;
}

/// Per-point deviations of `measured` from `reference` over `points`
/// (indices), and the deviation of their sums.
inline Result compare(const std::vector<double>& measured, const std::vector<double>& reference, const std::vector<size_t>& points) {
  Result r;
  double sum = 0.0, sum_ref = 0.0;
  for (size_t v : points) {
    r.worst = std::max(r.worst, std::abs(measured[v] / reference[v] - 1.0));
    sum += measured[v], sum_ref += reference[v];
  }
  r.overall = sum / sum_ref - 1.0;
  r.points = points.size();
  return r;
}

/// 5.2: a point source (20 W/sr) 1.5 m over a plane of ρ 0.5 (8 m square):
/// E = I cosθ / d² at every vertex (nothing to bounce to).
inline Result point_over_plane(const Setup& s) {
  const float height = 1.5f, intensity = 20.f;
  auto scene = test::finish(hilight::builders::plane(4.f, Rgb(0.5f)), 0.25f * s.coarseness);
  auto renderer = test::make_renderer(s.renderer, scene, s.settings);
  const Lighting lights{Light::point({0.f, height, 0.f}, Rgb(intensity))};
  const auto e = irradiance(*renderer, *scene, lights);
  std::vector<double> reference(e.size());
  std::vector<size_t> all(e.size());
  for (size_t v = 0; v < e.size(); ++v) {
    const Vec3 d = lights[0].position - scene->positions[v];
    const double dist = glm::length(d);
    reference[v] = intensity * double(height) / (dist * dist * dist);
    all[v] = v;
  }
  Result r = compare(e, reference, all);
  std::ostringstream out;
  out << s.renderer << " 5.2: " << r.points << " vertices, worst " << 100 * r.worst << "%, total " << 100 * r.overall << "%";
  r.detail = out.str();
  return r;
}

/// 5.3: a Lambertian 0.6 m square source (I0 = 10 W/sr along its normal)
/// facing down at `height` × its side over a plane of ρ 0.5 (3 m square):
/// E = π (I0/A) F from the closed-form configuration factor at every vertex.
inline Result area_source(const Setup& s, float height) {
  const float side = 0.6f, c = height * side, intensity = 10.f;
  auto scene = test::finish(hilight::builders::plane(1.5f, Rgb(0.5f)), 0.1f * s.coarseness);
  auto renderer = test::make_renderer(s.renderer, scene, s.settings);
  const Lighting lights{Light::area(hilight::LightType::Rectangle, {0.f, c, 0.f}, {0.f, -1.f, 0.f}, {1.f, 0.f, 0.f},
                                    {side, side}, Rgb(intensity))};
  const auto e = irradiance(*renderer, *scene, lights);
  std::vector<double> reference(e.size());
  std::vector<size_t> all(e.size());
  const double h = 0.5 * side;
  for (size_t v = 0; v < e.size(); ++v) {
    const Vec3 p = scene->positions[v];
    reference[v] = rectangle_irradiance(p.x, p.z, -h, h, -h, h, c, intensity);
    all[v] = v;
  }
  Result r = compare(e, reference, all);
  std::ostringstream out;
  out << s.renderer << " 5.3 at " << height << "x the side: " << r.points << " vertices, worst " << 100 * r.worst
      << "%, total " << 100 * r.overall << "%";
  r.detail = out.str();
  return r;
}

/// 5.4: a closed 4 m box of ρ 0.001 (black) with a 10 W/sr point source off
/// centre receives the source's whole flux 4πI; `overall` is the received
/// flux's deviation (no per-point figure).
inline Result black_box_flux(const Setup& s) {
  const float intensity = 10.f;
  auto scene = test::finish(hilight::builders::box_room({4.f, 4.f, 4.f}, Rgb(0.001f)), 0.1f * s.coarseness);
  auto renderer = test::make_renderer(s.renderer, scene, s.settings);
  // Off centre, so the faces receive unequal shares.
  const auto e = irradiance(*renderer, *scene, {Light::point({1.3f, 2.6f, 1.9f}, Rgb(intensity))});
  double area = 0.0;
  const double flux = area_mean(*scene, e, &area) * area, expected = 4.0 * kPi * intensity;
  Result r;
  r.overall = flux / expected - 1.0;
  std::ostringstream out;
  out << s.renderer << " 5.4: " << scene->positions.size() << " vertices receive " << flux << " W of " << expected << " W ("
      << 100 * r.overall << "%)";
  r.detail = out.str();
  return r;
}

/// 5.6 (`obstructed` false) and 5.7 (true): a 2 m square floor (ρ 0.5) lit by
/// a downward source 1 m above its centre (a spot whose 80° cone covers the
/// floor: its corners are 55° off the axis, and nothing above it is lit). A
/// dark (ρ 0.01) 0.8 m receiver 2 m up faces the floor and gets reflected
/// light only:
///   E(P) = ∫ L(y) cosθ_y cosθ_P / r² dA,  L(y) = ρ/π · I cosθ / d²,
/// integrated over the floor on a 400² grid here. With the obstruction (5.7),
/// a dark square 1.5 m up hides part of the floor from the receiver. Three
/// receiver points (centre, off centre, a corner's way).
inline Result floor_reflection(const Setup& s, bool obstructed) {
  const float rho = 0.5f, intensity = 10.f;
  const Vec3 source{0.f, 1.f, 0.f};
  Scene raw = hilight::builders::plane(1.f, Rgb(rho));
  const float r = 0.4f, y_r = 2.f, y_o = 1.5f, o_h = 0.25f, o_x = 0.45f;
  hilight::builders::add_quad(raw, {-r, y_r, -r}, {r, y_r, -r}, {r, y_r, r}, {-r, y_r, r}, Rgb(0.01f), "receiver");  // faces down
  if (obstructed)
    hilight::builders::add_quad(raw, {o_x - o_h, y_o, -o_h}, {o_x + o_h, y_o, -o_h}, {o_x + o_h, y_o, o_h}, {o_x - o_h, y_o, o_h},
                                Rgb(0.01f), "obstruction");
  auto scene = test::finish(std::move(raw), 0.1f * s.coarseness);
  auto renderer = test::make_renderer(s.renderer, scene, s.settings);
  const auto e = irradiance(*renderer, *scene, {Light::spot(source, {0.f, -1.f, 0.f}, 80.f, Rgb(intensity))});
  const int n = 400;
  const double cell = 2.0 / n;
  Result result;
  std::ostringstream out;
  out << s.renderer << (obstructed ? " 5.7:" : " 5.6:");
  double sum = 0.0, sum_ref = 0.0;
  for (const Vec3 at : {Vec3(0.f, y_r, 0.f), Vec3(0.3f, y_r, 0.f), Vec3(-0.3f, y_r, 0.2f)}) {
    const size_t v = vertex_at(*scene, at, {0.f, -1.f, 0.f});
    const Vec3 p = scene->positions[v];
    double expected = 0.0;
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < n; ++k) {
        const Vec3 y{float(-1.0 + (i + 0.5) * cell), 0.f, float(-1.0 + (k + 0.5) * cell)};
        if (obstructed && crosses_square(y, p, y_o, o_x, 0.f, o_h)) continue;
        const Vec3 from_source = y - source, to_p = p - y;
        const double d2 = glm::dot(from_source, from_source), r2 = glm::dot(to_p, to_p);
        const double radiance = rho / kPi * intensity * double(-from_source.y) / (d2 * std::sqrt(d2));
        expected += radiance * double(to_p.y) * double(to_p.y) / (r2 * r2) * cell * cell;
      }
    result.worst = std::max(result.worst, std::abs(e[v] / expected - 1.0));
    sum += e[v], sum_ref += expected;
    ++result.points;
    out << " at " << p.x << "," << p.z << " " << e[v] << " against " << expected << " (" << 100 * (e[v] / expected - 1.0) << "%);";
  }
  result.overall = sum / sum_ref - 1.0;
  out << " worst " << 100 * result.worst << "%";
  result.detail = out.str();
  return result;
}

/// 5.8: a closed 4 m cube of reflectance `rho`, an isotropic source of
/// 10 W/sr at its centre. Each reflection passes on ρ of the flux, so the
/// area-weighted mean indirect irradiance is ρΦ/(S(1−ρ)) exactly (Φ = 4πI,
/// S = 96 m²): `overall` is its deviation (the indirect is the render with
/// `s.settings` less one with bounces=0). At a wall's centre the direct light
/// is I/d² (d = 2 m): `worst` is the six centres' largest deviation from
/// I/d² + the mean indirect (the indirect is highest there, so a few % over).
inline Result cube(const Setup& s, float rho, double* mean_indirect_out = nullptr) {
  const float intensity = 10.f;
  const double flux = 4.0 * kPi * intensity, area = 96.0;
  auto scene = test::finish(hilight::builders::box_room({4.f, 4.f, 4.f}, Rgb(rho)), 0.2f * s.coarseness);
  auto renderer = test::make_renderer(s.renderer, scene, s.settings);
  std::vector<std::string> direct_settings;
  for (const auto& kv : s.settings)
    if (kv.rfind("bounces=", 0) != 0) direct_settings.push_back(kv);
  direct_settings.push_back("bounces=0");
  auto direct = test::make_renderer(s.renderer, scene, direct_settings);
  const Lighting lights{Light::point({2.f, 2.f, 2.f}, Rgb(intensity))};
  const auto e = irradiance(*renderer, *scene, lights), e_dir = irradiance(*direct, *scene, lights);
  std::vector<double> indirect(e.size());
  for (size_t v = 0; v < e.size(); ++v) indirect[v] = e[v] - e_dir[v];
  const double exact = rho * flux / (area * (1.0 - rho)), mean = area_mean(*scene, indirect);
  if (mean_indirect_out) *mean_indirect_out = mean;
  Result r;
  r.overall = exact > 0 ? mean / exact - 1.0 : 0.0;
  std::ostringstream out;
  out << s.renderer << " 5.8 rho " << rho << ": mean indirect " << mean << " against " << exact << " (" << 100 * r.overall
      << "%); wall centres";
  const Vec3 centres[] = {{0, 2, 2}, {4, 2, 2}, {2, 0, 2}, {2, 4, 2}, {2, 2, 0}, {2, 2, 4}};
  for (const Vec3& c : centres) {
    const Vec3 inward = glm::normalize(Vec3(2.f) - c);
    const double at = e[vertex_at(*scene, c, inward)], expected = intensity / 4.0 + exact;
    r.worst = std::max(r.worst, std::abs(at / expected - 1.0));
    out << " " << 100 * (at / expected - 1.0) << "%";
    ++r.points;
  }
  r.detail = out.str();
  return r;
}

} // namespace cie171
