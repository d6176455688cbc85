// Cube shadow map, one face per pass (CubeShadowMap, cube.layered = 0): world -> the face's
// clip space, and the position relative to the light for cube/distance.frag (interpolated
// as in the layered pass: the two modes store the same maps).
#include "cube/distance.glsl"
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_lightViewProj;  // the face's world -> clip (omni::CubeFit::viewProj)
out vec2 v_uv;
out vec3 v_fromLight;

void main() {
  v_uv = a_uv;
  v_fromLight = a_position - u_cubeLightPos;
  gl_Position = u_lightViewProj * vec4(a_position, 1.0);
}
