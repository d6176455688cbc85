// Dual-paraboloid depth pass, vertex stage: world positions to the tessellation stages
// (DualParaboloidShadowMap::renderShadows), which map them per tessellated vertex.
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
out vec3 vc_worldPos;
out vec2 vc_uv;

void main() {
  vc_worldPos = a_position;
  vc_uv = a_uv;
}
