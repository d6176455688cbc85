// Dual-paraboloid depth pass, fragment stage: EXACT depth (the RTW idea, rtw/warped_exact.frag):
// the depth interpolated across a mapped triangle is wrong inside it, because the mapping is
// not linear; the distance along the texel centre's own direction to the triangle's plane
// is right whatever the tessellation, which then only shapes the coverage at silhouettes.
#include "common/material.glsl"
#include "dual-paraboloid/paraboloid.glsl"
in vec2 v_uv;
flat in vec4 v_plane;  // dot(xyz, X) + w = 0, world
uniform int u_dpHalfIndex;
uniform float u_mapTexels;

void main() {
  if (materialAlphaRejectsLevel0(v_uv)) discard;
  vec3 dir = dpDirection(u_dpHalfIndex, gl_FragCoord.xy / u_mapTexels);
  vec3 N = v_plane.xyz;
  float t = dot(N, N) > 0.0 ? omniPlaneDistance(dir, -v_plane.w * N, N) : -1.0;
  gl_FragDepth = t > 0.0 ? clamp(omniStoredDistance(t), 0.0, 1.0) : gl_FragCoord.z;
}
