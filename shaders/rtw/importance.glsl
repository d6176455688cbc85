// Importance terms; mirrors sl::rtw::eyeDepthTerm / orientationTerm / combineImportance
// (algo/rtw/Importance.h), multiplied because Lloyd's aliasing m is a product.
#include "common/shared_constants.h"
uniform int u_eyeOn;
uniform float u_eyeWeight;
uniform int u_orientationOn;
uniform float u_orientationWeight;
uniform float u_minCosL;
uniform int u_edgeOn;
uniform float u_edgeWeight;
uniform float u_nearM;

float eyeDepthTerm(float eyeDepthM, float nearM) {
  return (!(nearM > 0.0) || !(eyeDepthM > nearM)) ? 1.0 : nearM / eyeDepthM;
}

float orientationTerm(float nDotL, float nDotV, float minCosL) {
  float v = nDotV > 0.0 ? min(nDotV, 1.0) : 0.0;
  float l = abs(nDotL);
  l = l > minCosL ? l : minCosL;
  return v / l;
}

float combineImportance(float eyeDepthM, float nDotL, float nDotV, float edge) {
  float e = 1.0, o = 1.0, k = 1.0;
  if (u_eyeOn != 0) e = 1.0 + u_eyeWeight * (eyeDepthTerm(eyeDepthM, u_nearM) - 1.0);
  if (u_orientationOn != 0)
    o = 1.0 + u_orientationWeight * (orientationTerm(nDotL, nDotV, u_minCosL) - 1.0);
  if (u_edgeOn != 0) k = 1.0 + u_edgeWeight * clamp(edge, 0.0, 1.0);
  return max((e * o) * k, 0.0);
}

// Shadow-edge proximity from the previous frame's hard mask (screen space): 1 when a
// covered pixel within 2 px has the other shadow state.
uniform usampler2D u_prevHard;
float shadowEdgeAt(ivec2 px) {
  if (u_edgeOn == 0) return 0.0;
  ivec2 size = textureSize(u_prevHard, 0);
  uint c = texelFetch(u_prevHard, clamp(px, ivec2(0), size - 1), 0).r;
  if (c == SL_MASK_EMPTY) return 0.0;
  for (int dy = -2; dy <= 2; dy += 2)
    for (int dx = -2; dx <= 2; dx += 2) {
      uint o = texelFetch(u_prevHard, clamp(px + ivec2(dx, dy), ivec2(0), size - 1), 0).r;
      if (o != SL_MASK_EMPTY && o != c) return 1.0;
    }
  return 0.0;
}

// The last frame's shadow edge at pixel px, for DA-RTW's turn prediction
// (sl::rtw::ImportanceSnapshot::edgeBins): the central differences of its hard mask (lit 1,
// shadowed 0; a neighbour without a surface counts as px itself). (0, 0) away from an edge and
// where px has no surface. Its direction is the edge's normal on screen.
vec2 shadowMaskGradient(ivec2 px) {
  ivec2 size = textureSize(u_prevHard, 0);
  uint c = texelFetch(u_prevHard, clamp(px, ivec2(0), size - 1), 0).r;
  if (c == SL_MASK_EMPTY) return vec2(0.0);
  float self = c == SL_MASK_LIT ? 1.0 : 0.0;
  float s[4];
  ivec2 d[4] = ivec2[4](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1));
  for (int i = 0; i < 4; ++i) {
    uint o = texelFetch(u_prevHard, clamp(px + d[i], ivec2(0), size - 1), 0).r;
    s[i] = o == SL_MASK_EMPTY ? self : (o == SL_MASK_LIT ? 1.0 : 0.0);
  }
  return vec2(s[0] - s[1], s[2] - s[3]);
}
