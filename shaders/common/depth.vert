// Depth-only light pass (uniform shadow map and friends): world -> light clip space.
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_lightViewProj;
out vec2 v_uv;

void main() {
  v_uv = a_uv;
  gl_Position = u_lightViewProj * vec4(a_position, 1.0);
}
