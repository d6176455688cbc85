// DA-RTW moment chain, level 0 (seed 000, after LEAN mapping): six channels per IM texel,
// I, xI, yI, (xx)I, (yy)I, (xy)I with centred texel coordinates. Mirrors
// sl::rtw::momentTextures / centredCoordinate (reciprocal from the host).
#include "common/shared_constants.h"
layout(local_size_x = SL_RTW_MOMENT_GROUP, local_size_y = SL_RTW_MOMENT_GROUP) in;
layout(r32ui, binding = SL_RTW_IMAGE_MOMENT_IM) readonly uniform uimage2D u_im;
layout(std430, binding = SL_RTW_BUFFER_MOMENTS) writeonly buffer Moments { float moments[]; };  // 6 per texel
uniform ivec2 u_size;
uniform vec2 u_invSize;

void main() {
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(t, u_size))) return;
  float I = uintBitsToFloat(imageLoad(u_im, t).r);
  float x = float(2 * t.x + 1 - u_size.x) * u_invSize.x;
  float y = float(2 * t.y + 1 - u_size.y) * u_invSize.y;
  int o = 6 * (t.y * u_size.x + t.x);
  moments[o + 0] = I;
  moments[o + 1] = x * I;
  moments[o + 2] = y * I;
  moments[o + 3] = (x * x) * I;
  moments[o + 4] = (y * y) * I;
  moments[o + 5] = (x * y) * I;
}
