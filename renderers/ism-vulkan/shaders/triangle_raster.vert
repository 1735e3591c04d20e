#version 450
// Triangle raster, vertex stage: the scene's vertices in world space, drawn
// indexed (the fragment stage names the triangle).
layout(location = 0) in vec3 position;
layout(push_constant) uniform View {
  mat4 view_projection;
  uint first_triangle;
} view;

void main() {
  gl_Position = view.view_projection * vec4(position, 1.0);
}
