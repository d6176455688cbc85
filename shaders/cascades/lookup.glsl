// Cascaded shadow maps lookup (C++: CascadedShadowMap::bindLookup): k orthographic maps in
// one texture array, map i serving view depths up to u_cascadeFar[i] (the last one beyond).
// The shared bias model (common/depth_map_test.glsl) uses map i's own matrix and texel.
#include "common/shared_constants.h"
uniform sampler2DArray u_cascadeMaps;
uniform int u_cascadeCount;                     // k
uniform float u_cascadeFar[SL_MAX_DEPTH_MAPS];  // far split of partition i, view depth (m)
uniform vec3 u_cascadeEye;                      // camera position
uniform vec3 u_cascadeForward;                  // camera view direction (unit)

// Selection by view depth: the first partition whose far split is beyond P.
int selectShadowMap(vec3 P) {
  float d = dot(P - u_cascadeEye, u_cascadeForward);
  int i = 0;
  while (i < u_cascadeCount - 1 && d > u_cascadeFar[i]) ++i;
  return i;
}
ivec2 shadowMapTexels(int map) { return textureSize(u_cascadeMaps, 0).xy; }
float shadowMapDepth(int map, ivec2 t) { return texelFetch(u_cascadeMaps, ivec3(t, map), 0).r; }

vec2 lightToMapUv(int map, vec2 uv) { return uv; }
vec2 texelCentreLightUv(int map, ivec2 t) { return (vec2(t) + 0.5) / vec2(shadowMapTexels(map)); }
vec2 localTexelLightUv(int map, vec2 uv) { return 1.0 / vec2(shadowMapTexels(map)); }

#include "common/depth_map_test.glsl"
