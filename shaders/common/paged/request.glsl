// RMSM page requests per camera pixel (Lefohn, Sengupta, Owens 2007), shared by the request
// pass (rmsm/requests.comp) and the lookup (rmsm/lookup.glsl), so both ask for the same
// page. C++ reference: sl::pages::pixelRequests / requestLevel / requestPage
// (renderer/algo/pages/PageRequests.cpp), line by line. Needs u_gPosition (the G-buffer's
// world position, w = covered) and u_gNormal declared before.
#include "common/shared_constants.h"
uniform mat4 u_rmsmViewProj;          // world -> the virtual map's clip space (orthographic)
uniform int u_rmsmVirtualResolution;  // virtual.resolution: texels per side of level 0
uniform int u_rmsmPageSize;           // page.size: texels per side of a page
uniform int u_rmsmLevels;             // levels of the quadtree (level 0 the finest)
uniform int u_rmsmLodBias;            // lod.bias: levels finer than the footprint asks for
uniform int u_rmsmDerivatives;        // lod.derivatives: SL_RMSM_DERIVATIVES_*

// The pixel's light uv (s, t); false where the G-buffer has no surface or px is outside.
bool rmsmPixelUv(ivec2 px, out vec2 st) {
  st = vec2(0.0);
  ivec2 size = textureSize(u_gPosition, 0);
  if (any(lessThan(px, ivec2(0))) || any(greaterThanEqual(px, size))) return false;
  vec4 P = texelFetch(u_gPosition, px, 0);
  if (!(P.w > 0.0)) return false;
  vec4 c = u_rmsmViewProj * vec4(P.xyz, 1.0);
  st = c.xy / c.w * 0.5 + 0.5;
  return true;
}

// Pixel q lies on pixel px's surface (sl::pages::sameSurface); both covered.
bool rmsmSameSurface(ivec2 px, ivec2 q) {
  vec3 P = texelFetch(u_gPosition, px, 0).xyz, N = texelFetch(u_gNormal, px, 0).xyz;
  vec3 d = texelFetch(u_gPosition, q, 0).xyz - P;
  return abs(dot(d, N)) <= float(SL_RMSM_SAME_SURFACE_PLANE) * length(d) &&
         dot(N, texelFetch(u_gNormal, q, 0).xyz) >= float(SL_RMSM_SAME_SURFACE_NORMAL_COS);
}

// The step to the neighbour at +1, else from the one at -1, else zero; same-surface
// derivatives first take the one on the pixel's surface (screenStep).
vec2 rmsmScreenStep(vec2 here, ivec2 px, ivec2 next, ivec2 prev) {
  vec2 o, p;
  bool nextOk = rmsmPixelUv(next, o), prevOk = rmsmPixelUv(prev, p);
  if (u_rmsmDerivatives == SL_RMSM_DERIVATIVES_SAME_SURFACE) {
    if (nextOk && rmsmSameSurface(px, next)) return o - here;
    if (prevOk && rmsmSameSurface(px, prev)) return here - p;
  }
  if (nextOk) return o - here;
  if (prevOk) return here - p;
  return vec2(0.0);
}

// floor(log2(sqrt(A))) - lod.bias, A = |dX x dY| in virtual texels, clamped (requestLevel).
int rmsmRequestLevel(vec2 dUvDx, vec2 dUvDy) {
  float v = float(u_rmsmVirtualResolution);
  vec2 dX = dUvDx * v;
  vec2 dY = dUvDy * v;
  float area = abs(dX.x * dY.y - dX.y * dY.x);
  if (!(area > 0.0)) return 0;
  int level = int(floor(0.5 * log2(area))) - u_rmsmLodBias;
  return clamp(level, 0, u_rmsmLevels - 1);
}

int rmsmPagesPerSide(int level) { return (u_rmsmVirtualResolution / u_rmsmPageSize) >> level; }

// The page of `level` holding light uv st, as a key (requestPage); SL_PAGE_NONE outside.
uint rmsmRequestPage(vec2 st, int level) {
  if (!(st.x >= 0.0 && st.x <= 1.0 && st.y >= 0.0 && st.y <= 1.0)) return SL_PAGE_NONE;
  int n = rmsmPagesPerSide(level);
  ivec2 p = min(ivec2(st * float(n)), ivec2(n - 1));
  return (uint(level) << SL_PAGE_KEY_LEVEL_SHIFT) | (uint(p.y) << SL_PAGE_KEY_COORD_BITS) |
         uint(p.x);
}

// The LOD pixel px asks for (-1: no surface there), from its and its neighbours' uv.
int rmsmPixelLevel(ivec2 px, out vec2 st) {
  if (!rmsmPixelUv(px, st)) return -1;
  vec2 dX = rmsmScreenStep(st, px, px + ivec2(1, 0), px - ivec2(1, 0));
  vec2 dY = rmsmScreenStep(st, px, px + ivec2(0, 1), px - ivec2(0, 1));
  return rmsmRequestLevel(dX, dY);
}
