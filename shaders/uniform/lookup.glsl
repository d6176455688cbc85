// Uniform shadow map lookup (C++: UniformShadowMap::bindLookup): the map samples light uv
// directly, so its texels are 1/size wide everywhere; the shared bias model does the rest.
uniform vec2 u_uniformMapSize;  // texels

vec2 lightToMapUv(vec2 uv) { return uv; }
vec2 texelCentreLightUv(ivec2 t) { return (vec2(t) + 0.5) / u_uniformMapSize; }
vec2 localTexelLightUv(vec2 uv) { return 1.0 / u_uniformMapSize; }

#include "common/depth_map_test.glsl"
