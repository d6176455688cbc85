// ASM edge finding (C++ reference: sl::adaptive::findEdges, line by line; the lecture's "if
// texel on shadow edge & page not in ASM: convert (s, t, z, l) to page request"): a covered
// pixel is on a shadow edge when its mask differs from a covered 4-neighbour's
// (u_edgeTest = SL_ASM_EDGE_SCREEN) or when test.comp found its texel on a shadow edge of the
// map (SL_ASM_EDGE_MAP, Fernando et al. 2001); such a pixel with
// a refine key asks for that page; every other covered pixel touches the page it used
// (key | SL_ASM_TOUCH_BIT: the cache's LRU). Then common/paged/compact.comp dedups and compacts.
#include "common/shared_constants.h"
layout(local_size_x = SL_RMSM_GROUP, local_size_y = SL_RMSM_GROUP) in;
layout(rgba32ui, binding = SL_ASM_IMAGE_TESTED) readonly uniform uimage2D u_tested;
layout(r32ui, binding = SL_RMSM_IMAGE_REQUESTS) writeonly uniform uimage2D u_requests;
uniform int u_edgeTest;  // asm.edge: SL_ASM_EDGE_SCREEN or SL_ASM_EDGE_MAP

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(u_tested);
  if (any(greaterThanEqual(px, size))) return;
  uvec4 p = imageLoad(u_tested, px);
  uint key = SL_PAGE_NONE;
  if (p.x != SL_MASK_EMPTY) {
    bool edge = u_edgeTest == SL_ASM_EDGE_MAP && p.w != 0u;
    const ivec2 offsets[4] = ivec2[4](ivec2(-1, 0), ivec2(1, 0), ivec2(0, -1), ivec2(0, 1));
    for (int i = 0; i < 4 && u_edgeTest == SL_ASM_EDGE_SCREEN; ++i) {
      ivec2 q = px + offsets[i];
      if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
      uint m = imageLoad(u_tested, q).x;
      edge = edge || (m != SL_MASK_EMPTY && m != p.x);
    }
    if (edge && p.z != SL_PAGE_NONE)
      key = p.z;
    else if (p.y != SL_PAGE_NONE)
      key = p.y | SL_ASM_TOUCH_BIT;
  }
  imageStore(u_requests, px, uvec4(key));
}
