#version 450
#extension GL_GOOGLE_include_directive : require
// Direct light: each (light, point) pair looks up the light's cube distance
// map with 2x2 percentage-closer filtering; writes the unit response ρ/π·E.
#include "common.glsl"

layout(push_constant) uniform Params {
  uint points;
  uint lights;
  uint size;          // cube face resolution
  float bias_texels;  // normal offset, in texels
  float bias_const;   // constant bias, scene units
} params;

layout(std430, binding = 0) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = 1) readonly buffer Normals { vec4 normals[]; };
layout(std430, binding = 2) readonly buffer Albedo { vec4 albedo[]; };
layout(std430, binding = 3) readonly buffer Lights { Light lights[]; };
layout(std430, binding = 4) readonly buffer Distances { float distances[]; };
layout(std430, binding = 5) writeonly buffer Out { vec4 result[]; };

float lit(uint base, ivec2 texel, float dist, float bias) {
  ivec2 t = clamp(texel, ivec2(0), ivec2(int(params.size) - 1));
  return dist - bias <= distances[base + uint(t.y) * params.size + uint(t.x)] ? 1.0 : 0.0;
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
  if (dist > 0.0) {
    vec3 to_point = d / dist;
    float cos_n = abs(dot(n, to_point));
    float angular = spot_factor(light, to_point);
    if (cos_n > 0.0 && angular > 0.0) {
      // Normal offset: the map is looked up from the point lifted toward the
      // light's side by a few texels' width, which clears the surface's own
      // depth at any angle (a texel spans about 2/size radians).
      vec3 side = dot(n, to_point) < 0.0 ? n : -n;
      vec3 q = p + side * (dist * 2.0 / float(params.size) * params.bias_texels);
      vec3 dq = q - light.position.xyz;
      float dist_q = length(dq);
      uint f = cube_face(dq);
      vec2 t = cube_texel(dq, f, params.size) - 0.5;
      ivec2 t0 = ivec2(floor(t));
      vec2 w = t - vec2(t0);
      float bias = params.bias_const;
      uint base = (c * 6u + f) * params.size * params.size;
      float v = mix(mix(lit(base, t0, dist_q, bias), lit(base, t0 + ivec2(1, 0), dist_q, bias), w.x),
                    mix(lit(base, t0 + ivec2(0, 1), dist_q, bias), lit(base, t0 + ivec2(1, 1), dist_q, bias), w.x), w.y);
      response = albedo[i].rgb * (cos_n * angular * v / (dist * dist * PI));
    }
  }
  result[id] = vec4(response, 0.0);
}
