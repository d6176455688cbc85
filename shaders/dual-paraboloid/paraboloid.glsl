// The dual paraboloid's mapping in GLSL (CPU: omni::paraboloidUv, omni::paraboloidDirection;
// Brabec, Annen, Seidel 2002): hemisphere 0 looks along u_dpAxis, hemisphere 1 along -axis
// (rotated 180° about u_dpX); p = (x, y) / (1 + z) in the hemisphere's frame, uv = 0.5 + 0.5 p.
#include "common/light_distance.glsl"
uniform vec3 u_dpLight;                 // world, metres
uniform vec3 u_dpX, u_dpY, u_dpAxis;    // omni::ParaboloidFrame (x × y = axis)
uniform float u_dpNearM, u_dpFarM;      // window depth = (L - near) / (far - near)

// World direction -> the hemisphere's frame (any length kept).
vec3 dpLocal(int hemi, vec3 d) {
  vec3 l = vec3(dot(d, u_dpX), dot(d, u_dpY), dot(d, u_dpAxis));
  return hemi == 0 ? l : vec3(l.x, -l.y, -l.z);
}
int dpHalf(vec3 d) { return dot(d, u_dpAxis) >= 0.0 ? 0 : 1; }
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
  return normalize(l.x * u_dpX + l.y * u_dpY + l.z * u_dpAxis);
}
float dpWindowDepth(float distanceM) { return storedLightDistance(distanceM, u_dpNearM, u_dpFarM); }
// Distance from the light along unit `dir` to the plane through P with normal N; -1 when the
// ray runs (nearly) inside the plane or away from it.
float dpPlaneDistance(vec3 dir, vec3 P, vec3 N) { return planeDistanceAlongRay(u_dpLight, dir, P, N); }
