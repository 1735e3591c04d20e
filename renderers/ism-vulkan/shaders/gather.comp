#version 450
#extension GL_GOOGLE_include_directive : require
// First bounce: each (light, point) pair sums the light's VPLs, each tested
// for visibility in its imperfect shadow map; adds ρ/π·E_ind to the result.
#include "common.glsl"

layout(push_constant) uniform Params {
  uint points;
  uint lights;
  uint vpls;         // per light
  uint size;         // ISM resolution
  float min_dist2;   // squared distances below this are clamped (VPL singularity)
  float bias_rel;    // ISM depth bias, relative to the distance
  float bias_const;  // ... plus this, scene units
} params;

layout(std430, binding = 0) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = 1) readonly buffer Normals { vec4 normals[]; };
layout(std430, binding = 2) readonly buffer Albedo { vec4 albedo[]; };
layout(std430, binding = 3) readonly buffer Vpls { vec4 vpls[]; };
layout(std430, binding = 4) readonly buffer Pyramid { float pyramid[]; };
layout(std430, binding = 5) buffer Out { vec4 result[]; };

void main() {
  uint id = thread_id();
  if (id >= params.points * params.lights) return;
  uint c = id / params.points, i = id % params.points;
  vec3 p = positions[i].xyz, n = normals[i].xyz;
  uint open_sides = uint(normals[i].w);  // bit 0: the side n points to faces free space; bit 1: the other
  vec3 irradiance = vec3(0.0);
  uint texels = params.size * params.size;
  for (uint k = 0u; k < params.vpls; ++k) {
    uint v = c * params.vpls + k;
    vec4 origin = vpls[VPL_STRIDE * v];
    if (origin.w == 0.0) continue;
    vec3 nv = vpls[VPL_STRIDE * v + 1u].xyz;
    vec3 w = p - origin.xyz;
    float d2 = dot(w, w);
    float len = sqrt(d2);
    float cos_out = dot(nv, w) / len;
    if (!(cos_out > 0.0)) continue;
    // The side of p that faces the VPL must be open (not inside a solid).
    if ((open_sides & (dot(n, w) < 0.0 ? 1u : 2u)) == 0u) continue;
    float cos_in = abs(dot(n, w)) / len;
    vec3 local = vec3(dot(w, vpls[VPL_STRIDE * v + 3u].xyz), dot(w, vpls[VPL_STRIDE * v + 4u].xyz), dot(w, nv));
    ivec2 texel = paraboloid_texel(local, len, params.size);
    float depth = pyramid[v * texels + uint(texel.y) * params.size + uint(texel.x)];
    // A texel spans about π/size radians; across it a surface seen at angle
    // acos(cos_in) changes depth by len·(π/size)/cos_in, and the texel keeps
    // the nearest splat: the bias grows with that slope.
    float slope = (PI / float(params.size)) / max(cos_in, 0.05);
    if (depth >= 0.0 && len > depth + len * (params.bias_rel + slope) + params.bias_const) continue;
    irradiance += vpls[VPL_STRIDE * v + 2u].rgb * (cos_out * cos_in / max(d2, params.min_dist2));
  }
  result[id] += vec4(albedo[i].rgb * irradiance / PI, 0.0);
}
