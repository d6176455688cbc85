// One level of the moment chain: each texel sums the up-to-four source texels that exist,
// (a00 + a10) + (a01 + a11); size ceil(src/2). Mirrors sl::rtw::reduceMomentLevel (SUMS,
// not averages, so non-power-of-two sizes are exact).
#include "common/shared_constants.h"
layout(local_size_x = SL_RTW_MOMENT_GROUP, local_size_y = SL_RTW_MOMENT_GROUP) in;
layout(std430, binding = SL_RTW_BUFFER_MOMENTS) buffer Moments { float moments[]; };
uniform ivec2 u_srcSize;
uniform int u_srcOffset;  // in floats
uniform int u_dstOffset;

float fetch(int x, int y, int c) {
  if (x >= u_srcSize.x || y >= u_srcSize.y) return 0.0;
  return moments[u_srcOffset + 6 * (y * u_srcSize.x + x) + c];
}

void main() {
  ivec2 dstSize = (u_srcSize + 1) / 2;
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(t, dstSize))) return;
  int o = u_dstOffset + 6 * (t.y * dstSize.x + t.x);
  for (int c = 0; c < 6; ++c) {
    int x = 2 * t.x, y = 2 * t.y;
    moments[o + c] = (fetch(x, y, c) + fetch(x + 1, y, c)) + (fetch(x, y + 1, c) + fetch(x + 1, y + 1, c));
  }
}
