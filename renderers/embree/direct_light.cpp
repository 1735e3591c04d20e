#include "direct_light.hpp"

namespace hilight::embree {

namespace {

constexpr int kDiskSides = 48;

std::shared_ptr<const AreaSource> prepare_area(const Light& light) {
  auto a = std::make_shared<AreaSource>();
  a->type = light.type;
  a->frame = AreaFrame::of(light);
  const AreaFrame& f = a->frame;
  if (light.type == LightType::Rectangle) {
    a->outline = {f.centre - f.half_u - f.half_v, f.centre + f.half_u - f.half_v, f.centre + f.half_u + f.half_v,
                  f.centre - f.half_u + f.half_v};
    a->area = light.size[0] * light.size[1];
  } else if (light.type == LightType::Disk) {
    // A polygon of the disk's own area: its form factor is the disk's to ~0.1%.
    const double k = 2.0 * kPi / kDiskSides, grow = std::sqrt(k / std::sin(k));
    for (int i = 0; i < kDiskSides; ++i)
      a->outline.push_back(f.centre + float(grow * std::cos(k * i)) * f.half_u + float(grow * std::sin(k * i)) * f.half_v);
    a->area = float(kPi / 4.0) * light.size[0] * light.size[0];
  } else {
    a->area = light.size[0];
  }
  a->samples = area_element_centres(light, light.type == LightType::Line ? kAreaSamples / 2 : kAreaSamples);
  if (light.profile && light.profile->peak() > 0) {
    a->profiled = &light;
    a->profile_frame = LuminaireFrame::of(light);
    a->lambert_part = luminaire_factor(light, a->profile_frame, a->frame.normal);
  }
  return a;
}

/// The part of a polygon (vertices relative to the point) on the positive
/// side of the plane through the point with normal `side` (Sutherland–Hodgman).
std::vector<glm::dvec3> clip_to_side(const std::vector<glm::dvec3>& poly, const glm::dvec3& side) {
  std::vector<glm::dvec3> out;
  for (size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec3 &a = poly[i], &b = poly[(i + 1) % poly.size()];
    const double da = glm::dot(a, side), db = glm::dot(b, side);
    if (da > 0) out.push_back(a);
    if ((da > 0) != (db > 0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

/// ∫ cos θ_r cos θ_e / r² dA over a polygon of unit radiance seen from the
/// origin with receiver normal n: Lambert's edge sum, ½ Σ β_i (n · γ_i).
double polygon_integral(const std::vector<glm::dvec3>& q, const glm::dvec3& n) {
  double sum = 0;
  for (size_t i = 0; i < q.size(); ++i) {
    const glm::dvec3 &a = q[i], &b = q[(i + 1) % q.size()];
    const glm::dvec3 c = glm::cross(a, b);
    const double len = glm::length(c);
    if (!(len > 0)) continue;
    sum += std::atan2(len, glm::dot(a, b)) * glm::dot(n, c) / len;
  }
  return 0.5 * std::abs(sum);
}

/// A Lambertian line of unit intensity along its normal, seen from the
/// origin: ∫ (1/L) cos θ_e cos θ_r / r² dl over its part on the side `side`,
/// in closed form. With X(t) = D + t u, σ = t + D·u and h the distance to
/// the line's axis, cos θ_e r = −m·D (constant: m ⊥ u) and cos θ_r r =
/// a + b σ, so the integrand is −m·D (a + b σ)/(σ² + h²)².
double line_integral(const AreaFrame& f, double length, const glm::dvec3& D, const glm::dvec3& n,
                     const glm::dvec3& side) {
  const glm::dvec3 m(f.normal);
  const double ce = -glm::dot(m, D);
  if (!(ce > 0)) return 0.0;
  const double half = 0.5 * length;
  const glm::dvec3 u = glm::normalize(glm::dvec3(f.half_u));
  double t0 = -half, t1 = half;
  // The side: side·D + t side·u > 0.
  const double s0 = glm::dot(side, D), s1 = glm::dot(side, u);
  if (s1 == 0) {
    if (!(s0 > 0)) return 0.0;
  } else {
    const double t_cross = -s0 / s1;
    if (s1 > 0) t0 = std::max(t0, t_cross);
    else t1 = std::min(t1, t_cross);
  }
  if (!(t1 > t0)) return 0.0;
  const double du = glm::dot(D, u), h2 = glm::dot(D, D) - du * du;
  if (!(h2 > 1e-24)) return 0.0;
  const double h = std::sqrt(h2);
  const double b = glm::dot(n, u), a = glm::dot(n, D) - du * b;
  auto f0 = [&](double s) { return s / (2 * h2 * (s * s + h2)) + std::atan(s / h) / (2 * h2 * h); };
  auto f1 = [&](double s) { return -1.0 / (2 * (s * s + h2)); };
  const double lo = t0 + du, hi = t1 + du;
  return ce * (a * (f0(hi) - f0(lo)) + b * (f1(hi) - f1(lo))) / length;
}

} // namespace

PreparedLight::PreparedLight(const Light& light) : position(light.position), intensity(light.intensity) {
  if (light.type == LightType::Spot) {
    spot = true;
    direction = glm::normalize(light.direction);
    cone = SpotCone::of(light);
  }
  if (light.type == LightType::Luminaire) {
    luminaire = &light;
    frame = LuminaireFrame::of(light);
  }
  if (is_area(light.type)) {
    direction = glm::normalize(light.direction);
    frame = LuminaireFrame::of(light);
    area = prepare_area(light);
  }
}

float area_irradiance_on_side(const RayScene& es, const ShadingPoint& at, const Vec3& n, const Vec3& side_normal,
                              const AreaSource& area, uint64_t& rays) {
  const Vec3& p = at.position;
  const AreaFrame& f = area.frame;
  const glm::dvec3 side(side_normal), pd(p);
  // The receiver's cosine is |n·ω| on this side.
  const glm::dvec3 n_side = glm::dot(n, side_normal) >= 0.f ? glm::dvec3(n) : -glm::dvec3(n);
  const bool in_front = glm::dot(f.normal, p - f.centre) > 0.f;
  // The cosine part, exact for the unhidden source.
  double exact = 0;
  std::vector<glm::dvec3> clipped;
  if (in_front && area.lambert_part > 0.f) {
    if (area.type == LightType::Line) {
      exact = line_integral(f, area.area, glm::dvec3(f.centre) - pd, n_side, side);
    } else {
      std::vector<glm::dvec3> q;
      q.reserve(area.outline.size());
      for (const Vec3& v : area.outline) q.push_back(glm::dvec3(v) - pd);
      clipped = clip_to_side(q, side);
      if (clipped.size() >= 3) exact = polygon_integral(clipped, n_side) / area.area;
    }
    exact *= area.lambert_part;
  }
  // Visibility and the profile's remainder from the parts.
  const float eps = es.epsilon();
  double lambert = 0, lambert_seen = 0, rest = 0;
  const double share = 1.0 / double(area.samples.size());
  for (const Vec3& x : area.samples) {
    const Vec3 d = x - p;
    const float dist2 = glm::dot(d, d);
    if (dist2 <= eps * eps || glm::dot(d, side_normal) <= 0.f) continue;
    const float dist = std::sqrt(dist2);
    const Vec3 w = d / dist;
    const double cos_r = std::abs(double(glm::dot(n, w))), cos_e = std::max(0.0, -double(glm::dot(f.normal, w)));
    const double weight = cos_e * cos_r / dist2;
    double other = 0;
    if (area.profiled)
      other = (luminaire_factor(*area.profiled, area.profile_frame, -w) - area.lambert_part * cos_e) * cos_r / dist2;
    if (weight == 0 && other == 0) continue;
    ++rays;
    const bool seen = !es.occluded(at.ray_start(w, side_normal, eps), w, dist - 2.f * eps) && !in_own_wedge(es, at, n, w);
    lambert += weight;
    if (seen) {
      lambert_seen += weight;
      rest += other * share;
    }
  }
  double visible = lambert > 0 ? lambert_seen / lambert : 0.0;
  if (exact > 0 && lambert == 0) {
    // A sliver in front of this side with no part's centre on it: one ray to its middle.
    glm::dvec3 mid(0.0);
    if (area.type == LightType::Line) {
      mid = glm::dvec3(f.centre) - pd;
    } else {
      for (const auto& v : clipped) mid += v;
      mid /= double(clipped.size());
    }
    const float dist = float(glm::length(mid));
    visible = 0;
    if (dist > eps) {
      const Vec3 w = Vec3(mid / double(dist));
      ++rays;
      visible = es.occluded(at.ray_start(w, side_normal, eps), w, dist - 2.f * eps) || in_own_wedge(es, at, n, w) ? 0.0 : 1.0;
    }
  }
  return float(std::max(0.0, exact * visible + rest));
}

} // namespace hilight::embree
