// Multi-pass shadowing with ONE kd leaf (Giegl & Wimmer 2007, §3.1; C++: the fvsm technique with
// fvsm.apply = multi-pass): the scene is rasterised again from the camera (common/gbuffer.vert)
// with the depth test EQUAL against the technique's own depth pre-pass (u_depthOnly: that
// pass, writing nothing else), and each fragment whose light uv in the full (virtual) map
// lies in the leaf's [u_tileUvMin, u_tileUvMax) is shadowed with the leaf — map 0 of the
// shared bias model, as in the deferred pass (common/tiled/apply_tile.comp) — and written to
// the resolve targets; the others are discarded (the paper's "pixels outside the tile are
// suppressed"). The world position is the rasterised one, not rebuilt from eye depth.
// Aliasing m: screen-space derivatives of the leaf's texel coordinate (full-map uv times its
// texels per uv), taken before any discard.
#include "common/shared_constants.h"
#include "common/material.glsl"
#include "common/light.glsl"
in vec3 v_worldPos;
in vec3 v_worldNormal;
in vec2 v_uv;
uniform vec3 u_cameraPos;
uniform bool u_depthOnly;        // the depth pre-pass: no outputs
uniform mat4 u_fullViewProj;     // world -> the full virtual map's clip space
uniform vec2 u_tileUvMin;        // the leaf's part of the full map's light uv
uniform vec2 u_tileUvMax;
uniform vec2 u_texelsPerFullUv;  // the leaf's texels per unit of full-map uv
uniform uint u_mapIndex;

#include "common/tiled/tile_lookup.glsl"

layout(location = 0) out uint o_hard;
layout(location = 1) out float o_filtered;
layout(location = 2) out float o_aliasing;
layout(location = 3) out vec2 o_texel;
layout(location = 4) out uint o_map;

void main() {
  vec4 c = u_fullViewProj * vec4(v_worldPos, 1.0);
  vec2 uv = c.xy / c.w * 0.5 + 0.5;
  vec2 texel = uv * u_texelsPerFullUv;
  vec2 dX = dFdxFine(texel), dY = dFdyFine(texel);  // uniform control flow
  if (materialAlphaRejects(v_uv)) discard;
  if (u_depthOnly) return;
  if (any(lessThan(uv, u_tileUvMin)) || any(greaterThanEqual(uv, u_tileUvMax))) discard;
  vec3 P = v_worldPos;
  vec3 N = normalize(v_worldNormal);
  if (dot(N, u_cameraPos - P) < 0.0) N = -N;  // facing the camera, as the G-buffer's
  float area = abs(dX.x * dY.y - dX.y * dY.x);
  ShadowCoord sc = shadowLookupCoord(P, N);
  o_texel = sc.uvz.xy;
  o_aliasing = area > 0.0 ? inversesqrt(area) : 0.0;
  o_map = u_mapIndex;
  if (dot(N, towardsLight(P)) <= 0.0 || lightIlluminates(P) < 0.5) {
    o_hard = SL_MASK_SHADOWED;
    o_filtered = 0.0;
  } else {
    o_hard = shadowHardAt(sc) >= 0.5 ? SL_MASK_LIT : SL_MASK_SHADOWED;
    o_filtered = shadowFilteredAt(sc);
  }
}
