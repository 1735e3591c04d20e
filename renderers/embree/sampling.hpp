#pragma once
/// Deterministic sampling helpers for the first-bounce gather: a per-point
/// random stream, Hammersley points with a random rotation per point
/// (Cranley–Patterson), and cosine-weighted hemisphere directions.
#include "hilight/math.hpp"

#include <cstdint>

namespace hilight::embree {

/// splitmix64: a good 64-bit mix; seeds independent per-point streams.
uint64_t mix64(uint64_t x);
/// Uniform float in [0, 1) from 64 random bits.
float to_unit_float(uint64_t bits);
/// Van der Corput radical inverse in base 2.
float radical_inverse2(uint32_t i);
/// Cosine-weighted direction around unit `n` from (u1, u2) in [0,1)^2.
Vec3 cosine_direction(const Vec3& n, float u1, float u2);

} // namespace hilight::embree
