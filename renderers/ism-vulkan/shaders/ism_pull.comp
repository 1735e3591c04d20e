#version 450
#extension GL_GOOGLE_include_directive : require
// Pull-push hole filling, pull: each texel of a coarser level averages the
// valid (>= 0) depths of its four finer texels; none valid: -1. The finest
// level is made from the splatted ISM bits (empty = 0xffffffff).
#include "common.glsl"

layout(push_constant) uniform Params {
  uint vpls;
  uint size;        // of the level written
  uint source;      // offset of the finer level (or 0 for the ISM)
  uint target;      // offset of the level written
  uint from_ism;    // 1: make the finest level from the ISM (same size)
} params;

layout(std430, binding = 0) readonly buffer Ism { uint ism[]; };
layout(std430, binding = 1) buffer Pyramid { float pyramid[]; };

void main() {
  uint id = thread_id();
  uint texels = params.size * params.size;
  if (id >= params.vpls * texels) return;
  if (params.from_ism != 0u) {
    uint bits = ism[id];
    pyramid[params.target + id] = bits == 0xffffffffu ? -1.0 : uintBitsToFloat(bits);
    return;
  }
  uint v = id / texels, r = id % texels;
  uint x = r % params.size, y = r / params.size;
  uint fine = params.size * 2u;
  uint base = params.source + v * fine * fine;
  float sum = 0.0, count = 0.0;
  for (uint k = 0u; k < 4u; ++k) {
    float d = pyramid[base + (2u * y + (k >> 1u)) * fine + 2u * x + (k & 1u)];
    if (d >= 0.0) { sum += d; count += 1.0; }
  }
  pyramid[params.target + id] = count > 0.0 ? sum / count : -1.0;
}
