// Face-partitioned shadow maps lookup (C++: FacePartitionShadowMap::bindLookup): one warped
// map per face partition in a texture array. Selection (CPU mirror and the rule's argument:
// sl::partition::selectFacePartition): the light ray through P, followed towards the light
// (front faces) or away from it (back faces), leaves the view frustum through exactly one
// partition face; P uses that face's map. The shared bias model (common/depth_map_test.glsl)
// uses the selected map's own perspective matrix and local texel.
#include "common/shared_constants.h"
uniform sampler2DArray u_faceMaps;
uniform vec4 u_facePlanes[6];    // the frustum's faces: outward unit normal, d (inside n.P <= d)
uniform int u_facePartition[6];  // the layer of face f, -1 when it has no partition
uniform vec3 u_faceRayDir;       // towards the light (front faces) or away (back faces)

int selectShadowMap(vec3 P) {
  int best = -1;
  float bestT = 3.0e38;
  for (int f = 0; f < 6; ++f) {
    int layer = u_facePartition[f];
    if (layer < 0) continue;
    float nd = dot(u_facePlanes[f].xyz, u_faceRayDir);
    if (!(nd > 0.0)) continue;
    float t = (u_facePlanes[f].w - dot(u_facePlanes[f].xyz, P)) / nd;
    if (t < bestT) {
      bestT = t;
      best = layer;
    }
  }
  return max(best, 0);
}
ivec2 shadowMapTexels(int map) { return textureSize(u_faceMaps, 0).xy; }
float shadowMapDepth(int map, ivec2 t) { return texelFetch(u_faceMaps, ivec3(t, map), 0).r; }

vec2 lightToMapUv(int map, vec2 uv) { return uv; }
vec2 texelCentreLightUv(int map, ivec2 t) { return (vec2(t) + 0.5) / vec2(shadowMapTexels(map)); }
vec2 localTexelLightUv(int map, vec2 uv) { return 1.0 / vec2(shadowMapTexels(map)); }

#include "common/depth_map_test.glsl"
