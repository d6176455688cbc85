// The whole lookup of a technique with ONE depth map sampled at its light uv (uniform, and the
// PSM / LiSPSM / TSM family whose warp is the map's own perspective matrix): the map side of
// common/single_depth_map.glsl, texels 1/size wide in light uv everywhere, and the shared bias
// model does the rest. C++: the technique's bindLookup (UniformShadowMap,
// PerspectiveShadowMap).
#include "common/single_depth_map.glsl"

vec2 lightToMapUv(int map, vec2 uv) { return uv; }
vec2 texelCentreLightUv(int map, ivec2 t) { return (vec2(t) + 0.5) / vec2(shadowMapTexels(map)); }
vec2 localTexelLightUv(int map, vec2 uv) { return 1.0 / vec2(shadowMapTexels(map)); }

#include "common/depth_map_test.glsl"
