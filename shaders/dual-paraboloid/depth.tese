// Dual-paraboloid depth pass, evaluation stage: each tessellated vertex through the issue's
// mapping in light view space: L = |p|, p /= L, (x, y) /= (z + 1), z = (L - near) / (far -
// near), w = 1 (CPU: omni::paraboloidUv). Clipped a little past the hemisphere's rim
// (z > -0.05) so rim texels are covered; texels beyond the disc are never looked up.
#include "dual-paraboloid/paraboloid.glsl"
layout(triangles, equal_spacing, ccw) in;
in vec3 te_worldPos[];
in vec2 te_uv[];
out vec2 v_uv;
flat out vec4 v_plane;  // the triangle's world plane (tp_plane), for exact depth
patch in vec4 tp_plane;
uniform int u_dpHalfIndex;

void main() {
  vec3 b = gl_TessCoord;
  vec3 P = b.x * te_worldPos[0] + b.y * te_worldPos[1] + b.z * te_worldPos[2];
  v_uv = b.x * te_uv[0] + b.y * te_uv[1] + b.z * te_uv[2];
  v_plane = tp_plane;
  vec3 d = P - u_omniLight;
  float L = max(length(d), 1e-9);
  vec3 l = dpLocal(u_dpHalfIndex, d / L);
  gl_ClipDistance[0] = l.z + 0.05;
  vec2 p = l.xy / max(1.0 + l.z, 1e-3);
  gl_Position = vec4(p, omniStoredDistance(L) * 2.0 - 1.0, 1.0);
}
