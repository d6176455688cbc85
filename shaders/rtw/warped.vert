// Warped shadow-map rendering without tessellation: each vertex moves by the warp, edges
// stay straight (the artifact tessellation fixes).
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_lightViewProj;
out vec2 v_uv;
#include "rtw/warp.glsl"

void main() {
  v_uv = a_uv;
  gl_Position = warpClip(u_lightViewProj * vec4(a_position, 1.0));
}
