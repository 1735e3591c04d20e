#include "sampling.hpp"

#include <cmath>

namespace hilight::embree {

uint64_t mix64(uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

float to_unit_float(uint64_t bits) { return float(bits >> 40) * (1.f / 16777216.f); }

float radical_inverse2(uint32_t i) {
  i = (i << 16) | (i >> 16);
  i = ((i & 0x00FF00FFu) << 8) | ((i & 0xFF00FF00u) >> 8);
  i = ((i & 0x0F0F0F0Fu) << 4) | ((i & 0xF0F0F0F0u) >> 4);
  i = ((i & 0x33333333u) << 2) | ((i & 0xCCCCCCCCu) >> 2);
  i = ((i & 0x55555555u) << 1) | ((i & 0xAAAAAAAAu) >> 1);
  return float(i) * (1.f / 4294967296.f);
}

Vec3 cosine_direction(const Vec3& n, float u1, float u2) {
  // Frisvad-style orthonormal basis, with the sign fix of Duff et al. 2017.
  float sign = std::copysign(1.f, n.z);
  float a = -1.f / (sign + n.z);
  float b = n.x * n.y * a;
  Vec3 t(1.f + sign * n.x * n.x * a, sign * b, -sign * n.x);
  Vec3 bt(b, sign + n.y * n.y * a, -n.y);
  float r = std::sqrt(u1);
  float phi = float(2.0 * kPi) * u2;
  float z = std::sqrt(std::max(0.f, 1.f - u1));
  return r * std::cos(phi) * t + r * std::sin(phi) * bt + z * n;
}

} // namespace hilight::embree
