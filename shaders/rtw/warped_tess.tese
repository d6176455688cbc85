// Warped shadow-map rendering, evaluation stage: interpolate the world position linearly,
// then warp, so long edges bend with the warp (silhouettes); hand the patch's planes to
// the exact-depth fragment stage unchanged.
layout(triangles, equal_spacing, ccw) in;
in vec3 te_worldPos[];
in vec2 te_uv[];
patch in vec4 tp_origin;
patch in vec3 tp_depth;
patch in vec3 tp_s;
patch in vec3 tp_t;
patch in float tp_valid;
out vec2 v_uv;
flat out vec4 f_origin;
flat out vec3 f_depth;
flat out vec3 f_s;
flat out vec3 f_t;
flat out float f_valid;
uniform mat4 u_lightViewProj;
#include "rtw/warp.glsl"

void main() {
  vec3 b = gl_TessCoord;
  vec3 p = b.x * te_worldPos[0] + b.y * te_worldPos[1] + b.z * te_worldPos[2];
  v_uv = b.x * te_uv[0] + b.y * te_uv[1] + b.z * te_uv[2];
  f_origin = tp_origin;
  f_depth = tp_depth;
  f_s = tp_s;
  f_t = tp_t;
  f_valid = tp_valid;
  gl_Position = warpClip(u_lightViewProj * vec4(p, 1.0));
}
