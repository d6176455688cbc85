// Tessellation level per edge from how much the warp BENDS it: the largest distance, in
// warped texels, between the warped edge and its straight chord at the quarter points.
// A curve's chord error falls as 1/k^2 with k segments, so the level is
// ceil(sqrt(deviation / u_toleranceTexels)), clamped to 1..64. Edges where the warp is
// nearly linear (most of them) stay whole; long edges across a strong warp bend.
layout(vertices = 3) out;
in vec3 vc_worldPos[];
in vec2 vc_uv[];
out vec3 te_worldPos[];
out vec2 te_uv[];
uniform mat4 u_lightViewProj;
uniform float u_toleranceTexels;
uniform vec2 u_smSize;
#include "rtw/warp.glsl"

vec2 lightUv(vec3 p) {
  vec4 c = u_lightViewProj * vec4(p, 1.0);
  return c.xy / c.w * 0.5 + 0.5;
}

// The bend is measured on the part of the edge inside the map (where the warp acts): an
// edge only partly inside needs its level scaled by 1 / (inside fraction) to give that part
// enough segments, since tessellation spaces vertices evenly along the whole edge.
float edgeLevel(vec3 a, vec3 b) {
  vec2 ua = lightUv(a), ub = lightUv(b);
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
  return clamp(ceil(sqrt(dev / u_toleranceTexels) / (t1 - t0)), 1.0, 64.0);
}

void main() {
  te_worldPos[gl_InvocationID] = vc_worldPos[gl_InvocationID];
  te_uv[gl_InvocationID] = vc_uv[gl_InvocationID];
  if (gl_InvocationID == 0) {
    // Outer level i is the edge opposite vertex i.
    float l0 = edgeLevel(vc_worldPos[1], vc_worldPos[2]);
    float l1 = edgeLevel(vc_worldPos[2], vc_worldPos[0]);
    float l2 = edgeLevel(vc_worldPos[0], vc_worldPos[1]);
    gl_TessLevelOuter[0] = l0;
    gl_TessLevelOuter[1] = l1;
    gl_TessLevelOuter[2] = l2;
    gl_TessLevelInner[0] = max(l0, max(l1, l2));
  }
}
