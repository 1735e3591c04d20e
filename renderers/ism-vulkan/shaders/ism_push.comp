#version 450
#extension GL_GOOGLE_include_directive : require
// Pull-push hole filling, push: a texel no point landed on takes the depth of
// its coarser parent (itself filled), so every hole gets its neighbourhood's depth.
#include "common.glsl"

layout(push_constant) uniform Params {
  uint vpls;
  uint size;        // of the level filled
  uint source;      // offset of the coarser level
  uint target;      // offset of the level filled
} params;

layout(std430, binding = 0) buffer Pyramid { float pyramid[]; };

void main() {
  uint id = thread_id();
  uint texels = params.size * params.size;
  if (id >= params.vpls * texels) return;
  if (pyramid[params.target + id] >= 0.0) return;
  uint v = id / texels, r = id % texels;
  uint x = r % params.size, y = r / params.size;
  uint coarse = params.size / 2u;
  pyramid[params.target + id] = pyramid[params.source + v * coarse * coarse + (y / 2u) * coarse + x / 2u];
}
