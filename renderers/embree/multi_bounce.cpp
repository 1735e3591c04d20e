#include "multi_bounce.hpp"

#include "hilight/bounces.hpp"
#include "hilight/error.hpp"

#include <array>
#include <cmath>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace hilight::embree {

namespace {
SurfacePoints vertices_of(const Scene& scene) { return SurfacePoints::from_vertices(scene); }

/// Σ of a field per channel, in double (the series' convergence test).
std::array<double, 3> channel_sums(const Rgb* field, size_t n) {
  std::array<double, 3> s{0.0, 0.0, 0.0};
  for (size_t k = 0; k < n; ++k)
    for (int c = 0; c < 3; ++c) s[c] += double(field[k][c]);
  return s;
}
} // namespace

MultiBounce::MultiBounce(const RayScene& es, const std::vector<ShadingPoint>& vertex_shading, int samples, uint64_t seed,
                         int bounces, ProgressStage* progress)
    // Another stream than the points' gathers, so the two estimates are independent.
    : m_es(es), m_gather(es, vertices_of(es.scene()), vertex_shading, samples, seed ^ 0x6d756c7469626f75ull, progress), m_bounces(bounces) {
  if (bounces != kAllBounces && bounces < 2) throw std::logic_error("MultiBounce: fewer than two bounces need no vertex transport");
}

std::vector<Rgb> MultiBounce::bounced_field(const std::vector<float>& direct, size_t light_count, ProgressStage* progress) const {
  const size_t v_count = m_es.scene().positions.size(), n = 2 * v_count;
  const float scale = 2.f / float(m_gather.samples());
  // One step for every light: out_j(v, s) = (2/N) Σ ρ(y) in_j(y) over v's hemisphere s.
  auto step = [&](auto&& read, std::vector<Rgb>& out, const std::vector<char>& active) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, v_count, 256), [&](const tbb::blocked_range<size_t>& r) {
      std::vector<Rgb> acc(light_count);
      for (size_t v = r.begin(); v != r.end(); ++v)
        for (int side = 0; side < 2; ++side) {
          std::fill(acc.begin(), acc.end(), Rgb(0.f));
          m_gather.for_each_hit(v, side, [&](const Rgb& albedo, const uint32_t* entry, const float* weight) {
            for (size_t j = 0; j < light_count; ++j)
              if (active[j]) acc[j] += albedo * read(j, entry, weight);
          });
          for (size_t j = 0; j < light_count; ++j)
            if (active[j]) out[j * n + 2 * v + side] = acc[j] * scale;
        }
    });
  };
  std::vector<Rgb> sum(light_count * n, Rgb(0.f)), current(light_count * n, Rgb(0.f)), next(light_count * n, Rgb(0.f));
  std::vector<char> active(light_count, 1);
  // d₁ = T e₀ from the scalar direct light.
  step([&](size_t j, const uint32_t* e, const float* w) {
         const float* d = &direct[j * n];
         return Rgb(w[0] * d[e[0]] + w[1] * d[e[1]] + w[2] * d[e[2]]);
       },
       current, active);
  if (progress) progress->advance();
  const int last = m_bounces == kAllBounces ? kMaxSteps : m_bounces - 1;  // d₁ … d_last
  std::vector<std::array<double, 3>> previous_ratio(light_count, {-1.0, -1.0, -1.0}), previous_size(light_count);
  int steps = 1;
  for (;; ++steps) {
    for (size_t j = 0; j < light_count; ++j) {
      if (!active[j]) continue;
      const Rgb* d = &current[j * n];
      Rgb* s = &sum[j * n];
      for (size_t k = 0; k < n; ++k) s[k] += d[k];
      const auto size = channel_sums(d, n), total = channel_sums(s, n);
      std::array<double, 3> ratio{-1.0, -1.0, -1.0};
      bool negligible = true, steady = steps >= 3;
      Rgb rest(0.f);
      for (int c = 0; c < 3; ++c) {
        if (steps > 1 && previous_size[j][c] > 0.0) ratio[c] = size[c] / previous_size[j][c];
        if (size[c] <= kNegligible * total[c]) continue;  // this channel has converged
        negligible = false;
        steady = steady && ratio[c] > 0.0 && ratio[c] < 1.0 && std::abs(ratio[c] - previous_ratio[j][c]) <= kSteadyRatio;
        if (steady) rest[c] = float(ratio[c] / (1.0 - ratio[c]));
      }
      bool done = negligible || steps >= last;
      if (m_bounces == kAllBounces && !done && steady) {
        // The geometric rest, per channel: d_k (r + r² + …) = d_k r/(1−r).
        for (size_t k = 0; k < n; ++k) s[k] += d[k] * rest;
        done = true;
      }
      if (done) active[j] = 0;
      previous_ratio[j] = ratio;
      previous_size[j] = size;
    }
    bool any = false;
    for (char a : active) any = any || a;
    if (!any) break;
    step([&](size_t j, const uint32_t* e, const float* w) {
           const Rgb* d = &current[j * n];
           return w[0] * d[e[0]] + w[1] * d[e[1]] + w[2] * d[e[2]];
         },
         next, active);
    if (progress) progress->advance();
    std::swap(current, next);
  }
  return sum;
}

} // namespace hilight::embree
