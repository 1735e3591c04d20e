#version 450
#extension GL_GOOGLE_include_directive : require
// Direct light: each (light, point) pair looks up the light's cube ID map
// around the direction to the point; the triangles found in the 2x2 texels
// there, and their edge neighbours, are the candidate occluders, and the
// exact ray from the light to the point is intersected with each. (The
// neighbours matter: a texel centre shows one triangle of a tessellated
// face, and the ray may cross that face in the next one.) The faces touching
// the point are candidates too. The map is an acceleration structure, not
// an approximation of depth: no depth bias, no acne, exact shadows wherever
// an occluder covers a texel centre near the ray. Writes ρ/π·E.
layout(std430, binding = 9) readonly buffer Profiles { float profiles[]; };
#define HILIGHT_PROFILES
#include "common.glsl"

layout(push_constant) uniform Params {
  uint points;
  uint lights;
  uint size;      // cube face resolution
  float epsilon;  // scene units: rays start this far off the surface
} params;

layout(std430, binding = 0) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = 1) readonly buffer Normals { vec4 normals[]; };
layout(std430, binding = 2) readonly buffer Albedo { vec4 albedo[]; };
layout(std430, binding = 3) readonly buffer Lights { Light lights[]; };
layout(std430, binding = 4) readonly buffer Triangles { uint triangles[]; };
layout(std430, binding = 5) readonly buffer Corners { float corners[]; };
layout(std430, binding = 6) readonly buffer Neighbours { uint neighbours[]; };  // 3 per triangle; ~0u = none
const uint CREASE_CANDIDATES = 16u;
// Texels looked up around the ray's direction, per side: on curved models a
// texel shows a triangle or two away from the one the exact ray crosses.
const int WINDOW = 4;  // as kCreaseCandidates in crease_candidates.hpp
layout(std430, binding = 7) readonly buffer Crease { uint crease[]; };  // per point; ~0u = none
layout(std430, binding = 8) writeonly buffer Out { vec4 result[]; };
// A bit per (light, point): the point's own wedge blocks the light (ray_scene.hpp: in_own_wedge).
layout(std430, binding = 10) readonly buffer Wedge { uint wedge[]; };

vec3 corner(uint t, uint k) {
  uint o = (3u * t + k) * 3u;
  return vec3(corners[o], corners[o + 1u], corners[o + 2u]);
}

// Blocks if hit between the light (beyond 2ε of it) and the lifted point:
// the same segment as Embree's shadow ray from the point.
bool blocks_triangle(uint t, vec3 origin, vec3 dir, float reach) {
  float d = ray_triangle(origin, dir, corner(t, 0u), corner(t, 1u), corner(t, 2u));
  return d > 2.0 * params.epsilon && d < reach;
}

// Does triangle `hit` (+1; 0 = none), or one of its neighbours, block the ray before `reach`?
bool blocks(uint hit, vec3 origin, vec3 dir, float reach) {
  if (hit == 0u) return false;
  uint t = hit - 1u;
  if (blocks_triangle(t, origin, dir, reach)) return true;
  for (uint k = 0u; k < 3u; ++k) {
    uint m = neighbours[3u * t + k];
    if (m != ~0u && blocks_triangle(m, origin, dir, reach)) return true;
  }
  return false;
}

void main() {
  uint id = thread_id();
  if (id >= params.points * params.lights) return;
  uint c = id / params.points, i = id % params.points;
  Light light = lights[c];
  vec3 p = positions[i].xyz, n = normals[i].xyz;
  vec3 d = p - light.position.xyz;
  float dist = length(d);
  vec3 response = vec3(0.0);
  if (dist > params.epsilon) {
    vec3 to_point = d / dist;
    float cos_n = abs(dot(n, to_point));
    float angular = spot_factor(light, to_point);
    bool in_wedge = (wedge[(c / 32u) * params.points + i] & (1u << (c % 32u))) != 0u;
    if (cos_n > 0.0 && angular > 0.0 && !in_wedge) {
      // The ray ends where Embree's starts (ShadingPoint::ray_start): a smooth
      // point's ray stops ε short of it (its own facets never shadow it);
      // another's ends a hair off the surface, on the light's side.
      bool on_smooth = positions[i].w > 0.5;
      vec3 side = dot(n, to_point) < 0.0 ? n : -n;
      vec3 q = on_smooth ? p : p + side * params.epsilon;
      vec3 dq = q - light.position.xyz;
      float reach = on_smooth ? length(dq) - params.epsilon : length(dq);
      vec3 dir = dq / length(dq);
      uint f = cube_face(dq);
      ivec2 t0 = ivec2(floor(cube_texel(dq, f, params.size) - 0.5)) - ivec2(WINDOW / 2 - 1);
      uint base = (c * 6u + f) * params.size * params.size;
      bool shadowed = false;
      for (int k = 0; k < WINDOW * WINDOW && !shadowed; ++k) {
        ivec2 t = clamp(t0 + ivec2(k % WINDOW, k / WINDOW), ivec2(0), ivec2(int(params.size) - 1));
        shadowed = blocks(triangles[base + uint(t.y) * params.size + uint(t.x)], light.position.xyz, dir, reach);
      }
      // The faces near the point, and their edge neighbours: at a crease the
      // blocking face may be a sliver seen edge-on, thinner than a texel
      // (crease_candidates.hpp); on a curved surface a ray that grazes it
      // enters it a triangle or two from the point, where a texel near that
      // direction may show another triangle.
      // A smooth point's ray that grazes into its own solid (the light a
      // little behind its tangent plane) enters it up to a few triangles
      // away: there the ring beyond the neighbours is tested too.
      bool grazing_in = on_smooth && dot(n, to_point) > 0.0 && dot(n, to_point) < 0.3;
      for (uint k = 0u; k < CREASE_CANDIDATES && !shadowed; ++k) {
        uint m = crease[CREASE_CANDIDATES * i + k];
        if (m == ~0u) break;
        shadowed = blocks(m + 1u, light.position.xyz, dir, reach);
        for (uint e = 0u; e < 3u && grazing_in && !shadowed; ++e) {
          uint o = neighbours[3u * m + e];
          if (o != ~0u) shadowed = blocks(o + 1u, light.position.xyz, dir, reach);
        }
      }
      if (!shadowed) response = albedo[i].rgb * (cos_n * angular / (dist * dist * PI));
    }
  }
  result[id] = vec4(response, 0.0);
}
