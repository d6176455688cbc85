// Uniform shadow map lookup (C++: UniformShadowMap::bindLookup): one map sampling light
// uv directly, so its texels are 1/size wide everywhere; the shared single-map lookup
// (common/single_depth_map_lookup.glsl) and bias model do the rest.
#include "common/single_depth_map_lookup.glsl"
