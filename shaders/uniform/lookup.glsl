// Uniform shadow map lookup (C++: UniformShadowMap::bindLookup): light clip space of the
// receiver, offset along its normal, then the shared depth-map test.
#include "common/depth_map_test.glsl"
uniform mat4 u_lightViewProj;
uniform float u_normalOffsetM;  // receiver offset along N, metres

vec3 shadowLookupCoord(vec3 P, vec3 N) {
  vec4 c = u_lightViewProj * vec4(P + N * u_normalOffsetM, 1.0);
  return c.xyz / c.w * 0.5 + 0.5;
}
