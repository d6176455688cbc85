// Tessellation level per edge from the edge's length in the WARPED shadow map:
// ceil(length in texels / u_texelsPerSegment), clamped to 1..64.
layout(vertices = 3) out;
in vec3 vc_worldPos[];
in vec2 vc_uv[];
out vec3 te_worldPos[];
out vec2 te_uv[];
uniform mat4 u_lightViewProj;
uniform float u_texelsPerSegment;
uniform vec2 u_smSize;
#include "rtw/warp.glsl"

vec2 warpedTexel(vec3 p) {
  vec4 c = u_lightViewProj * vec4(p, 1.0);
  return warpUv(c.xy / c.w * 0.5 + 0.5) * u_smSize;
}

void main() {
  te_worldPos[gl_InvocationID] = vc_worldPos[gl_InvocationID];
  te_uv[gl_InvocationID] = vc_uv[gl_InvocationID];
  if (gl_InvocationID == 0) {
    vec2 t0 = warpedTexel(vc_worldPos[0]), t1 = warpedTexel(vc_worldPos[1]),
         t2 = warpedTexel(vc_worldPos[2]);
    // Outer level i is the edge opposite vertex i.
    float l0 = clamp(ceil(distance(t1, t2) / u_texelsPerSegment), 1.0, 64.0);
    float l1 = clamp(ceil(distance(t2, t0) / u_texelsPerSegment), 1.0, 64.0);
    float l2 = clamp(ceil(distance(t0, t1) / u_texelsPerSegment), 1.0, 64.0);
    gl_TessLevelOuter[0] = l0;
    gl_TessLevelOuter[1] = l1;
    gl_TessLevelOuter[2] = l2;
    gl_TessLevelInner[0] = max(l0, max(l1, l2));
  }
}
