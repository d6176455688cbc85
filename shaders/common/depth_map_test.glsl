// The depth test shared by single-map lookups (uniform, RTW): nearest texel via texelFetch
// (no hardware filtering, so metrics see the map's true resolution); PCF averages the hard
// tests of a (2r+1)^2 neighbourhood. Needs u_shadowMap (depth, no compare) and u_pcfRadius.
uniform sampler2D u_shadowMap;
uniform int u_pcfRadius;

vec2 shadowMapSize() { return vec2(textureSize(u_shadowMap, 0)); }

float depthMapTexelTest(vec3 uvz, ivec2 offset) {
  ivec2 size = textureSize(u_shadowMap, 0);
  ivec2 t = clamp(ivec2(floor(uvz.xy * vec2(size))) + offset, ivec2(0), size - 1);
  return uvz.z <= texelFetch(u_shadowMap, t, 0).r ? 1.0 : 0.0;
}

float shadowHardAt(vec3 uvz) {
  if (any(lessThan(uvz.xy, vec2(0.0))) || any(greaterThan(uvz.xy, vec2(1.0)))) return 1.0;
  return depthMapTexelTest(uvz, ivec2(0));
}

float shadowFilteredAt(vec3 uvz) {
  if (u_pcfRadius == 0) return shadowHardAt(uvz);
  float sum = 0.0;
  for (int y = -u_pcfRadius; y <= u_pcfRadius; ++y)
    for (int x = -u_pcfRadius; x <= u_pcfRadius; ++x) sum += depthMapTexelTest(uvz, ivec2(x, y));
  return sum / float((2 * u_pcfRadius + 1) * (2 * u_pcfRadius + 1));
}
