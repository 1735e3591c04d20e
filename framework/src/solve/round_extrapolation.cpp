#include "hilight/solve/round_extrapolation.hpp"

#include "hilight/math.hpp"
#include "hilight/solve/spot_refinement.hpp"

#include <algorithm>
#include <cmath>

namespace hilight {

namespace {

/// The steps must agree this well in direction (cosine) to be one
/// iteration's shrinking steps and not a turn or noise.
constexpr double kSameWay = 0.5;
/// The furthest guess, in steps (r = 0.9 is ten steps on): a ratio nearer 1
/// is more likely the bounce's roughness than a slow valley.
constexpr double kMostSteps = 10.0;

/// A step from `a` to `b` in units where each coordinate's change weighs
/// alike: positions in diagonals, directions as unit vectors (radians for
/// small turns), cone angles in radians.
std::vector<double> step_between(const Lighting& a, const Lighting& b, float diagonal) {
  std::vector<double> s;
  for (size_t j = 0; j < a.size(); ++j) {
    for (int k = 0; k < 3; ++k) s.push_back(double(b[j].position[k] - a[j].position[k]) / diagonal);
    if (a[j].type != LightType::Spot) continue;
    const Vec3 da = glm::normalize(a[j].direction), db = glm::normalize(b[j].direction);
    for (int k = 0; k < 3; ++k) s.push_back(double(db[k] - da[k]));
    s.push_back(double(b[j].cutoff_deg - a[j].cutoff_deg) * kPi / 180.0);
    s.push_back(double(b[j].falloff_deg - a[j].falloff_deg) * kPi / 180.0);
  }
  return s;
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0;
  for (size_t i = 0; i < a.size(); ++i) sum += a[i] * b[i];
  return sum;
}

/// `from` carried `factor` times its step to `to`.
Lighting carried(const Lighting& from, const Lighting& to, double factor) {
  Lighting out = to;
  const float f = float(factor);
  for (size_t j = 0; j < from.size(); ++j) {
    out[j].position = from[j].position + f * (to[j].position - from[j].position);
    if (from[j].type != LightType::Spot) continue;
    const Vec3 da = glm::normalize(from[j].direction), db = glm::normalize(to[j].direction);
    out[j].direction = glm::normalize(da + f * (db - da));
    out[j].cutoff_deg = std::clamp(from[j].cutoff_deg + f * (to[j].cutoff_deg - from[j].cutoff_deg), kMinSpotCutoffDeg, kMaxSpotCutoffDeg);
    out[j].falloff_deg = std::clamp(from[j].falloff_deg + f * (to[j].falloff_deg - from[j].falloff_deg), kMinSpotFalloffDeg, out[j].cutoff_deg);
  }
  return out;
}

bool same_kinds(const Lighting& a, const Lighting& b) {
  if (a.size() != b.size()) return false;
  for (size_t j = 0; j < a.size(); ++j)
    if (a[j].type != b[j].type) return false;
  return true;
}

} // namespace

std::optional<Lighting> RoundExtrapolation::ahead(const Lighting& from, const Lighting& to) {
  if (!same_kinds(from, to) || !(m_diagonal > 0.f)) {
    restart();
    return std::nullopt;
  }
  std::vector<double> step = step_between(from, to, m_diagonal);
  std::vector<double> last = std::move(m_last);
  m_last = step;
  if (last.size() != step.size()) return std::nullopt;
  const double ll = dot(last, last), ss = dot(step, step), ls = dot(last, step);
  if (!(ll > 0.0) || !(ss > 0.0) || ls < kSameWay * std::sqrt(ll * ss)) return std::nullopt;
  const double r = ls / ll;  // the step along the last one, as a share of it
  if (!(r < 1.0)) return std::nullopt;
  const double factor = std::min(1.0 / (1.0 - r), kMostSteps);
  if (!(factor > 1.0 + 1e-6)) return std::nullopt;
  return carried(from, to, factor);
}

} // namespace hilight
