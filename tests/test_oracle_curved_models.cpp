// The brute-force oracle (issue 11): per-vertex direct light on real curved
// models, computed here by a plain loop over every triangle in double
// precision, sharing no code with any renderer, and every renderer held to it.
// It implements docs/rendering-model.md "Where a point is shaded" on its own:
// - a vertex whose only nearby triangles are its own smooth fan (they touch it
//   with the same normal) is shaded at the vertex itself; its shadow ray leaves
//   the vertex and ignores the first ε of its path, so the fan's flat facets
//   never shadow a light the smooth normal faces (no terminator speckles),
//   and a ray between its tangent plane and the fan's facet under it (the
//   wedge) is blocked: it would pass through the smooth surface;
// - a vertex where other surfaces meet it (hard creases, contacts) is shaded a
//   hair inside its triangle and lifted ε on the light's side.
#include "hilight/fixtures/real_model_scenes.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "hilight/ray_scene.hpp"
#include "random_lights.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

using namespace hilight;

namespace {

using D3 = glm::dvec3;

double luminance(const Rgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

struct Triangle {
  D3 a, b, c;
  D3 lo, hi;        ///< bounding box
  D3 face_normal;   ///< unit, from the winding
  uint32_t v[3];
};

std::vector<Triangle> triangles_of(const Scene& scene) {
  std::vector<Triangle> out;
  for (const auto& t : scene.triangles) {
    Triangle tri;
    tri.a = D3(scene.positions[t[0]]); tri.b = D3(scene.positions[t[1]]); tri.c = D3(scene.positions[t[2]]);
    tri.lo = glm::min(tri.a, glm::min(tri.b, tri.c));
    tri.hi = glm::max(tri.a, glm::max(tri.b, tri.c));
    D3 n = glm::cross(tri.b - tri.a, tri.c - tri.a);
    double len = glm::length(n);
    tri.face_normal = len > 0 ? n / len : D3(0);
    tri.v[0] = t[0]; tri.v[1] = t[1]; tri.v[2] = t[2];
    out.push_back(tri);
  }
  return out;
}

/// Distance from p to the triangle (projection inside, else the nearest edge).
double distance_to(const Triangle& t, const D3& p) {
  auto segment = [&](const D3& a, const D3& b) {
    D3 ab = b - a;
    double s = glm::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-300), 0.0, 1.0);
    return glm::length(p - (a + s * ab));
  };
  const D3& n = t.face_normal;
  D3 q = p - glm::dot(p - t.a, n) * n;
  D3 c0 = glm::cross(t.b - t.a, q - t.a), c1 = glm::cross(t.c - t.b, q - t.b), c2 = glm::cross(t.a - t.c, q - t.c);
  if (glm::dot(c0, n) >= 0 && glm::dot(c1, n) >= 0 && glm::dot(c2, n) >= 0) return std::abs(glm::dot(p - t.a, n));
  return std::min({segment(t.a, t.b), segment(t.b, t.c), segment(t.c, t.a)});
}

/// Ray parameter of the hit with the triangle, or -1 (Möller–Trumbore).
double hit_distance(const Triangle& t, const D3& o, const D3& d) {
  D3 e1 = t.b - t.a, e2 = t.c - t.a, pv = glm::cross(d, e2);
  double det = glm::dot(e1, pv);
  if (std::abs(det) < 1e-300) return -1;
  D3 tv = o - t.a;
  double u = glm::dot(tv, pv) / det;
  if (u < 0 || u > 1) return -1;
  D3 qv = glm::cross(tv, e1);
  double v = glm::dot(d, qv) / det;
  if (v < 0 || u + v > 1) return -1;
  return glm::dot(e2, qv) / det;
}

struct Oracle {
  const Scene& scene;
  std::vector<Triangle> tris;
  double eps;

  explicit Oracle(const Scene& s) : scene(s), tris(triangles_of(s)) {
    double largest = 0;
    for (const auto& p : s.positions) largest = std::max({largest, double(std::abs(p.x)), double(std::abs(p.y)), double(std::abs(p.z))});
    eps = std::max(1e-5 * double(s.diagonal()), 1e-6 * largest);  // relative only (rendering-model.md, Tolerances)
  }

  bool blocked(const D3& o, const D3& dir, double from, double to) const {
    for (const auto& t : tris) {
      double h = hit_distance(t, o, dir);
      if (h > from && h < to) return true;
    }
    return false;
  }

  /// True when every triangle within 2ε of vertex v is in its smooth fan.
  bool smooth(uint32_t v) const {
    const D3 p(scene.positions[v]), n(scene.normals[v]);
    const double near = 2 * eps;
    for (const auto& t : tris) {
      if (glm::any(glm::lessThan(p + near, t.lo)) || glm::any(glm::greaterThan(p - near, t.hi))) continue;
      if (distance_to(t, p) > near) continue;
      bool own = false;
      for (uint32_t w : t.v)
        own |= glm::length(D3(scene.positions[w]) - p) <= 0.1 * eps && glm::dot(D3(scene.normals[w]), n) >= 0.999;
      if (!own) return false;
    }
    return true;
  }

  /// The triangles within 2ε of p: a smooth vertex's own fan.
  std::vector<const Triangle*> fan(const D3& p) const {
    std::vector<const Triangle*> out;
    for (const auto& t : tris)
      if (!glm::any(glm::lessThan(p + 2 * eps, t.lo)) && !glm::any(glm::greaterThan(p - 2 * eps, t.hi)) && distance_to(t, p) <= 2 * eps)
        out.push_back(&t);
    return out;
  }

  /// The wedge: w on one side of the tangent plane (normal n) and on the
  /// other of the fan's facet under w — the one that holds w moved along n
  /// into its plane (between its edges at the vertex). Facets tilted under
  /// 10⁻⁴ or nearly edge-on (|f·n| < 10⁻³) have none.
  bool in_wedge(const std::vector<const Triangle*>& own, const D3& p, const D3& n, const D3& w) const {
    for (const Triangle* t : own) {
      const D3& f = t->face_normal;
      const double facing = glm::dot(f, n);
      if (std::abs(facing) < 1e-3 || glm::length(glm::cross(f, n)) < 1e-4) continue;
      const D3 x = w - glm::dot(f, w) / facing * n;
      const D3 c[3] = {t->a, t->b, t->c};
      int corner = -1;
      for (int k = 0; k < 3; ++k)
        if (glm::length(c[k] - p) <= 0.1 * eps) corner = k;
      if (corner < 0) continue;  // (the oracle's points are vertices)
      const D3 e1 = c[(corner + 1) % 3] - p, e2 = c[(corner + 2) % 3] - p, wound = glm::cross(e1, e2);
      const bool under = glm::dot(glm::cross(e1, x), wound) >= 0 && glm::dot(glm::cross(x, e2), wound) >= 0;
      if (under && glm::dot(n, w) * glm::dot(f, w) * facing < 0) return true;
    }
    return false;
  }

  /// Where a crease or contact vertex is shaded: a fixed step into the face
  /// of the nearest triangle that agrees best with its normal, away from the
  /// crease (the mean direction over the face's wedges at the point) or, where
  /// the face goes on all around, away from the surfaces touching it (their
  /// normals laid into the face's plane); halved until still on that face.
  D3 nudged(uint32_t v) const {
    const D3 p(scene.positions[v]), n(scene.normals[v]);
    double best = std::numeric_limits<double>::max(), best_alignment = -2;
    const Triangle* chosen = nullptr;
    for (const auto& t : tris) {
      if (glm::any(glm::lessThan(p + 4 * eps, t.lo)) || glm::any(glm::greaterThan(p - 4 * eps, t.hi))) continue;
      double d = distance_to(t, p), alignment = glm::dot(t.face_normal, n);
      // Ties (as close, as well aligned) go to the larger normal, x first:
      // the same choice on any cut of the same faces.
      auto larger = [&](const D3& a, const D3& b) {
        for (int k = 0; k < 3; ++k)
          if (std::abs(a[k] - b[k]) > 1e-4) return a[k] > b[k];
        return false;
      };
      if (d < best - eps ||
          (std::abs(d - best) <= eps && (alignment > best_alignment + 1e-4 ||
                                         (alignment >= best_alignment - 1e-4 && larger(t.face_normal, chosen->face_normal))))) {
        best = std::min(best, d);
        best_alignment = alignment;
        chosen = &t;
      }
    }
    if (!chosen) return p;
    const D3 plane = chosen->face_normal, on = p - glm::dot(p - chosen->a, plane) * plane;
    const double touch = 0.5 * eps, full_step = std::max(4 * eps, 3e-4 * double(scene.diagonal()));
    D3 fan(0), away(0);
    std::vector<std::pair<D3, double>> planes;  // other surfaces counted once a plane
    for (const auto& t : tris) {
      if (glm::any(glm::lessThan(on + full_step, t.lo)) || glm::any(glm::greaterThan(on - full_step, t.hi))) continue;
      const double d = distance_to(t, on), facing = glm::dot(t.face_normal, plane);
      if (d > full_step) continue;
      if (facing < 0.9999) {
        const double offset = glm::dot(t.face_normal, t.a);
        bool seen = facing <= -0.9999;
        for (const auto& [normal, o] : planes) seen |= glm::length(normal - t.face_normal) < 1e-4 && std::abs(o - offset) <= touch;
        if (!seen) planes.emplace_back(t.face_normal, offset), away += t.face_normal - facing * plane;
        continue;
      }
      if (d > touch) continue;
      const D3 corners[3] = {t.a, t.b, t.c};
      bool at_corner = false;
      for (int k = 0; k < 3 && !at_corner; ++k)
        if (glm::length(corners[k] - on) <= touch) {
          const D3 ub = glm::normalize(corners[(k + 1) % 3] - on), uc = glm::normalize(corners[(k + 2) % 3] - on);
          if (glm::length(ub + uc) > 0) fan += glm::length(ub - uc) * glm::normalize(ub + uc);  // 2 sin(α/2) on the bisector
          at_corner = true;
        }
      for (int k = 0; k < 3 && !at_corner; ++k) {
        const D3 a = corners[k], b = corners[(k + 1) % 3], c = corners[(k + 2) % 3], ab = b - a;
        const double s = glm::dot(on - a, ab) / glm::dot(ab, ab);
        if (s < 0 || s > 1 || glm::length(a + s * ab - on) > touch) continue;
        const D3 inward = (c - a) - glm::dot(c - a, glm::normalize(ab)) * glm::normalize(ab);
        fan += 2.0 * glm::normalize(inward);
        break;
      }
    }
    const D3 direction = glm::length(fan) > 0.05 ? fan : away;
    if (glm::length(direction) <= 1e-3) return on;  // an open face, nothing near to step away from
    for (double step = full_step; step > touch; step *= 0.5) {
      const D3 q = on + step * glm::normalize(direction);
      for (const auto& t : tris)
        if (glm::dot(t.face_normal, plane) >= 0.9999 && distance_to(t, q) <= 2 * touch) return q;
    }
    D3 to_centroid = (chosen->a + chosen->b + chosen->c) / 3.0 - p;
    double distance = glm::length(to_centroid);
    double step = std::min(std::max(0.01 * distance, full_step), 0.1 * distance);
    return p + to_centroid * (step / distance);
  }

  /// L at every vertex from point lights, bounces 0.
  std::vector<Rgb> illuminate(const Lighting& lights) const {
    const std::vector<Rgb> albedo = scene.vertex_albedo();
    std::vector<Rgb> out(scene.positions.size(), Rgb(0.f));
    for (uint32_t v = 0; v < out.size(); ++v) {
      const D3 n(scene.normals[v]);
      const bool is_smooth = smooth(v);
      const D3 p = is_smooth ? D3(scene.positions[v]) : nudged(v);
      const std::vector<const Triangle*> own = is_smooth ? fan(p) : std::vector<const Triangle*>();
      glm::dvec3 e(0);
      for (const Light& light : lights) {
        D3 d = D3(light.position) - p;
        double dist = glm::length(d);
        D3 w = d / dist;
        double cos_n = glm::dot(n, w);
        if (cos_n == 0) continue;
        bool dark = is_smooth ? in_wedge(own, p, n, w) || blocked(p, w, eps, dist - eps)
                              : blocked(p + (cos_n > 0 ? n : -n) * eps, w, 1e-9, dist - 2 * eps);
        if (!dark) e += glm::dvec3(light.intensity) * std::abs(cos_n) / (dist * dist);
      }
      out[v] = Rgb(D3(albedo[v]) / kPi * e);
    }
    return out;
  }
};

struct Agreement {
  double dbar = 0, off_share = 0;
};

/// D̄ and the share of vertices more than 5% off (with a floor of 0.1% of the
/// mean, so a vertex that is dark in both does not count).
Agreement agreement(const std::vector<Rgb>& a, const std::vector<Rgb>& oracle) {
  double mean = 0;
  for (const auto& o : oracle) mean += luminance(o) / double(oracle.size());
  size_t off = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    double x = luminance(a[i]), o = luminance(oracle[i]);
    off += std::abs(x - o) > 0.05 * o + 1e-3 * mean;
  }
  return {test::dbar(a, oracle), double(off) / double(a.size())};
}

struct OracleCase {
  std::shared_ptr<const Scene> scene;
  Lighting lights;
  std::vector<Rgb> oracle;
};

/// The Wuson and the spider (smooth-shaded, self-touching) on a floor before a
/// wall, three seeded random lights around them; the oracle computed once.
const OracleCase& curved_case() {
  static const OracleCase c = [] {
    OracleCase out;
    out.scene = std::make_shared<const Scene>(finish_scene(builders::curved_models_on_floor(), {}));
    RayScene rays(*out.scene);
    std::mt19937_64 rng(1101);
    out.lights = test::random_free_lights(rays, rng, 3, 0.05f);
    out.oracle = Oracle(*out.scene).illuminate(out.lights);
    return out;
  }();
  return c;
}

Agreement renderer_against_oracle(const std::string& name) {
  const OracleCase& c = curved_case();
  auto renderer = test::make_renderer(name, c.scene, {"bounces=0"});
  auto result = renderer->illuminate(SurfacePoints::from_vertices(*c.scene), c.lights);
  Agreement a = agreement(result, c.oracle);
  std::printf("oracle on curved models (%zu vertices, %zu lights): %s D-bar %.3f%%, %.2f%% of vertices > 5%% off\n",
              c.scene->positions.size(), c.lights.size(), name.c_str(), 100 * a.dbar, 100 * a.off_share);
  return a;
}

} // namespace

TEST_CASE("oracle: Embree's direct light on real curved models matches a brute-force loop over all triangles",
          "[oracle][renderer]") {
  Agreement a = renderer_against_oracle("embree");
  CHECK(a.dbar < 0.005);
  CHECK(a.off_share < 0.005);
}

TEST_CASE("oracle: POV-Ray's direct light on real curved models matches the brute-force loop", "[oracle][povray]") {
  if (test::skip_without_renderer("povray")) return;
  // Goal 1% (issue 11); measured 1.8% (2.1% before the wedge), most of it at
  // three vertices under a doubled sheet of the Wuson that POV-Ray's shadow
  // tolerance ignores (docs/povray.md).
  CHECK(renderer_against_oracle("povray").dbar < 0.025);
}

TEST_CASE("oracle: ism-vulkan's direct light on real curved models matches the brute-force loop", "[oracle][ism]") {
  if (test::skip_without_renderer("ism-vulkan")) return;
  // Issue 11's tolerance; measured 1.5% on lavapipe (512² ID maps, a 4x4
  // texel window of candidates; 256² and 2x2 gave 6.3%; 1.9% before the
  // wedge).
  CHECK(renderer_against_oracle("ism-vulkan").dbar < 0.02);
}

TEST_CASE("oracle: the loop itself gives the analytic answer on a plane, and most curved-model vertices are lit",
          "[oracle]") {
  auto plane = test::finish(builders::plane(6.f, Rgb(0.5f)), 0.5f);
  Lighting light{Light::point({0.4f, 1.7f, -0.3f}, Rgb(3.f))};
  auto values = Oracle(*plane).illuminate(light);
  double worst = 0;
  for (size_t v = 0; v < values.size(); ++v) {
    DVec3 d = DVec3(light[0].position) - DVec3(plane->positions[v]);
    double expected = 0.5 / kPi * 3.0 * std::abs(glm::dot(DVec3(plane->normals[v]), glm::normalize(d))) / glm::dot(d, d);
    worst = std::max(worst, std::abs(values[v].r - expected) / expected);
  }
  CHECK(worst < 1e-4);
  const OracleCase& c = curved_case();
  double lit = 0;
  for (const auto& o : c.oracle) lit += luminance(o) > 0;
  CHECK(lit > 0.5 * double(c.oracle.size()));
}

TEST_CASE("oracle: POV-Ray and Embree give one answer at the curved models' terminators (issue 32)", "[oracle][povray][cross]") {
  if (test::skip_without_renderer("povray")) return;
  // Issue 32 measured D̄ 8.8% between them, 294 of 5,297 lit vertices more
  // than 20% apart, at the terminators and shadow edges. A vertex is lit when
  // either renderer gives it more than 0.1% of the mean. Measured now (the
  // oracle's three lights): D̄ 1.8%, 21 of 5,339 apart; 2.1% and 62 of 5,504
  // while a smooth vertex's wedge let a light through in one renderer and
  // not the other (docs/rendering-model.md, "The oracle").
  const OracleCase& c = curved_case();
  const SurfacePoints points = SurfacePoints::from_vertices(*c.scene);
  const auto embree = test::make_renderer("embree", c.scene, {"bounces=0"})->illuminate(points, c.lights);
  const auto pov = test::make_renderer("povray", c.scene, {"bounces=0"})->illuminate(points, c.lights);
  double mean = 0;
  for (const auto& e : embree) mean += luminance(e) / double(embree.size());
  size_t lit = 0, apart = 0;
  for (size_t i = 0; i < embree.size(); ++i) {
    const double a = luminance(embree[i]), b = luminance(pov[i]);
    if (std::max(a, b) <= 1e-3 * mean) continue;
    ++lit;
    apart += std::abs(a - b) > 0.2 * std::max(a, b);
  }
  const double d = test::dbar(pov, embree);
  std::printf("curved models, direct light: POV-Ray against Embree D-bar %.3f%%, %zu of %zu lit vertices > 20%% apart\n", 100 * d,
              apart, lit);
  CHECK(d < 0.022);
  CHECK(double(apart) < 0.008 * double(lit));
}
