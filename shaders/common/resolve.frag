// Resolve pass: per camera pixel, the technique's shadow test. Writes the hard mask
// (SL_MASK_*: lit, shadowed, no surface) that the metrics compare with the Embree
// reference, the filtered visibility used for shading, aliasing m and the selected map's
// uv (grid overlay) and index (partition overlay). Surfaces facing away from the light are
// shadowed, exactly as in ShadowReference::isLit (C++), and so is what lies outside a spot's
// cone or a light's range (common/light.glsl). Techniques that resolve in their own deferred pass
// (Technique::resolveDeferred) write the same four targets themselves.
// A technique's lookup ("@lookup") defines, over any number of maps:
//   ShadowCoord shadowLookupCoord(vec3 P, vec3 N)  selects a map (common/shadow_coord.glsl),
//                                                  its uv (through any warp) and depth
//   vec2 shadowMapSize(int map)                    texels of that map
//   vec2 shadowMapUvOf(int map, vec3 P)            world point P's uv in THAT map (no
//                                                  selection, no offset; may leave [0, 1])
//   float shadowHardAt(ShadowCoord c), float shadowFilteredAt(ShadowCoord c)   1 = lit
// so the (possibly warped) coordinate is computed once per pixel. Depth-map techniques
// get all four from common/depth_map_test.glsl; the light (common/light.glsl, bound by
// sl::bindLight) is included before the lookup.
#include "common/shared_constants.h"
#include "common/shadow_coord.glsl"
#include "common/light.glsl"
layout(binding = SL_UNIT_G_POSITION) uniform sampler2D u_gPosition;
layout(binding = SL_UNIT_G_NORMAL) uniform sampler2D u_gNormal;

#include "@lookup"

layout(location = 0) out uint o_hard;
layout(location = 1) out float o_filtered;
layout(location = 2) out float o_aliasing;  // m: texel footprint / pixel footprint
layout(location = 3) out vec2 o_texel;      // the selected map's uv, for the grid
layout(location = 4) out uint o_map;        // the selected map's index (partition overlay)

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, px, 0);
  vec3 N = texelFetch(u_gNormal, px, 0).xyz;
  // Derivatives first, in uniform control flow (techniques.md, "Measuring"; RMSM's LOD):
  // A = |dX x dY| texels of the SELECTED map per pixel, m = 1 / sqrt(A).
  ShadowCoord c = P.w > 0.0 ? shadowLookupCoord(P.xyz, N) : ShadowCoord(0, vec3(0.0));
  vec2 texel = c.uvz.xy * shadowMapSize(c.map);
  vec2 dX = dFdxFine(texel), dY = dFdyFine(texel);
  // At a seam (a cube face edge, the paraboloid rim, a cascade split) the pixel's quad
  // partner selected ANOTHER map: the difference of two maps' texel coordinates says nothing
  // (a jump of up to a whole map: m falsely near 0). There the partner's surface point is
  // mapped into THIS pixel's map instead (maps extend beyond their edges: a plane, a
  // paraboloid): one finite difference in one map, as everywhere else. Fine derivatives
  // (own row / column of the quad) so the partner is known; not across a silhouette to the
  // background (no partner point). Tested: OmniAliasing (tests/gl).
  bvec2 otherMap = bvec2(dFdxFine(float(c.map)) != 0.0, dFdyFine(float(c.map)) != 0.0);
  bvec2 partnerCovered = bvec2(dFdxFine(P.w) == 0.0, dFdyFine(P.w) == 0.0);
  vec3 dPdx = dFdxFine(P.xyz), dPdy = dFdyFine(P.xyz);
  if (P.w > 0.0 && any(otherMap)) {
    // dFdxFine = value(x | 1) - value(x & ~1): the partner is P + d on even, P - d on odd.
    vec2 odd = vec2(ivec2(gl_FragCoord.xy) & 1);
    vec2 size = shadowMapSize(c.map);
    vec2 here = shadowMapUvOf(c.map, P.xyz);
    if (otherMap.x && partnerCovered.x)
      dX = (shadowMapUvOf(c.map, P.xyz + (1.0 - 2.0 * odd.x) * dPdx) - here) * size;
    if (otherMap.y && partnerCovered.y)
      dY = (shadowMapUvOf(c.map, P.xyz + (1.0 - 2.0 * odd.y) * dPdy) - here) * size;
  }
  float area = abs(dX.x * dY.y - dX.y * dY.x);
  o_texel = c.uvz.xy;
  o_map = uint(clamp(c.map, 0, 255));
  o_aliasing = P.w > 0.0 && area > 0.0 ? inversesqrt(area) : 0.0;
  if (P.w <= 0.0) {
    o_hard = SL_MASK_EMPTY;
    o_filtered = 1.0;
    return;
  }
  if (dot(N, towardsLight(P.xyz)) <= 0.0 || lightIlluminates(P.xyz) < 0.5) {
    o_hard = SL_MASK_SHADOWED;
    o_filtered = 0.0;
    return;
  }
  o_hard = shadowHardAt(c) >= 0.5 ? SL_MASK_LIT : SL_MASK_SHADOWED;
  o_filtered = shadowFilteredAt(c);
}
