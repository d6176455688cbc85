// Warped shadow-map rendering, control stage, once per scene triangle (C++:
// RtwShadowMap::renderWarped; CPU reference: sl::rtw::rasterizeWarpedDepth):
//  1. cull: a triangle wholly outside the light frustum's uv square makes nothing;
//  2. its planes in UNWARPED light space (window depth, texture coordinate), which the
//     fragment stage evaluates at each warped texel's unwarped centre: exact depth,
//     whatever the tessellation;
//  3. tessellation levels from how much the warp BENDS each edge: the largest distance, in
//     warped texels, between the warped edge and its straight chord at the quarter points.
//     A curve's chord error falls as 1/k^2 with k segments, so the level is
//     ceil(sqrt(deviation / u_toleranceTexels)), clamped to 1..SL_MAX_TESSELLATION_LEVEL. Depth no longer
//     depends on it: tessellation only shapes silhouettes (coverage).
#include "common/shared_constants.h"
layout(vertices = 3) out;
in vec3 vc_worldPos[];
in vec2 vc_uv[];
out vec3 te_worldPos[];
out vec2 te_uv[];
patch out vec4 tp_origin;  // xy: light uv of vertex 0; zw: window depth range (min, max)
patch out vec3 tp_depth;   // z(u, v) = x + y (u - u0) + z (v - v0)
patch out vec3 tp_s;       // texture coordinate s, same form
patch out vec3 tp_t;       // texture coordinate t
patch out float tp_valid;  // 0: seen edge-on by the light (no plane): interpolated depth
uniform mat4 u_lightViewProj;
uniform int u_tessOn;
uniform float u_toleranceTexels;
uniform vec2 u_smSize;
#include "rtw/warp.glsl"

vec3 lightUvz(vec3 p) { return (u_lightViewProj * vec4(p, 1.0)).xyz * 0.5 + 0.5; }

// The bend is measured on the part of the edge inside the map (where the warp acts): an
// edge only partly inside needs its level scaled by 1 / (inside fraction) to give that part
// enough segments, since tessellation spaces vertices evenly along the whole edge.
float edgeLevel(vec2 ua, vec2 ub) {
  vec2 d = ub - ua;
  float t0 = 0.0, t1 = 1.0;  // clip the parameter range to the unit square
  for (int k = 0; k < 2; ++k) {
    if (abs(d[k]) < 1e-12) {
      if (ua[k] < 0.0 || ua[k] > 1.0) return 1.0;
    } else {
      float s0 = (0.0 - ua[k]) / d[k], s1 = (1.0 - ua[k]) / d[k];
      t0 = max(t0, min(s0, s1));
      t1 = min(t1, max(s0, s1));
    }
  }
  if (t1 <= t0) return 1.0;
  vec2 ca = ua + t0 * d, cb = ua + t1 * d;
  vec2 ta = warpUv(ca) * u_smSize, tb = warpUv(cb) * u_smSize;
  float dev = 0.0;
  for (int q = 1; q <= 3; ++q) {
    float f = float(q) * 0.25;
    dev = max(dev, distance(warpUv(mix(ca, cb, f)) * u_smSize, mix(ta, tb, f)));
  }
  return clamp(ceil(sqrt(dev / u_toleranceTexels) / (t1 - t0)), 1.0, float(SL_MAX_TESSELLATION_LEVEL));
}

// f(u, v) = f0 + A (u - u0) + B (v - v0) through the three vertices (Cramer's rule).
vec3 planeOf(vec2 d1, vec2 d2, float det, float f0, float f1, float f2) {
  float a = ((f1 - f0) * d2.y - (f2 - f0) * d1.y) / det;
  float b = ((f2 - f0) * d1.x - (f1 - f0) * d2.x) / det;
  return vec3(f0, a, b);
}

void main() {
  te_worldPos[gl_InvocationID] = vc_worldPos[gl_InvocationID];
  te_uv[gl_InvocationID] = vc_uv[gl_InvocationID];
  if (gl_InvocationID != 0) return;
  vec3 p0 = lightUvz(vc_worldPos[0]), p1 = lightUvz(vc_worldPos[1]), p2 = lightUvz(vc_worldPos[2]);
  vec2 lo = min(p0.xy, min(p1.xy, p2.xy)), hi = max(p0.xy, max(p1.xy, p2.xy));
  if (any(greaterThan(lo, vec2(1.0))) || any(lessThan(hi, vec2(0.0)))) {
    gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = 0.0;
    gl_TessLevelInner[0] = 0.0;  // outside the light frustum: culled
    return;
  }
  vec2 d1 = p1.xy - p0.xy, d2 = p2.xy - p0.xy;
  float det = d1.x * d2.y - d2.x * d1.y;
  tp_valid = abs(det) > 1e-7 * (dot(d1, d1) + dot(d2, d2)) ? 1.0 : 0.0;
  if (tp_valid > 0.5) {
    tp_depth = planeOf(d1, d2, det, p0.z, p1.z, p2.z);
    tp_s = planeOf(d1, d2, det, vc_uv[0].x, vc_uv[1].x, vc_uv[2].x);
    tp_t = planeOf(d1, d2, det, vc_uv[0].y, vc_uv[1].y, vc_uv[2].y);
  } else {
    tp_depth = tp_s = tp_t = vec3(0.0);
  }
  tp_origin = vec4(p0.xy, min(p0.z, min(p1.z, p2.z)), max(p0.z, max(p1.z, p2.z)));
  // Outer level i is the edge opposite vertex i.
  float l0 = 1.0, l1 = 1.0, l2 = 1.0;
  if (u_tessOn != 0) {
    l0 = edgeLevel(p1.xy, p2.xy);
    l1 = edgeLevel(p2.xy, p0.xy);
    l2 = edgeLevel(p0.xy, p1.xy);
  }
  gl_TessLevelOuter[0] = l0;
  gl_TessLevelOuter[1] = l1;
  gl_TessLevelOuter[2] = l2;
  gl_TessLevelInner[0] = max(l0, max(l1, l2));
}
