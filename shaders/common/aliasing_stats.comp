// Aliasing statistics over the covered pixels without reading the m image back: per work
// group a shared histogram of log2 m (SL_ALIASING_BINS_PER_OCTAVE bins per octave), the
// count and the maximum (float bits: atomicMax on uint is the float max for m >= 0), added
// to one small buffer. CPU mirror: sl::Log2Histogram (algo/metrics/BenchStats.h).
#include "common/shared_constants.h"
layout(local_size_x = SL_ALIASING_GROUP, local_size_y = SL_ALIASING_GROUP) in;
layout(binding = SL_UNIT_ALIASING) uniform sampler2D u_aliasing;  // m, 0 where uncovered
layout(std430, binding = SL_BUFFER_ALIASING_STATS) buffer AliasingStats {
  uint counted;    // covered pixels with a finite m > 0
  uint maxBits;    // floatBitsToUint of the largest m
  uint nonFinite;  // pixels with m NaN or infinite
  uint reserved;
  uint bins[SL_ALIASING_BINS];
};

shared uint s_bins[SL_ALIASING_BINS];
shared uint s_counted, s_maxBits, s_nonFinite;

void main() {
  const uint local = gl_LocalInvocationIndex, groupSize = uint(SL_ALIASING_GROUP * SL_ALIASING_GROUP);
  for (uint b = local; b < uint(SL_ALIASING_BINS); b += groupSize) s_bins[b] = 0u;
  if (local == 0u) {
    s_counted = 0u;
    s_maxBits = 0u;
    s_nonFinite = 0u;
  }
  barrier();
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (all(lessThan(px, textureSize(u_aliasing, 0)))) {
    float m = texelFetch(u_aliasing, px, 0).r;
    if (isnan(m) || isinf(m)) {
      atomicAdd(s_nonFinite, 1u);
    } else if (m > 0.0) {
      float t = (log2(m) - float(SL_ALIASING_LOG2_MIN)) * float(SL_ALIASING_BINS_PER_OCTAVE);
      int bin = clamp(int(floor(t)), 0, SL_ALIASING_BINS - 1);
      atomicAdd(s_bins[bin], 1u);
      atomicAdd(s_counted, 1u);
      atomicMax(s_maxBits, floatBitsToUint(m));
    }
  }
  barrier();
  for (uint b = local; b < uint(SL_ALIASING_BINS); b += groupSize)
    if (s_bins[b] != 0u) atomicAdd(bins[b], s_bins[b]);
  if (local == 0u) {
    if (s_counted != 0u) {
      atomicAdd(counted, s_counted);
      atomicMax(maxBits, s_maxBits);
    }
    if (s_nonFinite != 0u) atomicAdd(nonFinite, s_nonFinite);
  }
}
