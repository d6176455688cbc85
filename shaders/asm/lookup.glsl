// ASM lookup (C++: AsmShadowMap::bindLookup; Fernando et al. 2001): the finest page the
// adaptive quadtree holds at the point, whatever the pixel's footprint (the page table's
// level 0 entry is its finest allocated ancestor, sl::pages::PageTable::finalised); that
// page's level is the selected "map" (common/paged/page_fetch.glsl: the pages and the pool are RMSM's).
#include "common/shared_constants.h"
#include "common/paged/request.glsl"
#include "common/paged/page_fetch.glsl"

int selectShadowMap(vec3 P) {
  vec4 c = u_rmsmViewProj * vec4(P, 1.0);
  vec2 st = clamp(c.xy / c.w * 0.5 + 0.5, vec2(0.0), vec2(1.0));
  int n = rmsmPagesPerSide(0);
  uint e = rmsmEntry(0, min(ivec2(st * float(n)), ivec2(n - 1)));
  return e == SL_PAGE_NONE ? u_rmsmLevels - 1 : int(e & 31u);
}

#include "common/depth_map_test.glsl"
