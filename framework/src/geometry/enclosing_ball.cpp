#include "hilight/enclosing_ball.hpp"

#include <cstdint>
#include <numeric>

namespace hilight {

namespace {

/// A point counts as inside a ball within this share of its radius: the
/// boundary points themselves must pass despite rounding.
constexpr double kSlack = 1e-12;

bool inside(const Ball& b, const DVec3& p) {
  if (b.radius < 0.0) return false;
  const DVec3 d = p - b.centre;
  return glm::dot(d, d) <= b.radius * b.radius * (1.0 + kSlack) + 1e-300;
}

Ball ball_of(const DVec3& a) { return {a, 0.0}; }

Ball ball_of(const DVec3& a, const DVec3& b) {
  const DVec3 c = 0.5 * (a + b);
  return {c, glm::length(a - c)};
}

/// The smallest ball with a, b and c on its boundary: their circumcircle
/// (the two farthest apart when they are collinear).
Ball ball_of(const DVec3& a, const DVec3& b, const DVec3& c) {
  const DVec3 u = b - a, v = c - a, w = glm::cross(u, v);
  const double w2 = glm::dot(w, w);
  if (!(w2 > 1e-30 * glm::dot(u, u) * glm::dot(v, v))) {
    Ball best = ball_of(a, b);
    for (const Ball& other : {ball_of(a, c), ball_of(b, c)})
      if (other.radius > best.radius) best = other;
    return best;
  }
  const DVec3 centre = a + (glm::dot(u, u) * glm::cross(v, w) + glm::dot(v, v) * glm::cross(w, u)) / (2.0 * w2);
  return {centre, glm::length(a - centre)};
}

/// The ball with a, b, c and d on its boundary: their circumsphere (the
/// smallest through three of them that holds the fourth when they are coplanar).
Ball ball_of(const DVec3& a, const DVec3& b, const DVec3& c, const DVec3& d) {
  const DVec3 u = b - a, v = c - a, w = d - a;
  const double det = glm::dot(u, glm::cross(v, w));
  const double scale = glm::length(u) * glm::length(v) * glm::length(w);
  if (!(std::abs(det) > 1e-12 * scale)) {
    Ball best;
    for (const Ball& candidate : {ball_of(a, b, c), ball_of(a, b, d), ball_of(a, c, d), ball_of(b, c, d)}) {
      const DVec3 all[4] = {a, b, c, d};
      bool holds = true;
      for (const DVec3& p : all) holds = holds && inside(candidate, p);
      if (holds && (best.radius < 0.0 || candidate.radius < best.radius)) best = candidate;
    }
    return best.radius >= 0.0 ? best : ball_of(a, b, c);
  }
  const DVec3 centre =
      a + (glm::dot(u, u) * glm::cross(v, w) + glm::dot(v, v) * glm::cross(w, u) + glm::dot(w, w) * glm::cross(u, v)) / (2.0 * det);
  return {centre, glm::length(a - centre)};
}

} // namespace

Ball smallest_enclosing_ball(const std::vector<Vec3>& points) {
  const size_t n = points.size();
  if (n == 0) return {};
  // A fixed shuffle (splitmix64 Fisher-Yates): the expected linear time of
  // the incremental algorithm, and the same order on every run and platform.
  std::vector<DVec3> p(n);
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  uint64_t state = 0x9E3779B97F4A7C15ull;
  for (size_t i = n; i > 1; --i) {
    state += 0x9E3779B97F4A7C15ull;
    uint64_t z = state;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    std::swap(order[i - 1], order[size_t(z % i)]);
  }
  for (size_t i = 0; i < n; ++i) p[i] = DVec3(points[order[i]]);

  Ball ball = ball_of(p[0]);
  for (size_t i = 1; i < n; ++i) {
    if (inside(ball, p[i])) continue;
    ball = ball_of(p[i]);
    for (size_t j = 0; j < i; ++j) {
      if (inside(ball, p[j])) continue;
      ball = ball_of(p[i], p[j]);
      for (size_t k = 0; k < j; ++k) {
        if (inside(ball, p[k])) continue;
        ball = ball_of(p[i], p[j], p[k]);
        for (size_t l = 0; l < k; ++l)
          if (!inside(ball, p[l])) ball = ball_of(p[i], p[j], p[k], p[l]);
      }
    }
  }
  return ball;
}

} // namespace hilight
