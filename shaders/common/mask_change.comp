// The hard mask's change since the previous frame, without reading either mask back: per
// work group shared counters of the pixels covered in both frames and of those whose lit /
// shadowed state differs, added to one small buffer. CPU mirror: sl::compareConsecutiveMasks
// (algo/metrics/BenchStats.h); the changed overlay (composite.frag) draws the same pixels.
#include "common/shared_constants.h"
layout(local_size_x = SL_MASK_CHANGE_GROUP, local_size_y = SL_MASK_CHANGE_GROUP) in;
layout(binding = SL_UNIT_HARD) uniform usampler2D u_hard;          // this frame (SL_MASK_*)
layout(binding = SL_UNIT_PREV_HARD) uniform usampler2D u_prevHard;  // the previous frame
layout(std430, binding = SL_BUFFER_MASK_CHANGE) buffer MaskChange {
  uint compared;  // covered in both frames
  uint changed;   // of which lit in one and shadowed in the other
};

shared uint s_compared, s_changed;

void main() {
  if (gl_LocalInvocationIndex == 0u) {
    s_compared = 0u;
    s_changed = 0u;
  }
  barrier();
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (all(lessThan(px, textureSize(u_hard, 0)))) {
    uint now = texelFetch(u_hard, px, 0).r, before = texelFetch(u_prevHard, px, 0).r;
    if (now != SL_MASK_EMPTY && before != SL_MASK_EMPTY) {
      atomicAdd(s_compared, 1u);
      if ((now == SL_MASK_LIT) != (before == SL_MASK_LIT)) atomicAdd(s_changed, 1u);
    }
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u) {
    if (s_compared != 0u) atomicAdd(compared, s_compared);
    if (s_changed != 0u) atomicAdd(changed, s_changed);
  }
}
