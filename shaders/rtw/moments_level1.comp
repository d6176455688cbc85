// DA-RTW moment chain, level 1 straight from the IM: each invocation computes the six
// moments (I, xI, yI, (xx)I, (yy)I, (xy)I at centred texel coordinates) of a 2x2 IM block
// and sums them as (a00 + a10) + (a01 + a11), texels outside the IM counting as 0 — exactly
// sl::rtw::reduceMomentLevel(momentTextures(IM)), without writing level 0 (the panels get
// level 0 from moments.comp when publishing). No shared memory, no barriers.
#include "common/shared_constants.h"
layout(local_size_x = SL_RTW_MOMENT_GROUP, local_size_y = SL_RTW_MOMENT_GROUP) in;
layout(r32ui, binding = SL_RTW_IMAGE_MOMENT_IM) readonly uniform uimage2D u_im;
layout(std430, binding = SL_RTW_BUFFER_MOMENTS) writeonly buffer Moments { float moments[]; };
uniform ivec2 u_size;    // IM size (level 0)
uniform vec2 u_invSize;  // 1 / size, from the host
uniform int u_dstOffset;

void texelMoments(ivec2 t, out float m[6]) {
  float I = 0.0;
  if (all(lessThan(t, u_size))) I = uintBitsToFloat(imageLoad(u_im, t).r);
  float x = float(2 * t.x + 1 - u_size.x) * u_invSize.x;
  float y = float(2 * t.y + 1 - u_size.y) * u_invSize.y;
  m[0] = I;
  m[1] = x * I;
  m[2] = y * I;
  m[3] = (x * x) * I;
  m[4] = (y * y) * I;
  m[5] = (x * y) * I;
}

void main() {
  ivec2 size = (u_size + 1) / 2;
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(t, size))) return;
  float a[6], b[6], c[6], d[6];
  texelMoments(2 * t, a);
  texelMoments(2 * t + ivec2(1, 0), b);
  texelMoments(2 * t + ivec2(0, 1), c);
  texelMoments(2 * t + ivec2(1, 1), d);
  int o = u_dstOffset + 6 * (t.y * size.x + t.x);
  for (int k = 0; k < 6; ++k) moments[o + k] = (a[k] + b[k]) + (c[k] + d[k]);
}
