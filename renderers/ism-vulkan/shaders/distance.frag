#version 450
// Distance raster, fragment stage: distance from the eye (a light or a camera)
// to the nearest surface, and which triangle it is (+1; 0 = nothing).
layout(location = 0) in vec3 world;
layout(push_constant) uniform View {
  mat4 view_projection;
  vec4 eye;
} view;
layout(location = 0) out float distance_out;
layout(location = 1) out uint triangle_out;

void main() {
  distance_out = length(world - view.eye.xyz);
  triangle_out = uint(gl_PrimitiveID) + 1u;
}
