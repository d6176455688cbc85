// Backward analysis (seed 002, seed 000) as a full-screen fragment pass: every covered
// camera pixel scatters its importance with atomicMax on the float's bits (valid for finite
// values >= +0; mirrors sl::rtw::scatterMax) STRAIGHT INTO THE TWO 1D MAPS: the collapse
// (max over each column and row of the IM, sl::rtw::collapseColumnsMax / collapseRowsMax) of
// a max-scatter is the max-scatter into the 1D maps, so the 2D IM is only written while a
// panel shows it, and DA-RTW's smaller moment IM only for DA-RTW. A fragment pass rather
// than a compute pass: llvmpipe shades fragments several times faster per pixel (measured
// on this pass: 1280x720, 26 ms as a compute dispatch).
#include "common/shared_constants.h"
layout(std430, binding = SL_RTW_BUFFER_COLLAPSED) buffer Collapsed { uint collapsed[]; };  // [x n][y n] float bits
layout(r32ui, binding = SL_RTW_IMAGE_IM) uniform uimage2D u_im;                    // n x n, if u_writeIm
layout(r32ui, binding = SL_RTW_IMAGE_MOMENT_IM) uniform uimage2D u_momentIm;              // if u_writeMomentIm
uniform int u_n;
uniform int u_writeIm;
uniform int u_writeMomentIm;
uniform int u_stride;  // importance.stride: the fragment at (x, y) is camera pixel k (x, y)
uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
uniform mat4 u_lightViewProj;
uniform vec3 u_cameraPos;
uniform vec3 u_cameraForward;
#include "common/light.glsl"
#include "rtw/importance.glsl"

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
  }
}
