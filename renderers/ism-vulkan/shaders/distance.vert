#version 450
// Distance raster, vertex stage: the scene's vertices in world space, drawn
// indexed (the fragment stage names the triangle by gl_PrimitiveID).
layout(location = 0) in vec3 position;
layout(push_constant) uniform View {
  mat4 view_projection;
  vec4 eye;
} view;
layout(location = 0) out vec3 world;

void main() {
  world = position;
  gl_Position = view.view_projection * vec4(position, 1.0);
}
