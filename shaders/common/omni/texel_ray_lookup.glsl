// The lookup's bias model of the omni maps that store the exact distance along each texel's
// own ray (dual-paraboloid/lookup.glsl, spherical/lookup.glsl): the receiver's plane is
// evaluated AT THE CENTRE OF THE TEXEL IT SAMPLES, the distance from the light along that
// texel's direction to the plane, the quantity the depth passes store, so a planar receiver
// compares against itself exactly; the normal offset, slope and constant terms are scaled by
// the local texel (texelM metres, given by the including lookup). The including lookup defines
// omniTapTest (one PCF tap); this file defines shadowHardAt and shadowFilteredAt from it.
#include "common/omni/frame.glsl"
uniform int u_pcfRadius;        // pcf
uniform float u_biasNormal;     // bias.normal, local texels
uniform float u_biasSlope;      // bias.slope, local texels
uniform float u_biasConstantM;  // bias.constant, metres along the light

vec3 g_receiverP;  // the offset receiver (world)
vec3 g_receiverN;
float g_receiverBiasM;  // slope + constant, metres along the texel's direction

// Sets this pixel's receiver from P, its normal N and the local texel at P (metres): P is
// offset along N by bias.normal texels (scaled by the sine of the angle to the light); the
// slope term grows with the tangent of that angle, capped at a slope of 10 (as in
// common/depth_map_test.glsl). Returns the offset receiver.
vec3 omniSetReceiver(vec3 P, vec3 N, float texelM) {
  vec3 towards = towardsLight(P);
  float cosL = clamp(dot(N, towards), -1.0, 1.0);
  float sinL = sqrt(max(1.0 - cosL * cosL, 0.0));
  vec3 Po = P + N * (u_biasNormal * texelM * sinL);
  // Slope: the plane's distance changes by texelM * tan(angle to the light) over one texel.
  float tanL = sinL / max(abs(cosL), 1e-3);
  g_receiverBiasM = u_biasSlope * texelM * min(tanL, 10.0) + u_biasConstantM;
  g_receiverP = Po;
  g_receiverN = N;
  return Po;
}

// 1 (lit) when the receiver, met along the texel direction `dir` (unit) and moved towards the
// light by its bias, is no farther than the texel's `stored` value.
float omniReceiverTest(vec3 dir, float stored) {
  float L = omniPlaneDistance(dir, g_receiverP, g_receiverN);
  if (L < 0.0) L = length(g_receiverP - u_omniLight);  // edge-on: its own distance
  float z = omniStoredDistance(L - g_receiverBiasM);
  return z <= stored ? 1.0 : 0.0;
}

// The tap `offset` texels from c's texel: omniReceiverTest at that texel (the lookup's).
float omniTapTest(ShadowCoord c, ivec2 offset);

float shadowHardAt(ShadowCoord c) { return omniTapTest(c, ivec2(0)); }

float shadowFilteredAt(ShadowCoord c) {
  if (u_pcfRadius == 0) return shadowHardAt(c);
  float sum = 0.0;
  for (int y = -u_pcfRadius; y <= u_pcfRadius; ++y)
    for (int x = -u_pcfRadius; x <= u_pcfRadius; ++x) sum += omniTapTest(c, ivec2(x, y));
  return sum / float((2 * u_pcfRadius + 1) * (2 * u_pcfRadius + 1));
}
