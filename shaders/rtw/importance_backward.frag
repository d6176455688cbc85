// Backward analysis (seed 002, seed 000) as a full-screen fragment pass: every covered
// camera pixel scatters its importance with atomicMax on the float's bits (valid for finite
// values >= +0; mirrors sl::rtw::scatterMax) STRAIGHT INTO THE TWO 1D MAPS: the collapse
// (max over each column and row of the IM, sl::rtw::collapseColumnsMax / collapseRowsMax) of
// a max-scatter is the max-scatter into the 1D maps, so the 2D IM is only written while a
// panel shows it, and DA-RTW's smaller moment IM only for DA-RTW. A fragment pass rather
// than a compute pass: llvmpipe shades fragments several times faster per pixel (measured
// on this pass: 1280x720, 26 ms as a compute dispatch). For DA-RTW it also counts, per moment
// IM texel, the scattering pixels and the last frame's shadow-edge pixels by the direction of
// their edge in the light plane: what the turn prediction weighs (algo/rtw/TurnPrediction.h).
#include "common/shared_constants.h"
layout(std430, binding = SL_RTW_BUFFER_COLLAPSED) buffer Collapsed { uint collapsed[]; };  // [x n][y n] float bits
layout(r32ui, binding = SL_RTW_IMAGE_IM) uniform uimage2D u_im;                    // n x n, if u_writeIm
layout(r32ui, binding = SL_RTW_IMAGE_MOMENT_IM) uniform uimage2D u_momentIm;              // if u_writeMomentIm
// If u_writeMomentIm: [pixels][importance sum low][high][edge bin 0]..[edge bin
// SL_RTW_EDGE_BINS - 1], m x m uints each (SL_RTW_COUNT_PLANES planes).
layout(std430, binding = SL_RTW_BUFFER_MOMENT_COUNTS) buffer MomentCounts { uint momentCounts[]; };
uniform int u_n;
uniform int u_writeIm;
uniform int u_writeMomentIm;
uniform int u_stride;  // importance.stride: the fragment at (x, y) is camera pixel k (x, y)
uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
uniform mat4 u_lightViewProj;
uniform vec3 u_cameraPos;
uniform vec3 u_cameraForward;
uniform vec2 u_lightExtentM;  // the light frustum's width and height (m): uv -> metres
#include "common/light.glsl"
#include "rtw/importance.glsl"

vec2 lightUvOf(vec3 P) {
  vec4 c = u_lightViewProj * vec4(P, 1.0);
  return c.xy / c.w * 0.5 + 0.5;
}

// Light-plane metres from pixel px's surface point (at light uv `uv`) to the neighbour px + d's
// (or minus px - d's where px + d has no surface); (0, 0) where neither has one.
vec2 lightPlaneStep(ivec2 px, ivec2 d, vec2 uv) {
  ivec2 size = textureSize(u_gPosition, 0);
  for (int side = 1; side >= -1; side -= 2) {
    ivec2 q = px + side * d;
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
    vec4 Q = texelFetch(u_gPosition, q, 0);
    if (Q.w > 0.0) return float(side) * (lightUvOf(Q.xyz) - uv) * u_lightExtentM;
  }
  return vec2(0.0);
}

// Counts pixel px (importance imp) in moment IM texel `cell`, adds its importance to the
// texel's 64-bit fixed-point sum (the carry of the low word's atomicAdd goes to the high word:
// an add wrapped exactly when the old value plus the add is below the old value) and, on a
// shadow edge of the last frame, counts its edge normal's light-plane direction in the two
// nearest bins (mirrors sl::rtw::edgeBinParts).
void countForPrediction(ivec2 px, vec2 uv, float imp, int cell, int plane) {
  atomicAdd(momentCounts[cell], 1u);
  uint add = uint(min(imp, SL_RTW_IMPORTANCE_MAX) * SL_RTW_IMPORTANCE_ONE);
  uint old = atomicAdd(momentCounts[plane + cell], add);
  if (old + add < old) atomicAdd(momentCounts[2 * plane + cell], 1u);
  vec2 g = shadowMaskGradient(px);
  if (g == vec2(0.0)) return;
  // The edge's screen tangent (-g.y, g.x) carried onto the light plane by the surface.
  vec2 t = -g.y * lightPlaneStep(px, ivec2(1, 0), uv) + g.x * lightPlaneStep(px, ivec2(0, 1), uv);
  if (!(dot(t, t) > 0.0)) return;
  float beta = mod(degrees(atan(t.x, -t.y)), 180.0);  // the normal (-t.y, t.x)
  float x = min(beta / (180.0 / float(SL_RTW_EDGE_BINS)), float(SL_RTW_EDGE_BINS) - 1e-4);
  int lo = int(floor(x));
  int hi = (lo + 1) % SL_RTW_EDGE_BINS;
  uint hiPart = uint(round((x - float(lo)) * float(SL_RTW_EDGE_ONE)));
  atomicAdd(momentCounts[plane * (3 + lo) + cell], uint(SL_RTW_EDGE_ONE) - hiPart);
  atomicAdd(momentCounts[plane * (3 + hi) + cell], hiPart);
}

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy) * u_stride;
  if (any(greaterThanEqual(px, textureSize(u_gPosition, 0)))) return;
  vec4 P = texelFetch(u_gPosition, px, 0);
  if (P.w <= 0.0) return;
  vec4 c = u_lightViewProj * vec4(P.xyz, 1.0);
  vec2 uv = c.xy / c.w * 0.5 + 0.5;
  vec2 f = floor(uv * float(u_n));
  if (!(f.x >= 0.0 && f.x < float(u_n) && f.y >= 0.0 && f.y < float(u_n))) return;
  vec3 N = texelFetch(u_gNormal, px, 0).xyz;
  vec3 V = normalize(u_cameraPos - P.xyz);
  float eyeDepth = dot(P.xyz - u_cameraPos, u_cameraForward);
  float imp = combineImportance(eyeDepth, dot(N, towardsLight(P.xyz)), dot(N, V), shadowEdgeAt(px));
  if (!(imp > 0.0) || isinf(imp)) return;
  uint bits = floatBitsToUint(imp);
  ivec2 t = ivec2(f);
  atomicMax(collapsed[t.x], bits);
  atomicMax(collapsed[u_n + t.y], bits);
  if (u_writeIm != 0) imageAtomicMax(u_im, t, bits);
  if (u_writeMomentIm != 0) {
    int m = imageSize(u_momentIm).x;
    ivec2 g = min(ivec2(floor(uv * float(m))), ivec2(m - 1));
    imageAtomicMax(u_momentIm, g, bits);
    if (all(equal(ivec2(gl_FragCoord.xy) % SL_RTW_COUNT_STRIDE, ivec2(0))))
      countForPrediction(px, uv, imp, g.y * m + g.x, m * m);
  }
}
