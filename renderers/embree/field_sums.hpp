#pragma once
/// The inner sum of every walk over gather hits that reads a field of many
/// lights at once (entry-major: an entry's lights lie together):
///   out[j] += albedo · (w₀ a[j] + w₁ b[j] + w₂ c[j])   for j < lights,
/// four lights (twelve floats) at a time in 4-wide vectors. Each channel
/// gets the same products and sums in the same order as the per-light form
/// (no fused multiply-add), so the bits are the same; the compiler did not
/// vectorize the per-light form over RGB triples.
#include "hilight/math.hpp"

#include <cstddef>
#include <cstring>

namespace hilight::embree {

namespace field_sums_detail {
typedef float Float4 __attribute__((vector_size(16)));
inline Float4 load(const float* p) {
  Float4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline void store(float* p, Float4 v) { std::memcpy(p, &v, sizeof v); }
} // namespace field_sums_detail

inline void add_interpolated(const Rgb& albedo, const float* weight, const Rgb* a, const Rgb* b, const Rgb* c, size_t lights,
                             Rgb* out) {
  using namespace field_sums_detail;
  static_assert(sizeof(Rgb) == 3 * sizeof(float), "Rgb must be three packed floats");
  const float *fa = &a[0].x, *fb = &b[0].x, *fc = &c[0].x;
  float* fo = &out[0].x;
  const Float4 w0 = {weight[0], weight[0], weight[0], weight[0]}, w1 = {weight[1], weight[1], weight[1], weight[1]},
               w2 = {weight[2], weight[2], weight[2], weight[2]};
  // Twelve floats are four lights' r g b: the albedo's channels repeat so.
  const Float4 albedo4[3] = {{albedo.r, albedo.g, albedo.b, albedo.r}, {albedo.g, albedo.b, albedo.r, albedo.g},
                             {albedo.b, albedo.r, albedo.g, albedo.b}};
  size_t j = 0;
  for (; j + 4 <= lights; j += 4)
    for (int q = 0; q < 3; ++q) {
      const size_t k = 3 * j + 4 * size_t(q);
      Float4 s = w0 * load(fa + k) + w1 * load(fb + k);
      s = s + w2 * load(fc + k);
      store(fo + k, load(fo + k) + albedo4[q] * s);
    }
  for (; j < lights; ++j) out[j] += albedo * (weight[0] * a[j] + weight[1] * b[j] + weight[2] * c[j]);
}

} // namespace hilight::embree
