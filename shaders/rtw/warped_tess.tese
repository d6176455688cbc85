// Interpolate the world position linearly, then warp: long edges bend with the warp.
layout(triangles, equal_spacing, ccw) in;
in vec3 te_worldPos[];
in vec2 te_uv[];
out vec2 v_uv;
uniform mat4 u_lightViewProj;
#include "rtw/warp.glsl"

void main() {
  vec3 b = gl_TessCoord;
  vec3 p = b.x * te_worldPos[0] + b.y * te_worldPos[1] + b.z * te_worldPos[2];
  v_uv = b.x * te_uv[0] + b.y * te_uv[1] + b.z * te_uv[2];
  gl_Position = warpClip(u_lightViewProj * vec4(p, 1.0));
}
