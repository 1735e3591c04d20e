// Validation against physics, after the analytic cases of CIE 171:2006
// (docs/rendering-model.md, "Validation against physics"). The scenes are
// built from the cases' published descriptions and every reference value is
// derived here from the geometry (closed forms, or a fine numerical integral
// written out below), not copied from CIE's tables. Tolerances are those of
// lighting practice: 5% per point, 10% overall. Renders give outgoing
// radiance L = ρ/π · E, so E = π L / ρ.
#include "hilight/scene_builders.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <cmath>

using namespace hilight;

namespace {

/// Irradiance at every vertex from a render of `lights` (E = π L / ρ, red channel).
std::vector<double> irradiance(Renderer& renderer, const Scene& scene, const Lighting& lights) {
  const SurfacePoints points = SurfacePoints::from_vertices(scene);
  const std::vector<Rgb> radiance = renderer.illuminate(points, lights);
  std::vector<double> out(points.size());
  for (size_t i = 0; i < points.size(); ++i) out[i] = kPi * double(radiance[i].r) / double(points.albedo[i].r);
  return out;
}

/// The closest vertex to `p` whose normal is `n`.
size_t vertex_at(const Scene& scene, const Vec3& p, const Vec3& n) {
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
double area_mean(const Scene& scene, const std::vector<double>& field, double* area_out = nullptr) {
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
bool crosses_square(const Vec3& a, const Vec3& b, float y, float cx, float cz, float h) {
  if ((a.y - y) * (b.y - y) >= 0.f) return false;
  const float t = (y - a.y) / (b.y - a.y);
  const Vec3 p = a + t * (b - a);
  return std::abs(p.x - cx) <= h && std::abs(p.z - cz) <= h;
}

} // namespace

TEST_CASE("CIE 171 5.2: a point source over a plane gives I cos(theta) / d^2 at every point, every bounce on",
          "[cie171][renderer][analytic]") {
  const float height = 1.5f, intensity = 20.f;
  auto scene = test::finish(builders::plane(4.f, Rgb(0.5f)), 0.25f);
  auto renderer = test::make_renderer("embree", scene, {"bounces=all"});
  const Lighting lights{Light::point({0.f, height, 0.f}, Rgb(intensity))};
  const auto e = irradiance(*renderer, *scene, lights);
  double worst = 0.0;
  for (size_t v = 0; v < scene->positions.size(); ++v) {
    const Vec3 d = lights[0].position - scene->positions[v];
    const double dist = glm::length(d), expected = intensity * double(height) / (dist * dist * dist);
    worst = std::max(worst, std::abs(e[v] / expected - 1.0));
  }
  INFO("largest deviation " << worst);
  CHECK(worst < 0.01);  // a lone plane has nothing to bounce to: direct light only
}

TEST_CASE("CIE 171 5.4: a closed black box receives exactly the source's flux 4 pi I", "[cie171][renderer][analytic]") {
  const float intensity = 10.f;
  auto scene = test::finish(builders::box_room({4.f, 4.f, 4.f}, Rgb(0.001f)), 0.1f);
  auto renderer = test::make_renderer("embree", scene, {"bounces=all"});
  // Off centre, so the faces receive unequal shares.
  const auto e = irradiance(*renderer, *scene, {Light::point({1.3f, 2.6f, 1.9f}, Rgb(intensity))});
  double area = 0.0;
  const double flux = area_mean(*scene, e, &area) * area, expected = 4.0 * kPi * intensity;
  INFO("received " << flux << " W, emitted " << expected << " W");
  CHECK(flux == Approx(expected).epsilon(0.01));
}

TEST_CASE("CIE 171 5.6 and 5.7: light reflected by a diffuse floor onto a receiver, without and with an obstruction",
          "[cie171][renderer][analytic]") {
  // A 2 m square floor (ρ 0.5) lit by a downward source 1 m above its centre
  // (a spot whose 80° cone covers the floor: the floor's corners are 55° off
  // its axis, and nothing above it is lit). A dark (ρ 0.01) 0.8 m receiver
  // 2 m up faces the floor and gets reflected light only:
  //   E(P) = ∫ L(y) cosθ_y cosθ_P / r² dA,  L(y) = ρ/π · I cosθ / d²,
  // integrated over the floor on a fine grid here. With the obstruction
  // (5.7), a dark square 1.5 m up hides part of the floor from the receiver.
  const float rho = 0.5f, intensity = 10.f;
  const Vec3 source{0.f, 1.f, 0.f};
  for (bool obstructed : {false, true}) {
    Scene raw = builders::plane(1.f, Rgb(rho));
    const float r = 0.4f, y_r = 2.f, y_o = 1.5f, o_h = 0.25f, o_x = 0.45f;
    builders::add_quad(raw, {-r, y_r, -r}, {r, y_r, -r}, {r, y_r, r}, {-r, y_r, r}, Rgb(0.01f), "receiver");  // faces down
    if (obstructed)
      builders::add_quad(raw, {o_x - o_h, y_o, -o_h}, {o_x + o_h, y_o, -o_h}, {o_x + o_h, y_o, o_h}, {o_x - o_h, y_o, o_h},
                         Rgb(0.01f), "obstruction");
    auto scene = test::finish(std::move(raw), 0.1f);
    auto renderer = test::make_renderer("embree", scene, {"bounces=all", "bounce_samples=4096"});
    const auto e = irradiance(*renderer, *scene, {Light::spot(source, {0.f, -1.f, 0.f}, 80.f, Rgb(intensity))});
    const int n = 400;
    const double cell = 2.0 / n;
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
      INFO((obstructed ? "5.7" : "5.6") << " at " << p.x << "," << p.z << ": hilight " << e[v] << ", reference " << expected);
      CHECK(e[v] == Approx(expected).epsilon(0.05));
    }
  }
}

TEST_CASE("CIE 171 5.8: the interreflecting cube, every bounce, for reflectances from 0 to 0.95",
          "[cie171][renderer][analytic][bounce]") {
  // A closed 4 m cube, an isotropic source of 10 W/sr at its centre. Each
  // reflection passes on ρ of the flux, so the area-weighted mean indirect
  // irradiance is ρΦ/(S(1−ρ)) exactly (Φ = 4πI, S = 96 m²). At a wall's
  // centre the direct light is I/d² (d = 2 m).
  const float intensity = 10.f;
  const double flux = 4.0 * kPi * intensity, area = 96.0;
  for (float rho : {0.001f, 0.2f, 0.5f, 0.8f, 0.95f}) {
    auto scene = test::finish(builders::box_room({4.f, 4.f, 4.f}, Rgb(rho)), 0.2f);
    auto renderer = test::make_renderer("embree", scene, {"bounces=all"});
    auto direct = test::make_renderer("embree", scene, {"bounces=0"});
    const Lighting lights{Light::point({2.f, 2.f, 2.f}, Rgb(intensity))};
    const auto e = irradiance(*renderer, *scene, lights), e_dir = irradiance(*direct, *scene, lights);
    std::vector<double> indirect(e.size());
    for (size_t v = 0; v < e.size(); ++v) indirect[v] = e[v] - e_dir[v];
    const double mean_indirect = rho * flux / (area * (1.0 - rho));
    INFO("rho " << rho << ": mean indirect " << area_mean(*scene, indirect) << ", exact " << mean_indirect);
    CHECK(area_mean(*scene, indirect) == Approx(mean_indirect).epsilon(0.05).margin(1e-3));
    const Vec3 centres[] = {{0, 2, 2}, {4, 2, 2}, {2, 0, 2}, {2, 4, 2}, {2, 2, 0}, {2, 2, 4}};
    for (const Vec3& c : centres) {
      const Vec3 inward = glm::normalize(Vec3(2.f) - c);
      const double at = e[vertex_at(*scene, c, inward)], expected = intensity / 4.0 + mean_indirect;
      INFO("wall centre " << c.x << "," << c.y << "," << c.z << ": " << at << " against " << expected);
      CHECK(at == Approx(expected).epsilon(0.05));
    }
  }
}

TEST_CASE("every bounce: --bounces N converges to all, and all is linear in the lights", "[renderer][bounce]") {
  auto scene = test::finish(builders::box_room({4.f, 3.f, 5.f}, Rgb(0.8f, 0.7f, 0.5f)), 0.4f);
  const SurfacePoints points = SurfacePoints::from_vertices(*scene);
  const Lighting a{Light::point({1.f, 2.5f, 1.f}, Rgb(3.f, 2.f, 1.f))}, b{Light::spot({3.f, 2.8f, 4.f}, {0.f, -1.f, 0.f}, 35.f, Rgb(1.f, 2.f, 4.f))};
  Lighting both = a;
  both.push_back(b[0]);
  auto all = test::make_renderer("embree", scene, {"bounces=all"});
  auto mean_red = [&](Renderer& r, const Lighting& l) {
    double s = 0;
    for (const Rgb& c : r.illuminate(points, l)) s += c.r;
    return s / double(points.size());
  };
  const double m_all = mean_red(*all, both);
  double previous = 0.0;
  for (int n : {1, 2, 4, 16, 64}) {
    auto r = test::make_renderer("embree", scene, {"bounces=" + std::to_string(n)});
    const double m = mean_red(*r, both);
    INFO(n << " bounces: " << m << ", all: " << m_all);
    CHECK(m > previous);          // each bounce adds light
    CHECK(m <= m_all * 1.01);     // and never passes every bounce
    previous = m;
  }
  CHECK(previous == Approx(m_all).epsilon(0.01));  // 0.8^64: converged
  // Superposition: render(A + B) = render(A) + render(B), and Σ I_j φ_j.
  const auto ra = all->illuminate(points, a), rb = all->illuminate(points, b), rab = all->illuminate(points, both);
  const auto phi = all->unit_responses(points, both);
  double worst = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    const Rgb sum = ra[i] + rb[i], from_phi = both[0].intensity * phi[i] + both[1].intensity * phi[points.size() + i];
    for (int c = 0; c < 3; ++c) {
      const double scale = std::max(1e-6, double(rab[i][c]));
      worst = std::max({worst, std::abs(double(sum[c] - rab[i][c])) / scale, std::abs(double(from_phi[c] - rab[i][c])) / scale});
    }
  }
  CHECK(worst < 1e-4);
}
