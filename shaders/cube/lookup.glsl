// Cube shadow map lookup (C++: CubeShadowMap::bindLookup; CPU mirror: omni::selectCubeFace,
// omni::cubeFaceUv, omni::cubeTexelCentreDirection). Map i is face i (+x, -x, +y, -y, +z,
// -z), each a 90° perspective map with its own matrix in the shared bias model
// (common/depth_map_test.glsl) as a DISTANCE map: each texel stores the distance from the
// light along its centre's ray (cube/distance.frag), and the receiver's plane is met by the
// sampled texel's ray. The face is the major axis of the direction from the light, the rule
// the faces were cut by, so every direction has exactly one face whose texels reach it
// (edge texel centres lie half a texel inside). Faces a spot's cone does not reach are not
// rendered (u_cubeFaceLayer -1): read as lit, which only points outside the cone select
// (and those the resolve shadows anyway).
#include "common/shared_constants.h"
#include "cube/distance.glsl"
uniform sampler2DArray u_cubeFaces;
uniform int u_cubeFaceLayer[6];  // the array layer of face f, -1 when not rendered
// Face f's frame (omni::cubeFaceBasis): columns right (u), up (v), forward. Its texel rays
// come from it directly: unprojecting through the inverse float matrix near the light would
// subtract nearly equal positions (directions off by 1e-5, a twentieth of a millimetre at 3 m).
uniform mat3 u_cubeFaceBasis[6];

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

#define SL_DEPTH_MAP_STORES_DISTANCE
vec3 shadowMapLight(int map) { return u_cubeLightPos; }
float shadowMapStoredDistance(int map, float m) { return cubeStoredDistance(m); }
// The direction (unnormalised) of light uv `uv` on face `map`: its plane at 1 m along the
// axis, which continues beyond [0, 1] (omni::cubeDirection).
vec3 cubeFaceDirection(int map, vec2 uv) { return u_cubeFaceBasis[map] * vec3(uv * 2.0 - 1.0, 1.0); }
// omni::cubeTexelCentreDirection.
vec3 shadowMapTexelRay(int map, ivec2 t) {
  return normalize(cubeFaceDirection(map, texelCentreLightUv(map, t)));
}

// PCF taps beyond a face's edge read the neighbouring face (common/depth_map_test.glsl).
#define SL_DEPTH_MAP_ACROSS_EDGES
float shadowMapDistanceAcross(int map, ivec2 t, out vec3 ray);

#include "common/depth_map_test.glsl"

// Tap t of face `map` lies beyond its edge: its direction (the face's plane continues) falls
// in face g; g's texel there is read, and its own centre's ray returned, so the receiver's
// plane is met by the ray the stored distance was measured along: a planar receiver meets
// itself exactly across the edge too. CPU mirror: omni::cubeTexel / cubeTexelCentreDirection.
float shadowMapDistanceAcross(int map, ivec2 t, out vec3 ray) {
  vec3 d = cubeFaceDirection(map, texelCentreLightUv(map, t));
  vec3 P = u_cubeLightPos + d;
  ray = normalize(d);
  int g = selectShadowMap(P);
  if (u_cubeFaceLayer[g] < 0) return 1.0;  // not rendered: lit, as shadowMapDepth
  vec2 size = vec2(shadowMapTexels(g));
  vec4 cg = u_mapViewProj[g] * vec4(P, 1.0);
  ivec2 tg = clamp(ivec2(floor((cg.xy / cg.w * 0.5 + 0.5) * size)), ivec2(0), ivec2(size) - 1);
  ray = shadowMapTexelRay(g, tg);
  return shadowMapDepth(g, tg);
}
