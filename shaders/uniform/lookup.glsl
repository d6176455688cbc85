// Uniform shadow map lookup (C++: UniformShadowMap::bindLookup). Hard test on the nearest
// texel (texelFetch, no hardware filtering) so that metrics see the map's true resolution;
// PCF averages the hard tests of a (2r+1)^2 texel neighbourhood.
uniform sampler2D u_shadowMap;  // DEPTH_COMPONENT32F, no compare mode
uniform mat4 u_lightViewProj;
uniform float u_normalOffsetM;  // receiver offset along N, metres
uniform int u_pcfRadius;

vec3 shadowCoord(vec3 P, vec3 N) {
  vec4 c = u_lightViewProj * vec4(P + N * u_normalOffsetM, 1.0);
  return c.xyz / c.w * 0.5 + 0.5;
}

vec2 shadowMapSize() { return vec2(textureSize(u_shadowMap, 0)); }
vec2 shadowMapTexel(vec3 P, vec3 N) { return shadowCoord(P, N).xy * shadowMapSize(); }

float shadowTexelTest(vec3 uvz, ivec2 offset) {
  ivec2 size = textureSize(u_shadowMap, 0);
  ivec2 t = clamp(ivec2(floor(uvz.xy * vec2(size))) + offset, ivec2(0), size - 1);
  return uvz.z <= texelFetch(u_shadowMap, t, 0).r ? 1.0 : 0.0;
}

float shadowHard(vec3 P, vec3 N) {
  vec3 uvz = shadowCoord(P, N);
  if (any(lessThan(uvz.xy, vec2(0.0))) || any(greaterThan(uvz.xy, vec2(1.0)))) return 1.0;
  return shadowTexelTest(uvz, ivec2(0));
}

float shadowFiltered(vec3 P, vec3 N) {
  if (u_pcfRadius == 0) return shadowHard(P, N);
  vec3 uvz = shadowCoord(P, N);
  float sum = 0.0;
  for (int y = -u_pcfRadius; y <= u_pcfRadius; ++y)
    for (int x = -u_pcfRadius; x <= u_pcfRadius; ++x) sum += shadowTexelTest(uvz, ivec2(x, y));
  float n = float((2 * u_pcfRadius + 1) * (2 * u_pcfRadius + 1));
  return sum / n;
}
