// Warped rendering with tessellation ("non-linear rasterization", seed 000): pass world
// positions through; the evaluation shader warps every generated vertex.
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
out vec3 vc_worldPos;
out vec2 vc_uv;

void main() {
  vc_worldPos = a_position;
  vc_uv = a_uv;
}
