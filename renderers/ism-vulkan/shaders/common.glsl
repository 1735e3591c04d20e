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
  vec4 direction;  // xyz (spots)
  vec4 cone;       // x: cos cutoff, y: cos of the full-intensity core, z: 1 for a spot
};

// The spot's angular factor toward unit direction `to_point`: smoothstep in
// the cosine between the cone's edge and its core (docs/rendering-model.md).
float spot_factor(Light light, vec3 to_point) {
  if (light.cone.z == 0.0) return 1.0;
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
