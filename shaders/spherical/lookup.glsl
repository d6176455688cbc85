// Spherical (lat-long) lookup (C++: SphericalShadowMap::bindLookup; CPU mirror:
// omni::latLongHalfUv, omni::latLongWrapTexel). The mapping is not a matrix, so this file
// defines the four contract functions of shaders/common/resolve.frag itself, with the one
// bias model's idea (as dual-paraboloid/lookup.glsl): the receiver's plane is met by the
// ray through the centre of the texel it samples, the distance the depth pass stores
// (spherical/depth.frag), so a planar receiver compares against itself exactly; the normal
// offset, slope and constant terms scale with the local texel's height, pi / H radians
// (its width is cos(latitude) times that: narrower towards the poles).
// Map i = half i of the map (longitudes [-pi, 0) and [0, pi)), each H x H texels.
#include "common/shared_constants.h"
#include "spherical/latlong.glsl"
uniform sampler2DArray u_sphMaps;
uniform int u_pcfRadius;        // pcf
uniform float u_biasNormal;     // bias.normal, local texels
uniform float u_biasSlope;      // bias.slope, local texels
uniform float u_biasConstantM;  // bias.constant, metres along the light

vec3 g_receiverP;  // the offset receiver (world)
vec3 g_receiverN;
float g_receiverBiasM;  // slope + constant, metres along the texel's direction

vec2 shadowMapSize(int map) { return vec2(textureSize(u_sphMaps, 0).xy); }

// P's uv in half `map`, continuing across its edges and the seam (resolve.frag's finite
// differences where a pixel's quad partner selected the other half).
vec2 shadowMapUvOf(int map, vec3 P) { return sphUvInHalf(map, P - u_sphLight); }

// Local texel at P in metres: its angular height times the distance.
float sphTexelM(vec3 P) { return length(P - u_sphLight) * kSphPi / shadowMapSize(0).y; }

ShadowCoord shadowLookupCoord(vec3 P, vec3 N) {
  float texelM = sphTexelM(P);
  vec3 towards = towardsLight(P);
  float cosL = clamp(dot(N, towards), -1.0, 1.0);
  float sinL = sqrt(max(1.0 - cosL * cosL, 0.0));
  vec3 Po = P + N * (u_biasNormal * texelM * sinL);
  // Slope: the plane's distance changes by texelM * tan(angle to the light) over one texel,
  // capped at a slope of 10 (as in common/depth_map_test.glsl).
  float tanL = sinL / max(abs(cosL), 1e-3);
  g_receiverBiasM = u_biasSlope * texelM * min(tanL, 10.0) + u_biasConstantM;
  g_receiverP = Po;
  g_receiverN = N;
  vec3 d = Po - u_sphLight;
  int m = sphHalf(d);
  return ShadowCoord(m, vec3(sphUvInHalf(m, d), sphStoredDistance(length(d))));
}

// A tap `offset` texels from c's texel on the whole 2H x H map; taps across the seam wrap,
// taps over a pole continue on the other side of it (sphWrapTexel).
float sphTexelTest(ShadowCoord c, ivec2 offset) {
  int H = int(shadowMapSize(c.map).y);
  ivec2 local = clamp(ivec2(floor(c.uvz.xy * float(H))), ivec2(0), ivec2(H - 1));
  ivec2 t = sphWrapTexel(local + ivec2(c.map * H, 0) + offset, H);
  vec3 dir = sphTexelDirection(t, H);
  float L = sphPlaneDistance(dir, g_receiverP, g_receiverN);
  if (L < 0.0) L = length(g_receiverP - u_sphLight);  // edge-on: its own distance
  float z = sphStoredDistance(L - g_receiverBiasM);
  return z <= texelFetch(u_sphMaps, ivec3(t.x % H, t.y, t.x / H), 0).r ? 1.0 : 0.0;
}

float shadowHardAt(ShadowCoord c) { return sphTexelTest(c, ivec2(0)); }

float shadowFilteredAt(ShadowCoord c) {
  if (u_pcfRadius == 0) return shadowHardAt(c);
  float sum = 0.0;
  for (int y = -u_pcfRadius; y <= u_pcfRadius; ++y)
    for (int x = -u_pcfRadius; x <= u_pcfRadius; ++x) sum += sphTexelTest(c, ivec2(x, y));
  return sum / float((2 * u_pcfRadius + 1) * (2 * u_pcfRadius + 1));
}
