// The dual paraboloid's mapping in GLSL (CPU: omni::paraboloidUv, omni::paraboloidDirection;
// Brabec, Annen, Seidel 2002): hemisphere 0 looks along u_omniAxis, hemisphere 1 along -axis
// (rotated 180° about u_omniX); p = (x, y) / (1 + z) in the hemisphere's frame, uv = 0.5 + 0.5 p.
// The light, frame and depth range: common/omni/frame.glsl.
#include "common/omni/frame.glsl"

// World direction -> the hemisphere's frame (any length kept).
vec3 dpLocal(int hemi, vec3 d) {
  vec3 l = omniLocal(d);
  return hemi == 0 ? l : vec3(l.x, -l.y, -l.z);
}
int dpHalf(vec3 d) { return dot(d, u_omniAxis) >= 0.0 ? 0 : 1; }
vec2 dpUv(int hemi, vec3 d) {
  vec3 l = dpLocal(hemi, normalize(d));
  return 0.5 + 0.5 * l.xy / (1.0 + l.z);
}
// The unit world direction through uv of hemisphere `hemi`.
vec3 dpDirection(int hemi, vec2 uv) {
  vec2 p = 2.0 * uv - 1.0;
  float r2 = dot(p, p);
  float z = (1.0 - r2) / (1.0 + r2);
  vec3 l = vec3(p * (1.0 + z), z);
  if (hemi == 1) l = vec3(l.x, -l.y, -l.z);
  return normalize(l.x * u_omniX + l.y * u_omniY + l.z * u_omniAxis);
}
