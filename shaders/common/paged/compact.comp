// RMSM steps 2 and 3, also ASM's compaction of its edge requests (C++:
// RmsmShadowMap::requestPages, AsmShadowMap; reference sl::pages::dedupRequests and
// compactRequests): a request stays only when its left and lower neighbours ask for a
// different page; the survivors are appended to one buffer (an atomic counter: compaction
// in arbitrary order, which sort + unique make canonical).
#include "common/shared_constants.h"
layout(local_size_x = SL_RMSM_GROUP, local_size_y = SL_RMSM_GROUP) in;
layout(r32ui, binding = SL_RMSM_IMAGE_REQUESTS) readonly uniform uimage2D u_requests;
layout(std430, binding = SL_RMSM_BUFFER_REQUESTS) buffer Requests {
  uint count;    // cleared to 0 by the C++; may exceed the capacity (only capacity are kept)
  uint keys[];   // capacity = the pixel count
};

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(u_requests);
  if (any(greaterThanEqual(px, size))) return;
  uint key = imageLoad(u_requests, px).r;
  if (key == SL_PAGE_NONE) return;
  if (px.x > 0 && imageLoad(u_requests, px - ivec2(1, 0)).r == key) return;
  if (px.y > 0 && imageLoad(u_requests, px - ivec2(0, 1)).r == key) return;
  uint i = atomicAdd(count, 1u);
  if (i < uint(keys.length())) keys[i] = key;
}
