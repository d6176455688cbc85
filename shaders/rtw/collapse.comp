// Collapse the IM to two 1D maps: max over each column (x map) and each row (y map).
// Mirrors sl::rtw::collapseColumnsMax / collapseRowsMax. The IM holds float bits; for
// values >= +0 the unsigned max equals the float max.
#include "common/shared_constants.h"
layout(local_size_x = SL_RTW_LINEAR_GROUP) in;
layout(r32ui, binding = SL_RTW_IMAGE_IM) readonly uniform uimage2D u_im;
layout(std430, binding = SL_RTW_BUFFER_COLLAPSED) writeonly buffer Collapsed { float collapsed[]; };  // [x n][y n]
uniform int u_n;

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= 2 * u_n) return;
  int axis = i / u_n, k = i - axis * u_n;
  uint m = 0u;
  for (int j = 0; j < u_n; ++j) m = max(m, imageLoad(u_im, axis == 0 ? ivec2(k, j) : ivec2(j, k)).r);
  collapsed[i] = uintBitsToFloat(m);
}
