#version 450
#extension GL_GOOGLE_include_directive : require
// Imperfect shadow maps: each VPL splats its own random subset of the
// scene's point samples into a small paraboloid depth map over its
// hemisphere (nearest wins; depths as float bits order like the floats).
#include "common.glsl"

layout(push_constant) uniform Params {
  uint vpls;       // all VPLs of the batch
  uint per_vpl;    // points splatted per VPL
  uint pool;       // scene point samples in all
  uint size;       // ISM resolution
} params;

layout(std430, binding = 0) readonly buffer Vpls { vec4 vpls[]; };
layout(std430, binding = 1) readonly buffer Pool { vec4 pool[]; };
layout(std430, binding = 2) buffer Ism { uint ism[]; };

void main() {
  uint id = thread_id();
  if (id >= params.vpls * params.per_vpl) return;
  uint v = id / params.per_vpl, j = id % params.per_vpl;
  vec4 origin = vpls[VPL_STRIDE * v];
  if (origin.w == 0.0) return;
  vec3 n = vpls[VPL_STRIDE * v + 1u].xyz, t = vpls[VPL_STRIDE * v + 3u].xyz, b = vpls[VPL_STRIDE * v + 4u].xyz;
  // The pool is shuffled: a run of it from a per-VPL start is a random subset.
  // The start is the VPL's own key (vpl_generate.comp), not its batch index.
  vec3 q = pool[(uint(vpls[VPL_STRIDE * v + 2u].w) % params.pool + j) % params.pool].xyz;
  vec3 w = q - origin.xyz;
  float len = length(w);
  vec3 local = vec3(dot(w, t), dot(w, b), dot(w, n));
  if (local.z <= 1e-6 * len || len == 0.0) return;
  ivec2 texel = paraboloid_texel(local, len, params.size);
  atomicMin(ism[v * params.size * params.size + uint(texel.y) * params.size + uint(texel.x)], floatBitsToUint(len));
}
