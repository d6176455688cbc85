// Forward / hybrid analysis: the scene from the light (unwarped) at IM resolution.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_lightViewProj;
out vec3 v_worldPos;
out vec3 v_worldNormal;
out vec2 v_uv;

void main() {
  v_worldPos = a_position;
  v_worldNormal = a_normal;
  v_uv = a_uv;
  gl_Position = u_lightViewProj * vec4(a_position, 1.0);
}
