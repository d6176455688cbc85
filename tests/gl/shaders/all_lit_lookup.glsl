// Test technique "test-all-lit" (tests/gl/TestTechniques.cpp): uniform's map is rendered and
// bound, but every texel reads as the far plane, so nothing occludes and every receiver is
// lit. A technique that is wrong on purpose: a claim measured on it must not be reproduced.
uniform sampler2D u_shadowMap;

int selectShadowMap(vec3 P) { return 0; }
ivec2 shadowMapTexels(int map) { return textureSize(u_shadowMap, 0); }
float shadowMapDepth(int map, ivec2 t) { return 1.0; }
vec2 lightToMapUv(int map, vec2 uv) { return uv; }
vec2 texelCentreLightUv(int map, ivec2 t) { return (vec2(t) + 0.5) / vec2(shadowMapTexels(map)); }
vec2 localTexelLightUv(int map, vec2 uv) { return 1.0 / vec2(shadowMapTexels(map)); }

#include "common/depth_map_test.glsl"
