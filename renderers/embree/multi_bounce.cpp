#include "multi_bounce.hpp"

#include "hilight/bounce_series.hpp"
#include "hilight/bounces.hpp"
#include "hilight/error.hpp"

#include <array>
#include <cmath>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace hilight::embree {

namespace {
SurfacePoints vertices_of(const Scene& scene) { return SurfacePoints::from_vertices(scene); }
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
  std::vector<Rgb> current(light_count * n, Rgb(0.f)), next(light_count * n, Rgb(0.f));
  BounceSeriesSum series(light_count, n, m_bounces, kMaxSteps);
  // d₁ = T e₀ from the scalar direct light.
  step([&](size_t j, const uint32_t* e, const float* w) {
         const float* d = &direct[j * n];
         return Rgb(w[0] * d[e[0]] + w[1] * d[e[1]] + w[2] * d[e[2]]);
       },
       current, series.active());
  if (progress) progress->advance();
  for (int steps = 1; series.add(steps, current); ++steps) {
    step([&](size_t j, const uint32_t* e, const float* w) {
           const Rgb* d = &current[j * n];
           return w[0] * d[e[0]] + w[1] * d[e[1]] + w[2] * d[e[2]];
         },
         next, series.active());
    if (progress) progress->advance();
    std::swap(current, next);
  }
  return std::move(series.sum());
}

} // namespace hilight::embree
