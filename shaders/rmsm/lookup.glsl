// RMSM lookup (C++: RmsmShadowMap::bindLookup): the pixel asks for the LOD its footprint
// needs (common/paged/request.glsl, as the request pass did), the page table at that LOD gives the
// finest allocated page covering it, and that page's level is the selected "map"
// (common/paged/page_fetch.glsl: the level's texels through the page table and the pool).
#include "common/shared_constants.h"
#include "common/paged/request.glsl"
#include "common/paged/page_fetch.glsl"

int selectShadowMap(vec3 P) {
  vec2 pixelSt;
  int level = max(rmsmPixelLevel(ivec2(gl_FragCoord.xy), pixelSt), 0);
  vec4 c = u_rmsmViewProj * vec4(P, 1.0);
  vec2 st = clamp(c.xy / c.w * 0.5 + 0.5, vec2(0.0), vec2(1.0));
  int n = rmsmPagesPerSide(level);
  uint e = rmsmEntry(level, min(ivec2(st * float(n)), ivec2(n - 1)));
  return e == SL_PAGE_NONE ? u_rmsmLevels - 1 : int(e & 31u);
}

#include "common/depth_map_test.glsl"
