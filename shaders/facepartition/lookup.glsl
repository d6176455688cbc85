// Face-partitioned shadow maps lookup (C++: FacePartitionShadowMap::bindLookup): one warped
// map per face partition in a texture array, SL_FACE_SLOTS per depth slice (face.zsplits).
// Selection (CPU mirror and the rule's argument: sl::partition::selectFacePartition): the
// slice of P's view depth (the first whose far split is not below it, the last beyond), then
// the light ray through P, followed towards the light (front faces) or away from it (back
// faces), leaves that slice through exactly one partition face; P uses that face's map. The
// shared bias model (common/depth_map_test.glsl) uses the selected map's own perspective
// matrix and local texel.
#include "common/shared_constants.h"
uniform sampler2DArray u_faceMaps;
// Slice s's faces are [6 s + f]: outward unit normal, d (inside n.P <= d).
uniform vec4 u_facePlanes[6 * SL_FACE_MAX_ZSPLITS];
uniform int u_facePartition[6 * SL_FACE_MAX_ZSPLITS];  // the layer of face f, -1 when none
uniform vec3 u_faceRayDir;  // towards the light (front faces) or away (back faces)
uniform int u_faceSlices;   // face.zsplits: depth slices
uniform float u_faceSplitFar[SL_FACE_MAX_ZSPLITS];  // far view depth of slice s (m)
uniform vec3 u_faceEye;                             // camera position
uniform vec3 u_faceForward;                         // camera view direction (unit)

int selectShadowMap(vec3 P) {
  int s = 0;
  if (u_faceSlices > 1) {
    float d = dot(P - u_faceEye, u_faceForward);
    while (s < u_faceSlices - 1 && d > u_faceSplitFar[s]) ++s;
  }
  int best = -1;
  float bestT = 3.0e38;
  for (int f = 6 * s; f < 6 * s + 6; ++f) {
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
  return best < 0 ? s * SL_FACE_SLOTS : best;
}
ivec2 shadowMapTexels(int map) { return textureSize(u_faceMaps, 0).xy; }
float shadowMapDepth(int map, ivec2 t) { return texelFetch(u_faceMaps, ivec3(t, map), 0).r; }

vec2 lightToMapUv(int map, vec2 uv) { return uv; }
vec2 texelCentreLightUv(int map, ivec2 t) { return (vec2(t) + 0.5) / vec2(shadowMapTexels(map)); }
vec2 localTexelLightUv(int map, vec2 uv) { return 1.0 / vec2(shadowMapTexels(map)); }

#include "common/depth_map_test.glsl"
