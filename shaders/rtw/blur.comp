// Gaussian blur of both 1D maps, clamp to edge, weights computed on the host by
// sl::rtw::gaussianWeights. Mirrors sl::rtw::gaussianBlur1D (ascending k).
#include "common/shared_constants.h"
layout(local_size_x = SL_RTW_LINEAR_GROUP) in;
layout(std430, binding = SL_RTW_BUFFER_COLLAPSED) readonly buffer Collapsed { float collapsed[]; };
layout(std430, binding = SL_RTW_BUFFER_BLURRED) writeonly buffer Blurred { float blurred[]; };
uniform int u_n;
uniform int u_radius;
uniform float u_weights[2 * SL_BLUR_MAX_RADIUS + 1];

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= 2 * u_n) return;
  int axis = i / u_n, k = i - axis * u_n, base = axis * u_n;
  float sum = 0.0;
  for (int d = -u_radius; d <= u_radius; ++d)
    sum += u_weights[d + u_radius] * collapsed[base + clamp(k + d, 0, u_n - 1)];
  blurred[i] = sum;
}
