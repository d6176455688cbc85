// The warped shadow map as seed 002 renders it (warp.depth = interpolated; C++:
// RtwShadowMap::renderWarped; CPU reference: sl::rtw::rasterizeWarpedInterpolated): the
// vertex shader moves every vertex of the scene's triangles by the warp, and the
// rasteriser interpolates depth linearly between the warped vertices. Edges stay straight
// in warped space and depth is wrong inside long triangles (see warped_exact.frag).
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_lightViewProj;
out vec2 v_uv;
#include "rtw/warp.glsl"

void main() {
  v_uv = a_uv;
  gl_Position = warpClip(u_lightViewProj * vec4(a_position, 1.0));
}
