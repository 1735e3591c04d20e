#include "bounce_transport.hpp"

#include "hilight/bounce_series.hpp"

#include "hilight/bounces.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <stdexcept>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace hilight::ism {

double surface_area(const Scene& s) {
  double area = 0;
  for (const auto& tri : s.triangles)
    area += 0.5 * double(glm::length(glm::cross(s.positions[tri[1]] - s.positions[tri[0]], s.positions[tri[2]] - s.positions[tri[0]])));
  return area;
}

SurfacePoints sample_bounce_points(const Scene& s, uint32_t count, uint64_t seed) {
  std::vector<double> cumulative(s.triangles.size());
  double area = 0;
  for (size_t t = 0; t < s.triangles.size(); ++t) {
    const Vec3 &p0 = s.positions[s.triangles[t][0]], &p1 = s.positions[s.triangles[t][1]], &p2 = s.positions[s.triangles[t][2]];
    area += 0.5 * double(glm::length(glm::cross(p1 - p0, p2 - p0)));
    cumulative[t] = area;
  }
  SurfacePoints out;
  std::mt19937_64 rng(seed * 0xD1B54A32D192ED03ull + 29);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (uint32_t k = 0; k < count; ++k) {
    // Stratified along the cumulative area: every part of the scene gets its share.
    const double at = (double(k) + uniform(rng)) / double(count) * area;
    size_t t = size_t(std::lower_bound(cumulative.begin(), cumulative.end(), at) - cumulative.begin());
    t = std::min(t, s.triangles.size() - 1);
    const float r1 = float(std::sqrt(uniform(rng))), r2 = float(uniform(rng));
    const Vec3 &p0 = s.positions[s.triangles[t][0]], &p1 = s.positions[s.triangles[t][1]], &p2 = s.positions[s.triangles[t][2]];
    out.positions.push_back((1.f - r1) * p0 + r1 * (1.f - r2) * p1 + r1 * r2 * p2);
    out.normals.push_back(s.face_normal(t));
    out.albedo.push_back(s.triangle_albedo(t));
  }
  return out;
}

std::vector<float> paraboloid_cosine_weights(uint32_t size) {
  // A direction at disk radius r = tan(θ/2) has cos θ = (1 − r²)/(1 + r²) and
  // dω = 4/(1 + r²)² du dv: the cosine-weighted density over the disk is
  // 4(1 − r²)/(π(1 + r²)³), integrated here on 16² sub-samples a texel.
  constexpr int kSub = 16;
  std::vector<float> w(size_t(size) * size, 0.f);
  double total = 0;
  for (uint32_t y = 0; y < size; ++y)
    for (uint32_t x = 0; x < size; ++x) {
      double sum = 0;
      for (int j = 0; j < kSub; ++j)
        for (int i = 0; i < kSub; ++i) {
          const double u = (x + (i + 0.5) / kSub) / size * 2.0 - 1.0, v = (y + (j + 0.5) / kSub) / size * 2.0 - 1.0;
          const double r2 = u * u + v * v;
          if (r2 < 1.0) sum += 4.0 * (1.0 - r2) / (kPi * std::pow(1.0 + r2, 3.0));
        }
      w[y * size + x] = float(sum);
      total += sum;
    }
  for (float& v : w) v = float(v / total);
  return w;
}

void GatherRows::append(const uint32_t* nearest, const uint32_t* drawn, size_t count, uint32_t size,
                        const std::vector<float>& weights) {
  const size_t texels = size_t(size) * size;
  std::vector<std::vector<std::pair<uint32_t, float>>> rows(count);
  tbb::parallel_for(size_t(0), count, [&](size_t r) {
    const uint32_t* map = nearest + r * texels;
    const uint32_t* draw = drawn + r * texels;
    for (uint32_t y = 0; y < size; ++y)
      for (uint32_t x = 0; x < size; ++x) {
        const float w = weights[y * size + x];
        if (w <= 0.f) continue;
        size_t at = y * size + x;
        for (int reach = 1; reach <= 2 && map[at] == ~0u; ++reach)
          for (int dy = -reach; dy <= reach; ++dy)
            for (int dx = -reach; dx <= reach; ++dx) {
              const int nx = int(x) + dx, ny = int(y) + dy;
              if (nx >= 0 && ny >= 0 && nx < int(size) && ny < int(size) && map[ny * size + nx] < map[at]) at = ny * size + nx;
            }
        if (map[at] == ~0u) continue;  // open sky
        const uint32_t v = draw[at] != ~0u ? draw[at] : map[at];
        rows[r].emplace_back(v & 0xffffu, w);
      }
  });
  for (const auto& row : rows) {
    for (const auto& [h, w] : row) {
      hit.push_back(h);
      weight.push_back(w);
    }
    start.push_back(uint32_t(hit.size()));
  }
}

BounceSeries::BounceSeries(GatherRows transport, std::vector<Rgb> albedo, int bounces)
    : m_transport(std::move(transport)), m_albedo(std::move(albedo)), m_bounces(bounces) {
  if (bounces != kAllBounces && bounces < 2) throw std::logic_error("BounceSeries: fewer than two bounces need no transport");
  if (m_transport.rows() != 2 * m_albedo.size()) throw std::logic_error("BounceSeries: one row per bounce point side");
}


std::vector<Rgb> BounceSeries::bounced(const std::vector<float>& direct, size_t lights) const {
  const size_t n = sides();
  const GatherRows& t = m_transport;
  // One step for every active light: out_j(r) = Σ w ρ(hit) in_j(hit).
  auto step = [&](auto&& read, std::vector<Rgb>& out, const std::vector<char>& active) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 64), [&](const tbb::blocked_range<size_t>& range) {
      std::vector<Rgb> acc(lights);
      for (size_t r = range.begin(); r != range.end(); ++r) {
        std::fill(acc.begin(), acc.end(), Rgb(0.f));
        for (uint32_t e = t.start[r]; e < t.start[r + 1]; ++e) {
          const uint32_t h = t.hit[e];
          const Rgb carried = t.weight[e] * m_albedo[h / 2];
          for (size_t j = 0; j < lights; ++j)
            if (active[j]) acc[j] += carried * read(j, h);
        }
        for (size_t j = 0; j < lights; ++j)
          if (active[j]) out[j * n + r] = acc[j];
      }
    });
  };
  std::vector<Rgb> current(lights * n, Rgb(0.f)), next(lights * n, Rgb(0.f));
  BounceSeriesSum series(lights, n, m_bounces, kMaxSteps);
  step([&](size_t j, uint32_t h) { return Rgb(direct[j * n + h]); }, current, series.active());  // d₁ = T e₀
  for (int steps = 1; series.add(steps, current); ++steps) {
    step([&](size_t j, uint32_t h) { return current[j * n + h]; }, next, series.active());
    std::swap(current, next);
  }
  return std::move(series.sum());
}

void BounceSeries::gather(const GatherRows& points, const std::vector<Rgb>& point_albedo, size_t first, const std::vector<Rgb>& f,
                          size_t lights, Rgb* out, size_t stride) const {
  const size_t n = sides(), count = points.rows() / 2;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 64), [&](const tbb::blocked_range<size_t>& range) {
    std::vector<Rgb> acc(lights);
    for (size_t i = range.begin(); i != range.end(); ++i) {
      std::fill(acc.begin(), acc.end(), Rgb(0.f));
      for (uint32_t e = points.start[2 * i]; e < points.start[2 * i + 2]; ++e) {
        const uint32_t h = points.hit[e];
        const Rgb carried = points.weight[e] * m_albedo[h / 2];
        for (size_t j = 0; j < lights; ++j) acc[j] += carried * f[j * n + h];
      }
      const Rgb rho = point_albedo[first + i] / float(kPi);
      for (size_t j = 0; j < lights; ++j) out[j * stride + first + i] += rho * acc[j];
    }
  });
}

} // namespace hilight::ism
