#version 450
// Triangle raster, fragment stage: which scene triangle is nearest the eye
// (a light or a camera) in each texel, +1 (0 = nothing). Distances are not
// stored: the compute stages intersect their exact rays with that triangle.
layout(push_constant) uniform View {
  mat4 view_projection;
  uint first_triangle;  // where this draw's entries start in `triangle_ids`
} view;
// The scene triangle each drawn triangle is (a draw may hold a culled subset).
layout(std430, set = 0, binding = 0) readonly buffer TriangleIds { uint triangle_ids[]; };
layout(location = 0) out uint triangle_out;

void main() {
  triangle_out = triangle_ids[view.first_triangle + uint(gl_PrimitiveID)] + 1u;
}
