// ASM shadow test, per camera pixel (C++: AsmShadowMap::findEdges; Fernando et al. 2001, the
// lecture's "lookup shadow map texel"): the resolve pass's hard test through the quadtree as it
// stands (asm/lookup.glsl, the shared bias model), the page that test read, and the page at
// the pixel's LOD (common/paged/request.glsl) when that page is finer (sl::adaptive::refineKey), and
// whether the texel the test read lies on a shadow edge of the map (Fernando et al. 2001; C++
// reference: sl::adaptive::mapTexelOnShadowEdge): the same depth test at that texel and at its
// 4 neighbours in the map, whatever the pixel faces, do not all agree.
#include "common/shared_constants.h"
layout(local_size_x = SL_RMSM_GROUP, local_size_y = SL_RMSM_GROUP) in;
layout(binding = SL_UNIT_G_POSITION) uniform sampler2D u_gPosition;
layout(binding = SL_UNIT_G_NORMAL) uniform sampler2D u_gNormal;
layout(rgba32ui, binding = SL_ASM_IMAGE_TESTED) writeonly uniform uimage2D u_tested;
#include "common/light.glsl"
#include "asm/lookup.glsl"

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(px, textureSize(u_gPosition, 0)))) return;
  vec4 P = texelFetch(u_gPosition, px, 0);
  if (!(P.w > 0.0)) {
    imageStore(u_tested, px, uvec4(SL_MASK_EMPTY, SL_PAGE_NONE, SL_PAGE_NONE, 0u));
    return;
  }
  vec3 N = texelFetch(u_gNormal, px, 0).xyz;
  ShadowCoord c = shadowLookupCoord(P.xyz, N);
  // As resolve.frag: facing away from the light or outside it is shadowed.
  uint mask = SL_MASK_SHADOWED;
  if (dot(N, towardsLight(P.xyz)) > 0.0 && lightIlluminates(P.xyz) >= 0.5)
    mask = shadowHardAt(c) >= 0.5 ? SL_MASK_LIT : SL_MASK_SHADOWED;
  uint served = rmsmRequestPage(clamp(c.uvz.xy, vec2(0.0), vec2(1.0)), c.map);
  vec2 st;
  int needed = rmsmPixelLevel(px, st);
  uint refine = needed >= 0 && c.map > needed ? rmsmRequestPage(st, needed) : SL_PAGE_NONE;
  uint mapEdge = 0u;
  if (all(greaterThanEqual(c.uvz.xy, vec2(0.0))) && all(lessThanEqual(c.uvz.xy, vec2(1.0)))) {
    float centre = depthMapTexelTest(c, ivec2(0));
    const ivec2 offsets[4] = ivec2[4](ivec2(-1, 0), ivec2(1, 0), ivec2(0, -1), ivec2(0, 1));
    for (int i = 0; i < 4; ++i)
      if (depthMapTexelTest(c, offsets[i]) != centre) mapEdge = 1u;
  }
  imageStore(u_tested, px, uvec4(mask, served, refine, mapEdge));
}
