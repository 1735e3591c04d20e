#include "hilight/photometry.hpp"

#include "hilight/math.hpp"

#include <algorithm>
#include <cmath>

namespace hilight {

namespace {

double wrap360(double a) {
  a = std::fmod(a, 360.0);
  return a < 0 ? a + 360.0 : a;
}

/// Index i and weight t with axis[i] ≤ x ≤ axis[i+1]; false outside the axis.
bool bracket(const std::vector<double>& axis, double x, size_t& i, double& t) {
  if (axis.size() == 1) {
    i = 0;
    t = 0;
    return std::abs(x - axis[0]) < 1e-9;
  }
  if (x < axis.front() - 1e-9 || x > axis.back() + 1e-9) return false;
  const auto it = std::upper_bound(axis.begin(), axis.end(), x);
  i = std::min<size_t>(size_t(std::max<std::ptrdiff_t>(it - axis.begin() - 1, 0)), axis.size() - 2);
  t = std::clamp((x - axis[i]) / (axis[i + 1] - axis[i]), 0.0, 1.0);
  return true;
}

} // namespace

double Photometry::intensity(double c_deg, double gamma_deg) const {
  if (candela.empty()) return 0.0;
  double h = wrap360(c_deg), v = gamma_deg;
  if (type == Type::B) {
    // Type B planes share the horizontal axis through the luminaire:
    // tan H = cos C · tan γ, sin V = sin C · sin γ (H, V in [−90, 90] for the
    // front hemisphere; the back one is not measured by type B files).
    const double c = h * kPi / 180.0, g = gamma_deg * kPi / 180.0;
    const double x = std::cos(c) * std::sin(g), y = std::sin(c) * std::sin(g), z = std::cos(g);
    if (z < -1e-12) return 0.0;
    h = std::atan2(x, z) * 180.0 / kPi;
    v = std::asin(std::clamp(y, -1.0, 1.0)) * 180.0 / kPi;
    if (symmetry == Symmetry::AboutC0C180) h = std::abs(h);  // a file with H in [0, 90] is mirrored
  } else {
    switch (symmetry) {
    case Symmetry::Rotational: h = horizontal.front(); break;
    case Symmetry::AboutC0C180: h = h <= 180.0 ? h : 360.0 - h; break;
    case Symmetry::AboutC90C270: h = (h >= 90.0 && h <= 270.0) ? h : wrap360(180.0 - h); break;
    case Symmetry::Quadrants:
      h = std::fmod(h, 180.0);
      h = h <= 90.0 ? h : 180.0 - h;
      break;
    case Symmetry::None:
      // Before the first plane is after the last one, a turn earlier (a
      // EULUMDAT file's planes need not start at C = 0).
      if (h < horizontal.front()) h += 360.0;
      if (h > horizontal.back()) {  // between the last plane and 360 = the first plane again
        const double span = 360.0 - horizontal.back() + horizontal.front();
        const double t = span > 0 ? (h - horizontal.back()) / span : 0.0;
        const size_t last = horizontal.size() - 1, n = vertical.size();
        size_t i;
        double s;
        if (!bracket(vertical, v, i, s)) return 0.0;
        auto at = [&](size_t plane) {
          return vertical.size() == 1 ? candela[plane * n] : (1 - s) * candela[plane * n + i] + s * candela[plane * n + i + 1];
        };
        return (1 - t) * at(last) + t * at(0);
      }
      break;
    }
  }
  size_t p = 0, i = 0;
  double tp = 0, ti = 0;
  if (!bracket(vertical, v, i, ti)) return 0.0;
  if (horizontal.size() > 1 && !bracket(horizontal, h, p, tp)) return 0.0;
  const size_t n = vertical.size();
  auto at = [&](size_t plane) {
    return n == 1 ? candela[plane * n] : (1 - ti) * candela[plane * n + i] + ti * candela[plane * n + i + 1];
  };
  return horizontal.size() == 1 ? at(0) : (1 - tp) * at(p) + tp * at(p + 1);
}

double Photometry::flux() const {
  // Midpoint rule on a fine (C, γ) grid: exact enough for a check (0.1%).
  const int nc = 360, ng = 360;
  double sum = 0;
  for (int g = 0; g < ng; ++g) {
    const double gamma = (g + 0.5) * 180.0 / ng;
    const double band = 2.0 * kPi / nc * std::sin(gamma * kPi / 180.0) * kPi / ng;
    for (int c = 0; c < nc; ++c) sum += intensity((c + 0.5) * 360.0 / nc, gamma) * band;
  }
  return sum;
}

double Photometry::peak() const { return candela.empty() ? 0.0 : *std::max_element(candela.begin(), candela.end()); }

std::vector<float> distinct_spins(const Photometry& profile) {
  switch (profile.symmetry) {
    case Photometry::Symmetry::Rotational: return {0.f};
    case Photometry::Symmetry::Quadrants: return {0.f, 90.f};
    default: return {0.f, 90.f, 180.f, 270.f};
  }
}

} // namespace hilight
