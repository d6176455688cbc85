// Warped lookup (seed 002 "warped lookup"; C++: RtwShadowMap::bindLookup): light uv -> warp
// -> the shared depth-map test. Texel centres come back from the inverse tables the scan
// pass leaves (the same centres the warped pass evaluated its exact depth at), and the local
// texel size is 1 / (size * du'/du): the bias model follows the warp's compression.
#include "rtw/warp.glsl"
#include "common/single_depth_map.glsl"
uniform int u_smRes;  // warped map size in texels

vec2 lightToMapUv(int map, vec2 uv) { return warpUv(uv); }
vec2 texelCentreLightUv(int map, ivec2 t) { return inverseWarpCentre(t, u_smRes); }
vec2 localTexelLightUv(int map, vec2 uv) {
  return 1.0 / (float(u_smRes) * max(vec2(warpSlope(0, uv.x), warpSlope(1, uv.y)), 1e-6));
}

#include "common/depth_map_test.glsl"
