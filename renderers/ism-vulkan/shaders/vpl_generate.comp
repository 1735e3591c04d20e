#version 450
#extension GL_GOOGLE_include_directive : require
// Virtual point lights: each light sends `vpls` directions, evenly spread
// over its emission cap (a Fibonacci spiral: the sphere for a point light,
// the cone for a spot), and finds the first surface in its cube ID map. A VPL
// re-emits that surface's reflected share: radiant intensity power·cos θ.
layout(std430, binding = 5) readonly buffer Profiles { float profiles[]; };
#define HILIGHT_PROFILES
#include "common.glsl"

layout(push_constant) uniform Params {
  uint lights;
  uint vpls;     // per light
  uint size;     // cube face resolution
  uint seed;
  float lift;    // VPLs sit this far off their surface (scene units)
} params;

layout(std430, binding = 0) readonly buffer Lights { Light lights[]; };
layout(std430, binding = 1) readonly buffer Triangles { uint triangles[]; };
layout(std430, binding = 2) readonly buffer Corners { float corners[]; };
layout(std430, binding = 3) readonly buffer TriangleAlbedo { vec4 triangle_albedo[]; };
// Per VPL (VPL_STRIDE vec4s): position (w: 1 = valid), normal, power, and the
// basis of its hemisphere (tangent, bitangent), computed once here.
layout(std430, binding = 4) writeonly buffer Vpls { vec4 vpls[]; };

vec3 corner(uint t, uint k) {
  uint o = (3u * t + k) * 3u;
  return vec3(corners[o], corners[o + 1u], corners[o + 2u]);
}

void main() {
  uint id = thread_id();
  if (id >= params.lights * params.vpls) return;
  uint c = id / params.vpls, k = id % params.vpls;
  Light light = lights[c];
  vec3 axis = light.cone.z != 0.0 ? light.direction.xyz : vec3(0.0, 1.0, 0.0);
  float cos_max = light.cone.z != 0.0 ? light.cone.x : -1.0;
  float cos_theta = 1.0 - (1.0 - cos_max) * (float(k) + 0.5) / float(params.vpls);
  float sin_theta = sqrt(max(1.0 - cos_theta * cos_theta, 0.0));
  // Random numbers keyed by the light itself, not its place in the batch: a
  // light gets the same VPLs alone or beside others (superposition holds).
  uint light_key = params.seed;
  for (int a = 0; a < 3; ++a)
    light_key = hash_u32(light_key ^ floatBitsToUint(light.position[a])) ^ hash_u32(floatBitsToUint(light.direction[a]) + 0x9e3779b9u);
  light_key = hash_u32(light_key ^ floatBitsToUint(light.cone.x) ^ hash_u32(floatBitsToUint(light.cone.y)));
  float rotation = float(light_key & 0xffffu) / 65536.0;
  float phi = 2.0 * PI * fract(float(k) * 0.61803398875 + rotation);
  vec3 t, b;
  basis_around(axis, t, b);
  vec3 dir = normalize(sin_theta * cos(phi) * t + sin_theta * sin(phi) * b + cos_theta * axis);

  for (uint k = 0u; k < VPL_STRIDE; ++k) vpls[VPL_STRIDE * id + k] = vec4(0.0);
  uint f = cube_face(dir);
  ivec2 texel = clamp(ivec2(cube_texel(dir, f, params.size)), ivec2(0), ivec2(int(params.size) - 1));
  uint index = (c * 6u + f) * params.size * params.size + uint(texel.y) * params.size + uint(texel.x);
  uint hit = triangles[index];
  if (hit == 0u) return;
  uint tri = hit - 1u;
  vec3 a = corner(tri, 0u), e1 = corner(tri, 1u) - a, e2 = corner(tri, 2u) - a;
  vec3 n = cross(e1, e2);
  if (dot(n, n) == 0.0) return;
  n = normalize(n);
  if (dot(n, dir) > 0.0) n = -n;  // the lit side faces the light
  // The hit on that triangle's plane along this exact direction (a grazing
  // hit carries almost no power: skipped).
  float denom = dot(n, dir);
  if (denom > -1e-3) return;
  float dist = dot(n, a - light.position.xyz) / denom;
  if (!(dist > 0.0)) return;
  float solid_angle = 2.0 * PI * (1.0 - cos_max) / float(params.vpls);
  vec3 power = triangle_albedo[tri].rgb * (solid_angle * spot_factor(light, dir) / PI);
  vec3 tangent, bitangent;
  basis_around(n, tangent, bitangent);
  vpls[VPL_STRIDE * id] = vec4(light.position.xyz + dir * dist + n * params.lift, 1.0);
  vpls[VPL_STRIDE * id + 1u] = vec4(n, 0.0);
  // w: this VPL's own key, which picks its ISM points (ism_splat.comp).
  vpls[VPL_STRIDE * id + 2u] = vec4(power, float(hash_u32(light_key ^ (k + 1u)) & 0xffffffu));  // exact in a float
  vpls[VPL_STRIDE * id + 3u] = vec4(tangent, 0.0);
  vpls[VPL_STRIDE * id + 4u] = vec4(bitangent, 0.0);
}
