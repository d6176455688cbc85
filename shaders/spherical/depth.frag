// Spherical (lat-long) depth pass, fragment stage: the texel's own direction from the light
// (omni::latLongTexelCentreDirection) meets the triangle's plane; its distance is stored
// (exact per texel, omni::storedDistance). sph.exactCoverage: the texel is kept only where
// that ray hits the triangle itself (the true, curved image; a shared edge counts for both
// triangles within a relative 1e-5 of barycentrics, so no texel falls between them).
#include "common/material.glsl"
#include "spherical/latlong.glsl"
flat in vec3 g_a, g_b, g_c;
flat in vec2 g_uvA, g_uvB, g_uvC;
uniform int u_sphHalfIndex;
uniform int u_sphExact;
uniform float u_mapTexels;

void main() {
  int H = int(u_mapTexels);
  ivec2 texel = ivec2(gl_FragCoord.xy) + ivec2(u_sphHalfIndex * H, 0);
  vec3 dir = sphTexelDirection(texel, H);
  vec3 tuv = sphRayTriangle(dir, g_a, g_b, g_c);
  if (tuv.x <= 0.0) discard;
  if (u_sphExact != 0 && !sphBaryInside(tuv, 1e-5)) discard;
  if (materialAlphaRejectsLevel0((1.0 - tuv.y - tuv.z) * g_uvA + tuv.y * g_uvB + tuv.z * g_uvC))
    discard;
  gl_FragDepth = clamp(omniStoredDistance(tuv.x), 0.0, 1.0);
}
