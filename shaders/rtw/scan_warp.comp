// Importance floor, work-efficient (Blelloch) prefix sum in shared memory, and the warp
// map, one work group per axis. Mirrors sl::rtw::applyImportanceFloor, blellochScan (same
// up-sweep / down-sweep order, zero padding to m = bit_ceil(n)) and warpFromImportance:
// warp[e] = S[e-1] / S[n-1] - e/n for 0 < e < n, warp[0] = warp[n] = 0.
#include "common/shared_constants.h"
#define SCAN_GROUP (SL_IM_MAX_RESOLUTION / 2)  // invocations per axis
layout(local_size_x = SCAN_GROUP) in;
layout(std430, binding = SL_RTW_BUFFER_BLURRED) buffer Blurred { float blurred[]; };  // floored in place
layout(std430, binding = SL_RTW_BUFFER_WARP) writeonly buffer WarpOut { float warpEdges[]; };
uniform int u_n;
uniform int u_m;  // bit_ceil(n) <= SL_IM_MAX_RESOLUTION
uniform float u_floor;
shared float a[SL_IM_MAX_RESOLUTION];
shared float red[SCAN_GROUP];

void main() {
  int axis = int(gl_WorkGroupID.x), lid = int(gl_LocalInvocationID.x);
  int base = axis * u_n;
  float mx = 0.0;
  for (int i = lid; i < u_n; i += SCAN_GROUP) mx = max(mx, blurred[base + i]);
  red[lid] = mx;
  barrier();
  for (int s = SCAN_GROUP / 2; s > 0; s >>= 1) {
    if (lid < s) red[lid] = max(red[lid], red[lid + s]);
    barrier();
  }
  float vmax = red[0];
  float lo = clamp(u_floor, 0.0, 1.0) * vmax;
  for (int i = lid; i < u_m; i += SCAN_GROUP) {
    float v = 0.0;
    if (i < u_n) {
      v = vmax > 0.0 ? max(blurred[base + i], lo) : 1.0;
      blurred[base + i] = v;
    }
    a[i] = v;
  }
  barrier();
  for (int d = 1; d < u_m; d *= 2) {  // up-sweep
    for (int j = lid; j < u_m / (2 * d); j += SCAN_GROUP) {
      int k = j * 2 * d;
      a[k + 2 * d - 1] = a[k + d - 1] + a[k + 2 * d - 1];
    }
    barrier();
  }
  float total = a[u_m - 1];
  barrier();
  if (lid == 0) a[u_m - 1] = 0.0;
  barrier();
  for (int d = u_m / 2; d >= 1; d /= 2) {  // down-sweep
    for (int j = lid; j < u_m / (2 * d); j += SCAN_GROUP) {
      int k = j * 2 * d;
      float t = a[k + d - 1];
      a[k + d - 1] = a[k + 2 * d - 1];
      a[k + 2 * d - 1] = t + a[k + 2 * d - 1];
    }
    barrier();
  }
  // Inclusive S[i] = a[i + 1] (i + 1 < m) or the total.
  float T = u_n < u_m ? a[u_n] : total;
  int wbase = axis * (u_n + 1);
  bool ok = T > 0.0 && !isinf(T);
  for (int e = lid; e <= u_n; e += SCAN_GROUP) {
    float w = 0.0;
    if (ok && e > 0 && e < u_n) w = a[e] / T - float(e) / float(u_n);
    warpEdges[wbase + e] = w;
  }
}
