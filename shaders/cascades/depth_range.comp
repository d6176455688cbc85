// Min and max view depth of the covered G-buffer pixels (C++: CascadedShadowMap::
// reduceDepthRange): per work group in shared memory, then one atomic per group into a
// 2-uint buffer. Depths are >= 0, whose float bits order like the floats as uints.
#include "common/shared_constants.h"
layout(local_size_x = SL_CASCADE_GROUP, local_size_y = SL_CASCADE_GROUP) in;
layout(binding = SL_UNIT_G_POSITION) uniform sampler2D u_gPosition;
layout(std430, binding = SL_CASCADE_BUFFER_DEPTH_RANGE) buffer DepthRange {
  uint minBits;  // cleared to FLT_MAX's bits by the C++
  uint maxBits;  // cleared to 0
};
uniform vec3 u_eye;
uniform vec3 u_forward;
uniform ivec2 u_size;
shared uint s_min, s_max;

void main() {
  if (gl_LocalInvocationIndex == 0u) {
    s_min = 0x7f7fffffu;
    s_max = 0u;
  }
  barrier();
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (all(lessThan(px, u_size))) {
    vec4 P = texelFetch(u_gPosition, px, 0);
    if (P.w > 0.0) {
      uint d = floatBitsToUint(max(dot(P.xyz - u_eye, u_forward), 0.0));
      atomicMin(s_min, d);
      atomicMax(s_max, d);
    }
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u) {
    atomicMin(minBits, s_min);
    atomicMax(maxBits, s_max);
  }
}
