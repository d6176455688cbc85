// PSM / LiSPSM / TSM lookup (C++: PerspectiveShadowMap::bindLookup): one map whose light
// matrix is the warp's perspective lightProj * lightView, so its light uv IS the texture uv
// (the w-divide of depth_map_test.glsl's mapUvzw does the warp) and its texels are 1/size
// in uv: the single-map lookup uniform uses too (common/single_depth_map_lookup.glsl).
#include "common/single_depth_map_lookup.glsl"
