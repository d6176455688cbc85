// Inverse warp tables: for each warped texel centre s = (i + 0.5) / size of each axis, the
// unwarped light coordinate u with warpCoordinate(u) = s. Mirrors sl::rtw::unwarpCoordinate
// (algo/rtw/Warp.cpp) operation for operation: binary search for the last edge e in
// [0, n-1] with c_e = e/n + warp[e] <= s, a plateau steps back to its first edge, else
// linear interpolation inside the edge interval (GLSL division: 2.5 ulp, parity 1e-6).
// The exact-depth warped pass and the lookup read these tables (SL_RTW_BUFFER_INVERSE).
#include "common/shared_constants.h"
layout(local_size_x = SL_RTW_LINEAR_GROUP) in;
layout(std430, binding = SL_RTW_BUFFER_WARP) readonly buffer WarpMaps { float warpEdges[]; };
layout(std430, binding = SL_RTW_BUFFER_INVERSE) writeonly buffer InverseOut { float inverseWarp[]; };
uniform int u_n;     // 1D map size (n + 1 edges per axis)
uniform int u_size;  // warped map size (entries per axis)

float edgeCoord(int base, int e) { return float(e) / float(u_n) + warpEdges[base + e]; }

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= 2 * u_size) return;
  int axis = i / u_size, k = i - axis * u_size;
  int base = axis * (u_n + 1);
  float s = (float(k) + 0.5) / float(u_size);
  int lo = 0, hi = u_n - 1;
  while (lo < hi) {
    int mid = (lo + hi + 1) / 2;
    if (edgeCoord(base, mid) <= s)
      lo = mid;
    else
      hi = mid - 1;
  }
  int e = lo;
  float ce = edgeCoord(base, e), cn = edgeCoord(base, e + 1);
  float u;
  if (s == ce) {
    while (e > 0 && edgeCoord(base, e - 1) == ce) --e;
    u = float(e) / float(u_n);
  } else {
    float t = cn > ce ? clamp((s - ce) / (cn - ce), 0.0, 1.0) : 0.0;
    u = (float(e) + t) / float(u_n);
  }
  inverseWarp[i] = u;
}
