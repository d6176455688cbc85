// Warped lookup (seed 002 "warped lookup"; C++: RtwShadowMap::bindLookup): light-space uv
// -> warp -> nearest texel of the warped map. The normal offset is scaled by the local
// texel size, which the warp shrinks where importance is high.
#include "rtw/warp.glsl"
uniform sampler2D u_shadowMap;  // DEPTH_COMPONENT32F, no compare mode
uniform mat4 u_lightViewProj;
uniform float u_normalOffsetM;  // bias.normal x unwarped texel size (metres)
uniform int u_pcfRadius;

vec2 shadowMapSize() { return vec2(textureSize(u_shadowMap, 0)); }

vec3 rtwCoord(vec3 P, vec3 N) {
  vec4 c0 = u_lightViewProj * vec4(P, 1.0);
  vec2 uv0 = c0.xy / c0.w * 0.5 + 0.5;
  float density = max(warpSlope(0, uv0.x), warpSlope(1, uv0.y));
  vec4 c = u_lightViewProj * vec4(P + N * (u_normalOffsetM / max(density, 1.0)), 1.0);
  vec3 uvz = c.xyz / c.w * 0.5 + 0.5;
  return vec3(warpUv(uvz.xy), uvz.z);
}

vec2 shadowMapTexel(vec3 P, vec3 N) { return rtwCoord(P, N).xy * shadowMapSize(); }

float rtwTexelTest(vec3 uvz, ivec2 offset) {
  ivec2 size = textureSize(u_shadowMap, 0);
  ivec2 t = clamp(ivec2(floor(uvz.xy * vec2(size))) + offset, ivec2(0), size - 1);
  return uvz.z <= texelFetch(u_shadowMap, t, 0).r ? 1.0 : 0.0;
}

float shadowHard(vec3 P, vec3 N) {
  vec3 uvz = rtwCoord(P, N);
  if (any(lessThan(uvz.xy, vec2(0.0))) || any(greaterThan(uvz.xy, vec2(1.0)))) return 1.0;
  return rtwTexelTest(uvz, ivec2(0));
}

float shadowFiltered(vec3 P, vec3 N) {
  if (u_pcfRadius == 0) return shadowHard(P, N);
  vec3 uvz = rtwCoord(P, N);
  float sum = 0.0;
  for (int y = -u_pcfRadius; y <= u_pcfRadius; ++y)
    for (int x = -u_pcfRadius; x <= u_pcfRadius; ++x) sum += rtwTexelTest(uvz, ivec2(x, y));
  return sum / float((2 * u_pcfRadius + 1) * (2 * u_pcfRadius + 1));
}
