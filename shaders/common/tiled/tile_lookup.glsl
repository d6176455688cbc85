// One tile of a virtual shadow map as map 0 of the shared bias model (common/depth_map_test.glsl;
// C++: sl::applyTile). The tile's u_tileTexels may be a sub-rectangle at the origin of a
// larger texture (fvsm's sub-rectangle and power-of-two texture modes). With u_clampToTile a
// receiver whose normal offset leaves the tile is compared with the tile's edge texel
// (virtual-tiled, which has no overlap); without it, it is lit, as beyond any map of the
// shared model — the seams fvsm's tile overlap (fvsm.overlap) removes.
uniform sampler2D u_shadowMap;
uniform ivec2 u_tileTexels;
uniform bool u_clampToTile;

int selectShadowMap(vec3 P) { return 0; }
ivec2 shadowMapTexels(int map) { return u_tileTexels; }
float shadowMapDepth(int map, ivec2 t) { return texelFetch(u_shadowMap, t, 0).r; }
vec2 lightToMapUv(int map, vec2 uv) { return u_clampToTile ? clamp(uv, vec2(0.0), vec2(1.0)) : uv; }
vec2 texelCentreLightUv(int map, ivec2 t) { return (vec2(t) + 0.5) / vec2(u_tileTexels); }
vec2 localTexelLightUv(int map, vec2 uv) { return 1.0 / vec2(u_tileTexels); }

#include "common/depth_map_test.glsl"
