// Dual-paraboloid depth pass, control stage, once per scene triangle: cull triangles wholly
// in the other hemisphere (the sign of the hemisphere's z is linear in world position), the
// triangle's world plane for exact depth, and tessellation levels from how far the mapping
// BENDS each edge (largest distance, in texels, between the mapped edge and its chord at the
// quarter points; chord error falls as 1/k^2: level ceil(sqrt(dev / u_toleranceTexels))).
// dp.tessellation off: level 1 (the edges stay straight in paraboloid space: the artifact).
#include "common/shared_constants.h"
#include "dual-paraboloid/paraboloid.glsl"
layout(vertices = 3) out;
in vec3 vc_worldPos[];
in vec2 vc_uv[];
out vec3 te_worldPos[];
out vec2 te_uv[];
patch out vec4 tp_plane;  // world plane: dot(xyz, X) + w = 0
uniform int u_dpHalfIndex;
uniform int u_tessOn;
uniform float u_toleranceTexels;
uniform float u_mapTexels;

vec2 mapped(vec3 P) { return dpUv(u_dpHalfIndex, P - u_omniLight) * u_mapTexels; }

float edgeLevel(vec3 a, vec3 b) {
  vec2 ta = mapped(a), tb = mapped(b);
  float dev = 0.0;
  for (int q = 1; q <= 3; ++q) {
    float f = float(q) * 0.25;
    dev = max(dev, distance(mapped(mix(a, b, f)), mix(ta, tb, f)));
  }
  return clamp(ceil(sqrt(dev / u_toleranceTexels)), 1.0, float(SL_MAX_TESSELLATION_LEVEL));
}

void main() {
  te_worldPos[gl_InvocationID] = vc_worldPos[gl_InvocationID];
  te_uv[gl_InvocationID] = vc_uv[gl_InvocationID];
  if (gl_InvocationID != 0) return;
  vec3 p0 = vc_worldPos[0], p1 = vc_worldPos[1], p2 = vc_worldPos[2];
  vec3 n = cross(p1 - p0, p2 - p0);
  float len = length(n);
  tp_plane = len > 0.0 ? vec4(n / len, -dot(n / len, p0)) : vec4(0.0);
  // Wholly in the other hemisphere (beyond the clip margin of the evaluation stage).
  float z0 = dpLocal(u_dpHalfIndex, normalize(p0 - u_omniLight)).z;
  float z1 = dpLocal(u_dpHalfIndex, normalize(p1 - u_omniLight)).z;
  float z2 = dpLocal(u_dpHalfIndex, normalize(p2 - u_omniLight)).z;
  if (z0 < -0.05 && z1 < -0.05 && z2 < -0.05) {
    gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = 0.0;
    gl_TessLevelInner[0] = 0.0;
    return;
  }
  float l0 = 1.0, l1 = 1.0, l2 = 1.0;
  if (u_tessOn != 0) {
    l0 = edgeLevel(p1, p2);
    l1 = edgeLevel(p2, p0);
    l2 = edgeLevel(p0, p1);
  }
  gl_TessLevelOuter[0] = l0;
  gl_TessLevelOuter[1] = l1;
  gl_TessLevelOuter[2] = l2;
  gl_TessLevelInner[0] = max(l0, max(l1, l2));
}
