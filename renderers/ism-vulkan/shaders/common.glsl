// Shared by the compute shaders: thread numbering, cube-map faces, lights,
// the VPL hemisphere's basis and its paraboloid mapping.
layout(constant_id = 0) const uint WORKGROUP = 64;
layout(local_size_x_id = 0) in;

const float PI = 3.14159265358979;
const uint VPL_STRIDE = 5u;  // vec4s per VPL (vpl_generate.comp)

// One number per thread over a 1D or 2D grid of work groups.
uint thread_id() {
  return gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * WORKGROUP;
}

// Cube faces (must match ism_geometry.cpp): forward, right, up; right x up = forward.
const vec3 FACE_FORWARD[6] = vec3[](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0), vec3(0, 0, 1), vec3(0, 0, -1));
const vec3 FACE_RIGHT[6] = vec3[](vec3(0, 0, -1), vec3(0, 0, 1), vec3(1, 0, 0), vec3(1, 0, 0), vec3(1, 0, 0), vec3(-1, 0, 0));
const vec3 FACE_UP[6] = vec3[](vec3(0, 1, 0), vec3(0, 1, 0), vec3(0, 0, -1), vec3(0, 0, 1), vec3(0, 1, 0), vec3(0, 1, 0));

uint cube_face(vec3 d) {
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x > 0.0 ? 0u : 1u;
  if (a.y >= a.z) return d.y > 0.0 ? 2u : 3u;
  return d.z > 0.0 ? 4u : 5u;
}

// Continuous texel coordinates of direction d on face f of a size x size map
// (texel centres at +0.5), as the raster's projection places them.
vec2 cube_texel(vec3 d, uint f, uint size) {
  float z = dot(d, FACE_FORWARD[f]);
  vec2 ndc = vec2(dot(d, FACE_RIGHT[f]), dot(d, FACE_UP[f])) / z;
  return (ndc * 0.5 + 0.5) * float(size);
}

struct Light {
  vec4 position;   // xyz
  vec4 direction;  // xyz (spots; a luminaire's nadir), w: a luminaire's least measured γ
  vec4 cone;       // x: cos cutoff, y: cos of the full-intensity core, z: 1 for a spot, 2 for a luminaire
  vec4 c0;         // a luminaire's C = 0 axis; w: its profile table's offset in `profiles`
  vec4 c90;        // a luminaire's C = 90 axis, w: its largest measured γ (dark beyond, as the file says)
};

// Luminaire profiles, resampled on the CPU (ism_renderer.cpp) to candela over
// the peak on a regular grid: C every 5° (0–360, 73 planes), γ every 2.5°
// (0–180, 73 angles). Shaders that evaluate lights declare the buffer
// `profiles` and define HILIGHT_PROFILES before including this file.
const uint PROFILE_C = 73u, PROFILE_G = 73u;
#ifdef HILIGHT_PROFILES
float profile_factor(Light light, vec3 to_point) {
  float gamma = degrees(acos(clamp(dot(to_point, light.direction.xyz), -1.0, 1.0)));
  if (gamma < light.direction.w - 1e-4 || gamma > light.c90.w + 1e-4) return 0.0;
  float c = degrees(atan(dot(to_point, light.c90.xyz), dot(to_point, light.c0.xyz)));
  if (c < 0.0) c += 360.0;
  float fc = clamp(c / 5.0, 0.0, float(PROFILE_C - 1u)), fg = clamp(gamma / 2.5, 0.0, float(PROFILE_G - 1u));
  uint ic = min(uint(fc), PROFILE_C - 2u), ig = min(uint(fg), PROFILE_G - 2u);
  float tc = fc - float(ic), tg = fg - float(ig);
  uint base = uint(light.c0.w);
  float a = profiles[base + ic * PROFILE_G + ig], b = profiles[base + ic * PROFILE_G + ig + 1u];
  float d = profiles[base + (ic + 1u) * PROFILE_G + ig], e = profiles[base + (ic + 1u) * PROFILE_G + ig + 1u];
  return mix(mix(a, b, tg), mix(d, e, tg), tc);
}
#endif

// The light's angular factor toward unit direction `to_point`: 1 for a point
// light; a spot's smoothstep in the cosine between the cone's edge and its
// core; a luminaire's profile (docs/rendering-model.md).
float spot_factor(Light light, vec3 to_point) {
  if (light.cone.z == 0.0) return 1.0;
#ifdef HILIGHT_PROFILES
  if (light.cone.z == 2.0) return profile_factor(light, to_point);
#endif
  float c = dot(light.direction.xyz, to_point);
  if (c < light.cone.x) return 0.0;
  if (c >= light.cone.y) return 1.0;
  float t = (c - light.cone.x) / (light.cone.y - light.cone.x);
  return t * t * (3.0 - 2.0 * t);
}

// An orthonormal basis around unit n (Duff et al. 2017), the same everywhere.
void basis_around(vec3 n, out vec3 t, out vec3 b) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float c = n.x * n.y * a;
  t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

// Paraboloid map of the hemisphere around n (local z): the point seen in
// direction w (not unit, length len) lands at texel (size x size).
ivec2 paraboloid_texel(vec3 local, float len, uint size) {
  vec2 uv = local.xy / (len + local.z);  // the unit disk
  ivec2 texel = ivec2((uv * 0.5 + 0.5) * float(size));
  return clamp(texel, ivec2(0), ivec2(int(size) - 1));
}

uint hash_u32(uint x) {
  x ^= x >> 16; x *= 0x7feb352du;
  x ^= x >> 15; x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// Distance along the ray o + t·dir (dir unit) to triangle (a, b, c), or -1
// when the ray misses it (Möller–Trumbore; edges count as hits, so a ray
// through a shared edge cannot slip between two triangles).
float ray_triangle(vec3 o, vec3 dir, vec3 a, vec3 b, vec3 c) {
  vec3 e1 = b - a, e2 = c - a;
  vec3 pv = cross(dir, e2);
  float det = dot(e1, pv);
  if (abs(det) < 1e-12) return -1.0;
  float inv = 1.0 / det;
  vec3 tv = o - a;
  float u = dot(tv, pv) * inv;
  if (u < -1e-6 || u > 1.0 + 1e-6) return -1.0;
  vec3 qv = cross(tv, e1);
  float v = dot(dir, qv) * inv;
  if (v < -1e-6 || u + v > 1.0 + 1e-6) return -1.0;
  return dot(e2, qv) * inv;
}
