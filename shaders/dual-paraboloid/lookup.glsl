// Dual-paraboloid lookup (C++: DualParaboloidShadowMap::bindLookup; CPU mirror:
// omni::paraboloidUv). The mapping is not a matrix, so this file defines the four contract
// functions of shaders/common/resolve.frag itself, with the one bias model's idea: the
// receiver's plane is evaluated AT THE CENTRE OF THE TEXEL IT SAMPLES — here the distance
// from the light along that texel's own direction to the plane (dpPlaneDistance), the same
// quantity the depth pass stores (dual-paraboloid/depth.frag) — so a planar receiver compares
// against itself exactly; the normal offset, slope and constant terms are scaled by the local
// texel, (1 + cos theta) 2 / resolution radians wide (omni::paraboloidTexelsPerSteradian).
// Map i = hemisphere i (a spot: hemisphere 0 only, along its axis).
#include "common/shared_constants.h"
#include "dual-paraboloid/paraboloid.glsl"
uniform sampler2DArray u_dpMaps;
uniform int u_dpHalves;         // 2 (point) or 1 (spot)
uniform int u_pcfRadius;        // pcf
uniform float u_biasNormal;     // bias.normal, local texels
uniform float u_biasSlope;      // bias.slope, local texels
uniform float u_biasConstantM;  // bias.constant, metres along the light

vec3 g_receiverP;  // the offset receiver (world)
vec3 g_receiverN;
float g_receiverBiasM;  // slope + constant, metres along the texel's direction

vec2 shadowMapSize(int map) { return vec2(textureSize(u_dpMaps, 0).xy); }

// P's uv in hemisphere `map` (resolve.frag, across the rim): the mapping continues a
// little beyond the split plane (z + 1 > 0 for all but the opposite pole).
vec2 shadowMapUvOf(int map, vec3 P) { return dpUv(map, P - u_dpLight); }

int dpSelect(vec3 P) { return u_dpHalves == 1 ? 0 : dpHalf(P - u_dpLight); }

// Local texel at P in metres: its angular width times the distance.
float dpTexelM(int hemi, vec3 P) {
  vec3 d = P - u_dpLight;
  float L = length(d);
  float cosTheta = dpLocal(hemi, d / max(L, 1e-9)).z;
  return L * (1.0 + max(cosTheta, 0.0)) * 2.0 / shadowMapSize(hemi).x;
}

ShadowCoord shadowLookupCoord(vec3 P, vec3 N) {
  int hemi = dpSelect(P);
  float texelM = dpTexelM(hemi, P);
  vec3 towards = towardsLight(P);
  float cosL = clamp(dot(N, towards), -1.0, 1.0);
  float sinL = sqrt(max(1.0 - cosL * cosL, 0.0));
  vec3 Po = P + N * (u_biasNormal * texelM * sinL);
  hemi = dpSelect(Po);
  // Slope: the plane's distance changes by texelM * tan(angle to the light) over one texel,
  // capped at a slope of 10 (as in common/depth_map_test.glsl).
  float tanL = sinL / max(abs(cosL), 1e-3);
  g_receiverBiasM = u_biasSlope * texelM * min(tanL, 10.0) + u_biasConstantM;
  g_receiverP = Po;
  g_receiverN = N;
  vec3 d = Po - u_dpLight;
  return ShadowCoord(hemi, vec3(dpUv(hemi, d), dpWindowDepth(length(d))));
}

// A PCF tap whose texel centre lies beyond the rim (outside the disc, nothing rendered there)
// continues into the other hemisphere: the mapping goes on past the split plane, so the
// tap's direction is found there and that hemisphere's texel read (a spot: one hemisphere,
// the tap is clamped). Tested: OmniPcf (tests/gl).
float dpTexelTest(ShadowCoord c, ivec2 offset) {
  ivec2 size = ivec2(shadowMapSize(c.map));
  ivec2 t = clamp(ivec2(floor(c.uvz.xy * vec2(size))), ivec2(0), size - 1) + offset;
  int hemi = c.map;
  vec2 p = 2.0 * (vec2(t) + 0.5) / vec2(size) - 1.0;
  if (dot(p, p) > 1.0 && u_dpHalves == 2) {
    vec3 across = dpDirection(hemi, (vec2(t) + 0.5) / vec2(size));
    hemi = 1 - hemi;
    t = ivec2(floor(dpUv(hemi, across) * vec2(size)));
  }
  t = clamp(t, ivec2(0), size - 1);
  vec3 dir = dpDirection(hemi, (vec2(t) + 0.5) / vec2(size));
  float L = dpPlaneDistance(dir, g_receiverP, g_receiverN);
  if (L < 0.0) L = length(g_receiverP - u_dpLight);  // edge-on: its own distance
  float z = dpWindowDepth(L - g_receiverBiasM);
  return z <= texelFetch(u_dpMaps, ivec3(t, hemi), 0).r ? 1.0 : 0.0;
}

float shadowHardAt(ShadowCoord c) { return dpTexelTest(c, ivec2(0)); }

float shadowFilteredAt(ShadowCoord c) {
  if (u_pcfRadius == 0) return shadowHardAt(c);
  float sum = 0.0;
  for (int y = -u_pcfRadius; y <= u_pcfRadius; ++y)
    for (int x = -u_pcfRadius; x <= u_pcfRadius; ++x) sum += dpTexelTest(c, ivec2(x, y));
  return sum / float((2 * u_pcfRadius + 1) * (2 * u_pcfRadius + 1));
}
