#version 450
#extension GL_GOOGLE_include_directive : require
// The bounce transport's hemisphere maps (bounce_transport.hpp): each
// receiver (a point's side: its position and the normal of that side)
// splats every bounce point into a paraboloid map over its hemisphere.
// Pass 0: a texel keeps the nearest bounce point (16 bits of depth above 16
// bits of (point, the side of it seen), one atomicMin). Pass 1: among the
// points on the nearest one's surface, a random one, drawn in proportion to
// the solid angle it spans (cos/d²; an exponential race): the nearest alone
// would favour the near end of every surface a texel sees obliquely.
#include "common.glsl"

layout(push_constant) uniform Params {
  uint receivers;
  uint emitters;       // bounce points
  uint size;           // map resolution
  float depth_scale;   // depth units per scene unit (about 65000 over the diagonal)
  uint pass;           // 0: nearest; 1: a draw among the nearest surface's points
  float radius;        // a bounce point's share of the surface, as a disk's radius
} params;

layout(std430, binding = 0) readonly buffer Receivers { vec4 receivers[]; };  // 2 per receiver: position, side's normal
layout(std430, binding = 1) readonly buffer Emitters { vec4 emitters[]; };    // 2 per bounce point: position, normal (w: open sides)
layout(std430, binding = 2) buffer Nearest { uint nearest[]; };
layout(std430, binding = 3) buffer Drawn { uint drawn[]; };

void main() {
  uint id = thread_id();
  if (id >= params.receivers * params.emitters) return;
  uint r = id / params.emitters, m = id % params.emitters;
  vec4 normal = receivers[2u * r + 1u];
  if (normal.w == 0.0) return;  // a side inside a solid gathers nothing
  vec3 origin = receivers[2u * r].xyz, n = normal.xyz;
  vec3 q = emitters[2u * m].xyz, nq = emitters[2u * m + 1u].xyz;
  vec3 w = q - origin;
  float len = length(w);
  float z = dot(w, n);
  // Points in the receiver's own plane (its own surface) are not in its hemisphere.
  if (!(len > 0.0) || z <= 1e-3 * len) return;
  vec3 t, b;
  basis_around(n, t, b);
  // The point stands for a disk of its share of the area: it covers the
  // texels within 0.7 of that disk's angular radius, at most 3 texels either
  // way, so a near surface leaves few holes (the rest are filled on the CPU:
  // GatherRows::append). Larger disks let near points take whole texels
  // beyond their share: at 1.5 radii the furnished room's later bounces
  // were 42% D̄ off Embree's, at 0.7 16%, at 0.5 13% with 1.7% of the
  // light lost to holes in the 5.8 cube at ρ 0.95.
  vec2 uv = vec2(dot(w, t), dot(w, b)) / (len + z);
  vec2 centre = (uv * 0.5 + 0.5) * float(params.size);
  float reach = 0.7 * params.radius / len * (1.0 + dot(uv, uv)) * float(params.size) / 4.0;
  int span = min(int(ceil(reach)), 3);
  float facing = dot(nq, w);
  uint side = facing < 0.0 ? 0u : 1u;  // the side of q that faces the receiver
  // A side inside a solid is never seen (the solid's own faces are in
  // front): splatting it would let the maps' gaps show dark insides.
  if ((uint(emitters[2u * m + 1u].w) & (1u << side)) == 0u) return;
  uint self = 2u * m + side;
  uint depth = min(uint(len * params.depth_scale), 65534u);
  // Pass 1: a key for an exponential race weighted by the solid angle.
  float solid_angle = abs(facing) / (len * len * len);
  float u = (float(hash_u32(id * 2654435761u + r)) + 0.5) / 4294967296.0;
  uint coded = uint(clamp((log2(-log(u) / max(solid_angle, 1e-30)) + 96.0) * 256.0, 0.0, 65534.0));
  ivec2 home = clamp(ivec2(centre), ivec2(0), ivec2(int(params.size) - 1));
  for (int dy = -span; dy <= span; ++dy)
    for (int dx = -span; dx <= span; ++dx) {
      ivec2 texel = home + ivec2(dx, dy);
      if (texel.x < 0 || texel.y < 0 || texel.x >= int(params.size) || texel.y >= int(params.size)) continue;
      if ((dx != 0 || dy != 0) && length(vec2(texel) + 0.5 - centre) > reach + 0.5) continue;
      uint at = r * params.size * params.size + uint(texel.y) * params.size + uint(texel.x);
      if (params.pass == 0u) {
        atomicMin(nearest[at], (depth << 16) | self);
        continue;
      }
      uint first = nearest[at] & 0xffffu;
      vec3 p0 = emitters[2u * (first / 2u)].xyz, n0 = emitters[2u * (first / 2u) + 1u].xyz;
      // On the nearest point's surface: the same side of a parallel plane through it.
      if ((first & 1u) != side || dot(n0, nq) < 0.99 || abs(dot(n0, q - p0)) > 2e-3 * len) continue;
      atomicMin(drawn[at], (coded << 16) | self);
    }
}
