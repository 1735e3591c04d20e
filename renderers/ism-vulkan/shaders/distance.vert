#version 450
// Distance raster, vertex stage: triangle corners in world space (three per
// triangle, not indexed, so the triangle's number is gl_VertexIndex / 3).
layout(location = 0) in vec3 position;
layout(push_constant) uniform View {
  mat4 view_projection;
  vec4 eye;
} view;
layout(location = 0) out vec3 world;
layout(location = 1) flat out uint triangle;

void main() {
  world = position;
  triangle = uint(gl_VertexIndex) / 3u;
  gl_Position = view.view_projection * vec4(position, 1.0);
}
