// RMSM step 1 (C++: RmsmShadowMap::requestPages; reference sl::pages::pixelRequests): every
// camera pixel's page request, written as its key into an r32ui image.
#include "common/shared_constants.h"
layout(local_size_x = SL_RMSM_GROUP, local_size_y = SL_RMSM_GROUP) in;
layout(binding = SL_UNIT_G_POSITION) uniform sampler2D u_gPosition;
layout(binding = SL_UNIT_G_NORMAL) uniform sampler2D u_gNormal;
layout(r32ui, binding = SL_RMSM_IMAGE_REQUESTS) writeonly uniform uimage2D u_requests;
#include "common/paged/request.glsl"

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(px, textureSize(u_gPosition, 0)))) return;
  vec2 st;
  int level = rmsmPixelLevel(px, st);
  uint key = level < 0 ? SL_PAGE_NONE : rmsmRequestPage(st, level);
  imageStore(u_requests, px, uvec4(key));
}
