// Test technique "uniform-array2x2" (tests/gl/TestTechniques.cpp): the uniform map split into
// a 2x2 texture array of sub-maps, each with its own matrix (a quarter of the light frustum),
// selected by light uv. Proves the multi-map lookup contract with the shared bias model.
uniform sampler2DArray u_maps;
uniform mat4 u_selectViewProj;  // the whole fit: the selection function's light uv

int selectShadowMap(vec3 P) {
  vec2 uv = (u_selectViewProj * vec4(P, 1.0)).xy * 0.5 + 0.5;
  return (uv.x >= 0.5 ? 1 : 0) + (uv.y >= 0.5 ? 2 : 0);
}
ivec2 shadowMapTexels(int map) { return textureSize(u_maps, 0).xy; }
float shadowMapDepth(int map, ivec2 t) { return texelFetch(u_maps, ivec3(t, map), 0).r; }
vec2 lightToMapUv(int map, vec2 uv) { return uv; }
vec2 texelCentreLightUv(int map, ivec2 t) { return (vec2(t) + 0.5) / vec2(shadowMapTexels(map)); }
vec2 localTexelLightUv(int map, vec2 uv) { return 1.0 / vec2(shadowMapTexels(map)); }

#include "common/depth_map_test.glsl"
