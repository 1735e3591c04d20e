#include "multi_bounce.hpp"

#include "field_sums.hpp"
#include "hilight/bounce_series.hpp"
#include "hilight/bounces.hpp"
#include "hilight/error.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <type_traits>

namespace hilight::embree {

namespace {
SurfacePoints vertices_of(const Scene& scene) { return SurfacePoints::from_vertices(scene); }
} // namespace

MultiBounce::MultiBounce(const RayScene& es, const std::vector<ShadingPoint>& vertex_shading, int samples, uint64_t seed,
                         int bounces, double rest_share, ProgressStage* progress)
    // Another stream than the points' gathers, so the two estimates are independent.
    : m_es(es), m_gather(es, vertices_of(es.scene()), vertex_shading, samples, seed ^ 0x6d756c7469626f75ull, progress), m_bounces(bounces),
      m_rest_share(rest_share) {
  if (bounces != kAllBounces && bounces < 2) throw std::logic_error("MultiBounce: fewer than two bounces need no vertex transport");
}

std::vector<Rgb> MultiBounce::bounced_field(const std::vector<float>& direct, size_t light_count, ProgressStage* progress) const {
  const size_t v_count = m_es.scene().positions.size(), n = 2 * v_count, lights = light_count;
  const float scale = 2.f / float(m_gather.samples());
  // Entry-major fields: a hit reads the lights' values at a vertex side
  // together (light-major, each light was a cache miss of its own).
  // One step for every light: out_j(v, s) = (2/N) Σ ρ(y) in_j(y) over v's
  // hemisphere s; `value` interpolates the hit's light from its vertices.
  // A hit whose three corners hold no light of any active light adds
  // nothing and is passed by: `lit` says per (vertex, side) of the field
  // read whether it holds any, and the step says it of the field it writes.
  // (Half the hits in the bench building's cache build: a light's bounced
  // light reaches the rooms beyond its own a step at a time.)
  std::vector<uint8_t> lit(n), lit_next(n);
  auto step = [&](const auto* in, auto&& value, std::vector<Rgb>& out, const std::vector<char>& active) {
    // Looked at only where a quarter of the field or more is dark: in a
    // lit room the look is all cost (5% of the bundled room's cache build).
    const bool sparse = size_t(std::count(lit.begin(), lit.end(), uint8_t(0))) * 4 >= n;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, v_count, 256), [&](const tbb::blocked_range<size_t>& r) {
      std::vector<Rgb> acc(lights);
      for (size_t v = r.begin(); v != r.end(); ++v)
        for (int side = 0; side < 2; ++side) {
          std::fill(acc.begin(), acc.end(), Rgb(0.f));
          m_gather.for_each_hit(v, side, [&](const Rgb& albedo, const uint32_t* entry, const float* weight) {
            if (sparse && !(lit[entry[0]] | lit[entry[1]] | lit[entry[2]])) return;
            const auto *a = in + entry[0] * lights, *b = in + entry[1] * lights, *c = in + entry[2] * lights;
            if constexpr (std::is_same_v<std::remove_cvref_t<decltype(*in)>, Rgb>)
              add_interpolated(albedo, weight, a, b, c, lights, acc.data());  // every light: the ended ones are not written
            else
              for (size_t j = 0; j < lights; ++j)
                if (active[j]) acc[j] += albedo * value(weight, a[j], b[j], c[j]);
          });
          Rgb* o = &out[(2 * v + side) * lights];
          uint8_t any = 0;
          for (size_t j = 0; j < lights; ++j)
            if (active[j]) {
              o[j] = acc[j] * scale;
              any |= uint8_t(o[j] != Rgb(0.f));
            }
          lit_next[2 * v + side] = any;
        }
    });
    std::swap(lit, lit_next);
  };
  std::vector<float> direct_by_entry(direct.size());
  for (size_t j = 0; j < lights; ++j)
    for (size_t e = 0; e < n; ++e) {
      direct_by_entry[e * lights + j] = direct[j * n + e];
      lit[e] |= uint8_t(direct[j * n + e] != 0.f);
    }
  std::vector<Rgb> current(lights * n, Rgb(0.f)), next(lights * n, Rgb(0.f));
  BounceSeriesSum series(lights, n, m_bounces, kMaxSteps, BounceSeriesSum::Layout::EntryMajor, m_rest_share);
  // d₁ = T e₀ from the scalar direct light.
  step(direct_by_entry.data(),
       [](const float* w, float a, float b, float c) { return Rgb(w[0] * a + w[1] * b + w[2] * c); }, current,
       series.active());
  std::vector<float>().swap(direct_by_entry);
  if (progress) progress->advance();
  for (int steps = 1; series.add(steps, current); ++steps) {
    step(current.data(), [](const float* w, const Rgb& a, const Rgb& b, const Rgb& c) { return w[0] * a + w[1] * b + w[2] * c; },
         next, series.active());
    if (progress) progress->advance();
    std::swap(current, next);
  }
  return std::move(series.sum());
}

} // namespace hilight::embree
