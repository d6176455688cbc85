// Dual-paraboloid lookup (C++: DualParaboloidShadowMap::bindLookup; CPU mirror:
// omni::paraboloidUv). The mapping is not a matrix, so this file defines the contract
// functions of shaders/common/resolve.frag itself, with the bias model of the maps that store
// the distance along each texel's own direction (common/omni/texel_ray_lookup.glsl: the
// receiver's plane met by the ray through the centre of the texel it samples, the quantity
// dual-paraboloid/depth.frag stores); the local texel is (1 + cos theta) 2 / resolution
// radians wide (omni::paraboloidTexelsPerSteradian).
// Map i = hemisphere i (a spot: hemisphere 0 only, along its axis).
#include "common/shared_constants.h"
#include "common/omni/texel_ray_lookup.glsl"
#include "dual-paraboloid/paraboloid.glsl"
uniform sampler2DArray u_dpMaps;
uniform int u_dpHalves;  // 2 (point) or 1 (spot)

vec2 shadowMapSize(int map) { return vec2(textureSize(u_dpMaps, 0).xy); }

// P's uv in hemisphere `map` (resolve.frag, across the rim): the mapping continues a
// little beyond the split plane (z + 1 > 0 for all but the opposite pole).
vec2 shadowMapUvOf(int map, vec3 P) { return dpUv(map, P - u_omniLight); }

int dpSelect(vec3 P) { return u_dpHalves == 1 ? 0 : dpHalf(P - u_omniLight); }

// Local texel at P in metres: its angular width times the distance.
float dpTexelM(int hemi, vec3 P) {
  vec3 d = P - u_omniLight;
  float L = length(d);
  float cosTheta = dpLocal(hemi, d / max(L, 1e-9)).z;
  return L * (1.0 + max(cosTheta, 0.0)) * 2.0 / shadowMapSize(hemi).x;
}

ShadowCoord shadowLookupCoord(vec3 P, vec3 N) {
  vec3 Po = omniSetReceiver(P, N, dpTexelM(dpSelect(P), P));
  int hemi = dpSelect(Po);
  vec3 d = Po - u_omniLight;
  return ShadowCoord(hemi, vec3(dpUv(hemi, d), omniStoredDistance(length(d))));
}

// A PCF tap whose texel centre lies beyond the rim (outside the disc, nothing rendered there)
// continues into the other hemisphere: the mapping goes on past the split plane, so the
// tap's direction is found there and that hemisphere's texel read (a spot: one hemisphere,
// the tap is clamped). Tested: OmniPcf (tests/gl).
float omniTapTest(ShadowCoord c, ivec2 offset) {
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
  return omniReceiverTest(dir, texelFetch(u_dpMaps, ivec3(t, hemi), 0).r);
}
