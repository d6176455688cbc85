// Exact warped depth (C++: RtwShadowMap::renderWarped; CPU reference:
// sl::rtw::rasterizeWarpedDepth). The fragment sits at a warped texel centre; the inverse
// tables give that centre's unwarped light uv, where the triangle's plane gives the exact
// depth (and texture coordinate for alpha-tested casters). Interpolating depth in WARPED
// space, as plain rasterisation does, is wrong wherever the warp bends a triangle, by an
// amount that grows with the resolution. Clamped to the triangle's own depth range, so a
// silhouette fragment the straight warped edges cover by mistake cannot extrapolate far.
#include "common/material.glsl"
#include "rtw/warp.glsl"
in vec2 v_uv;
flat in vec4 f_origin;
flat in vec3 f_depth;
flat in vec3 f_s;
flat in vec3 f_t;
flat in float f_valid;
uniform int u_smRes;
uniform int u_interpolatedDepth;  // warp.depth = interpolated: the rasteriser's depth

void main() {
  if (u_interpolatedDepth != 0) {  // linear in warped space between the tessellated vertices
    if (materialAlphaRejectsLevel0(v_uv)) discard;
    gl_FragDepth = gl_FragCoord.z;  // the shader writes gl_FragDepth: every path must
    return;
  }
  vec2 d = inverseWarpCentre(ivec2(gl_FragCoord.xy), u_smRes) - f_origin.xy;
  bool plane = f_valid > 0.5;
  vec2 uv = plane ? vec2(f_s.x + dot(f_s.yz, d), f_t.x + dot(f_t.yz, d)) : v_uv;
  if (materialAlphaRejectsLevel0(uv)) discard;
  float z = plane ? f_depth.x + dot(f_depth.yz, d) : gl_FragCoord.z;
  gl_FragDepth = clamp(z, f_origin.z, f_origin.w);
}
