// The paged virtual map's texel fetch, shared by the RMSM and ASM lookups (rmsm/lookup.glsl,
// asm/lookup.glsl), which differ only in selectShadowMap: each level of the quadtree is one
// "map" of the shared bias model (common/depth_map_test.glsl), a virtual map of
// virtual.resolution >> level texels whose texels live in pages of one physical pool behind
// the page table (finalised on the CPU: sl::pages::PageTable::finalised). A texel of a
// neighbouring page that holds a coarser page (PCF, normal offset) is read from that page.
// Needs common/paged/request.glsl (the layout's uniforms) included before.
uniform sampler2D u_rmsmPool;         // DEPTH_COMPONENT32F: the pages side by side
uniform usampler2D u_rmsmPageTable;   // R32UI mip chain: slot << 5 | page level, per entry
uniform int u_rmsmPoolColumns;        // pages per row of the pool

uint rmsmEntry(int level, ivec2 page) { return texelFetch(u_rmsmPageTable, page, level).r; }

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
