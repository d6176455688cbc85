// The map side of the shared depth-map test (common/depth_map_test.glsl) for techniques
// with ONE depth map in a sampler2D (uniform, RTW): map 0 everywhere.
// C++: bindDepthLookup + the technique's glBindTextureUnit of u_shadowMap.
uniform sampler2D u_shadowMap;

int selectShadowMap(vec3 P) { return 0; }
ivec2 shadowMapTexels(int map) { return textureSize(u_shadowMap, 0); }
float shadowMapDepth(int map, ivec2 t) { return texelFetch(u_shadowMap, t, 0).r; }
