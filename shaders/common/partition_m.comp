// Per-partition statistics of the perspective aliasing m of the previous frame (C++:
// core/PartitionMStats, for cascades and face-partition): for every covered pixel, its m
// (resolve target 2) goes to the histogram of the map it selected (resolve target 4):
// SL_CASCADE_M_BINS bins over log2 m in [SL_CASCADE_M_LOG2_MIN, SL_CASCADE_M_LOG2_MAX), then
// the pixel count and the largest m (float bits; m > 0 orders like its bits as uint).
#include "common/shared_constants.h"
layout(local_size_x = SL_CASCADE_GROUP, local_size_y = SL_CASCADE_GROUP) in;
layout(binding = SL_UNIT_ALIASING) uniform sampler2D u_aliasing;
layout(binding = SL_UNIT_MAP_INDEX) uniform usampler2D u_mapIndex;
layout(std430, binding = SL_CASCADE_BUFFER_M_STATS) buffer MStats {
  uint stats[];  // per map: [bins][count][max bits], cleared to 0 by the C++
};
uniform ivec2 u_size;
uniform int u_maps;

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(px, u_size))) return;
  float m = texelFetch(u_aliasing, px, 0).r;
  if (!(m > 0.0)) return;  // uncovered (or no finite footprint)
  uint map = texelFetch(u_mapIndex, px, 0).r;
  if (map >= uint(u_maps)) return;  // a frame with more maps than this one
  const float perOctave = float(SL_CASCADE_M_BINS) / (SL_CASCADE_M_LOG2_MAX - SL_CASCADE_M_LOG2_MIN);
  int bin = clamp(int(floor((log2(m) - SL_CASCADE_M_LOG2_MIN) * perOctave)), 0, SL_CASCADE_M_BINS - 1);
  uint base = map * uint(SL_CASCADE_M_BINS + 2);
  atomicAdd(stats[base + uint(bin)], 1u);
  atomicAdd(stats[base + uint(SL_CASCADE_M_BINS)], 1u);
  atomicMax(stats[base + uint(SL_CASCADE_M_BINS) + 1u], floatBitsToUint(m));
}
