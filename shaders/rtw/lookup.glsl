// Warped lookup (seed 002 "warped lookup"; C++: RtwShadowMap::bindLookup): light-space uv
// -> warp -> the shared depth-map test on the warped map. The normal offset is scaled by
// the local texel size, which the warp shrinks where importance is high.
#include "rtw/warp.glsl"
#include "common/depth_map_test.glsl"
uniform mat4 u_lightViewProj;
uniform float u_normalOffsetM;  // bias.normal x unwarped texel size (metres)

vec3 shadowLookupCoord(vec3 P, vec3 N) {
  vec4 c0 = u_lightViewProj * vec4(P, 1.0);
  vec2 uv0 = c0.xy / c0.w * 0.5 + 0.5;
  float density = max(warpSlope(0, uv0.x), warpSlope(1, uv0.y));
  vec4 c = u_lightViewProj * vec4(P + N * (u_normalOffsetM / max(density, 1.0)), 1.0);
  vec3 uvz = c.xyz / c.w * 0.5 + 0.5;
  return vec3(warpUv(uvz.xy), uvz.z);
}
