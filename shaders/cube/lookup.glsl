// Cube shadow map lookup (C++: CubeShadowMap::bindLookup; CPU mirror: omni::selectCubeFace
// and omni::cubeFaceUv). Map i is face i (+x, -x, +y, -y, +z, -z), each a 90° perspective
// map with its own matrix in the shared bias model (common/depth_map_test.glsl); the face
// is the major axis of the direction from the light, the rule the faces were cut by, so
// every direction has exactly one face whose texels reach it (edge texel centres lie half
// a texel inside) and the receiver is compared in that face's own depth. Faces a spot's
// cone does not reach are not rendered (u_cubeFaceLayer -1): read as lit, which only
// points outside the cone select (and those the resolve shadows anyway).
#include "common/shared_constants.h"
uniform sampler2DArray u_cubeFaces;
uniform vec3 u_cubeLightPos;     // world, metres
uniform int u_cubeFaceLayer[6];  // the array layer of face f, -1 when not rendered
uniform mat4 u_cubeClipToWorld[6];  // inverse of face f's world -> clip matrix

// omni::selectCubeFace: largest |component|; ties x before y before z, + before -.
int selectShadowMap(vec3 P) {
  vec3 d = P - u_cubeLightPos;
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0 ? 2 : 3;
  return d.z >= 0.0 ? 4 : 5;
}
ivec2 shadowMapTexels(int map) { return textureSize(u_cubeFaces, 0).xy; }
float shadowMapDepth(int map, ivec2 t) {
  int layer = u_cubeFaceLayer[map];
  return layer < 0 ? 1.0 : texelFetch(u_cubeFaces, ivec3(t, layer), 0).r;
}

vec2 lightToMapUv(int map, vec2 uv) { return uv; }
vec2 texelCentreLightUv(int map, ivec2 t) { return (vec2(t) + 0.5) / vec2(shadowMapTexels(map)); }
vec2 localTexelLightUv(int map, vec2 uv) { return 1.0 / vec2(shadowMapTexels(map)); }

// PCF taps beyond a face's edge read the neighbouring face (common/depth_map_test.glsl).
#define SL_DEPTH_MAP_ACROSS_EDGES
float shadowMapDepthAcross(int map, ivec2 t, out vec2 centreLightUv);

#include "common/depth_map_test.glsl"

// Tap t of face `map` lies beyond its edge: its direction (the face's plane continues) falls
// in face g; g's texel there stores a point Q (its centre's ray at the stored depth). Q's
// depth and light uv in face `map` are returned, so the receiver's plane is compared with Q
// where Q's own ray meets it: a planar receiver meets itself exactly across the edge too.
// CPU mirror: omni::cubeTexel / cubeTexelCentreDirection for the face and texel.
float shadowMapDepthAcross(int map, ivec2 t, out vec2 centreLightUv) {
  vec2 size = vec2(shadowMapTexels(map));
  vec2 uv = (vec2(t) + 0.5) / size;
  centreLightUv = uv;
  vec4 onPlane = u_cubeClipToWorld[map] * vec4(uv * 2.0 - 1.0, 0.0, 1.0);
  vec3 P = onPlane.xyz / onPlane.w;
  int g = selectShadowMap(P);
  int layer = u_cubeFaceLayer[g];
  if (layer < 0) return 1.0;  // not rendered: lit, as shadowMapDepth
  vec4 cg = u_mapViewProj[g] * vec4(P, 1.0);
  ivec2 tg = clamp(ivec2(floor((cg.xy / cg.w * 0.5 + 0.5) * size)), ivec2(0), ivec2(size) - 1);
  float zg = texelFetch(u_cubeFaces, ivec3(tg, layer), 0).r;
  if (zg >= 1.0) return 1.0;  // nothing there: the far plane
  vec4 q = u_cubeClipToWorld[g] * vec4((vec2(tg) + 0.5) / size * 2.0 - 1.0, zg * 2.0 - 1.0, 1.0);
  vec4 inMap = mapUvzw(map, q.xyz / q.w);
  centreLightUv = inMap.xy;
  return inMap.z;
}
