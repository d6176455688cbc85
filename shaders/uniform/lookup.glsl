// Uniform shadow map lookup (C++: UniformShadowMap::bindLookup): one map sampling light
// uv directly, so its texels are 1/size wide everywhere; the shared bias model does the rest.
#include "common/single_depth_map.glsl"

vec2 lightToMapUv(int map, vec2 uv) { return uv; }
vec2 texelCentreLightUv(int map, ivec2 t) { return (vec2(t) + 0.5) / vec2(shadowMapTexels(map)); }
vec2 localTexelLightUv(int map, vec2 uv) { return 1.0 / vec2(shadowMapTexels(map)); }

#include "common/depth_map_test.glsl"
