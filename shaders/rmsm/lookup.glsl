// RMSM lookup (C++: RmsmShadowMap::bindLookup): the pixel asks for the LOD its footprint
// needs (rmsm/request.glsl, as the request pass did), the page table at that LOD gives the
// finest allocated page covering it (finalised on the CPU: sl::pages::PageTable::finalised),
// and that page's level is the selected "map": a virtual map of virtual.resolution >> level
// texels whose texels live in pages of one physical pool. The shared bias model
// (common/depth_map_test.glsl) then works in that level's texels. A texel of a neighbouring
// page that holds a coarser page (PCF, normal offset) is read from that coarser page.
#include "common/shared_constants.h"
#include "rmsm/request.glsl"
uniform sampler2D u_rmsmPool;         // DEPTH_COMPONENT32F: the pages side by side
uniform usampler2D u_rmsmPageTable;   // R32UI mip chain: slot << 5 | page level, per entry
uniform int u_rmsmPoolColumns;        // pages per row of the pool

uint rmsmEntry(int level, ivec2 page) { return texelFetch(u_rmsmPageTable, page, level).r; }

int selectShadowMap(vec3 P) {
  vec2 pixelSt;
  int level = max(rmsmPixelLevel(ivec2(gl_FragCoord.xy), pixelSt), 0);
  vec4 c = u_rmsmViewProj * vec4(P, 1.0);
  vec2 st = clamp(c.xy / c.w * 0.5 + 0.5, vec2(0.0), vec2(1.0));
  int n = rmsmPagesPerSide(level);
  uint e = rmsmEntry(level, min(ivec2(st * float(n)), ivec2(n - 1)));
  return e == SL_PAGE_NONE ? u_rmsmLevels - 1 : int(e & 31u);
}

ivec2 shadowMapTexels(int map) { return ivec2(u_rmsmVirtualResolution >> map); }

float shadowMapDepth(int map, ivec2 t) {
  int ps = u_rmsmPageSize;
  uint e = rmsmEntry(map, t / ps);
  if (e == SL_PAGE_NONE) return 1.0;  // nothing allocated (not even the root): lit
  int owner = int(e & 31u);
  int slot = int(e >> 5);
  ivec2 tt = t >> (owner - map);  // the texel at the owning page's level
  ivec2 origin = ivec2(slot % u_rmsmPoolColumns, slot / u_rmsmPoolColumns) * ps;
  return texelFetch(u_rmsmPool, origin + (tt - (tt / ps) * ps), 0).r;
}

vec2 lightToMapUv(int map, vec2 uv) { return uv; }
vec2 texelCentreLightUv(int map, ivec2 t) { return (vec2(t) + 0.5) / vec2(shadowMapTexels(map)); }
vec2 localTexelLightUv(int map, vec2 uv) { return 1.0 / vec2(shadowMapTexels(map)); }

#include "common/depth_map_test.glsl"
