// Deferred shadowing with ONE tile of a virtual shadow map (Giegl & Wimmer 2007, §3.2; C++:
// sl::applyTile in core/tiled/TiledVirtualMap): every pixel of the dispatched screen rectangle
// whose light uv in the full (virtual) map lies in the tile's [u_tileUvMin, u_tileUvMax)
// is shadowed with the tile — map 0 of the shared bias model (tile_lookup.glsl) — and
// written to the resolve targets; the others are left as they are (a later tile, or
// the clear). Each pixel's world position is rebuilt from the eye-space depth buffer with
// eq. 1 (common/tiled/eye_depth.glsl), not read from the G-buffer's positions. Aliasing m:
// finite differences over the pixel's 2x2 quad of the tile's texel coordinate (full-map uv
// times the tile's texels per uv).
#include "common/shared_constants.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = SL_UNIT_G_NORMAL) uniform sampler2D u_gNormal;
layout(r8ui, binding = SL_IMAGE_RESOLVE_HARD) writeonly uniform uimage2D o_hard;
layout(r8, binding = SL_IMAGE_RESOLVE_FILTERED) writeonly uniform image2D o_filtered;
layout(r32f, binding = SL_IMAGE_RESOLVE_ALIASING) writeonly uniform image2D o_aliasing;
layout(rg32f, binding = SL_IMAGE_RESOLVE_TEXEL) writeonly uniform image2D o_texel;
layout(r8ui, binding = SL_IMAGE_RESOLVE_MAP) writeonly uniform uimage2D o_map;
#include "common/light.glsl"
uniform ivec2 u_size;            // frame size in pixels
uniform ivec2 u_rectMin;         // the dispatch's screen rectangle starts here
uniform ivec2 u_rectMax;         // ... and ends here (exclusive)
uniform mat4 u_fullFromEye;      // eye -> the full virtual map's clip space (its view-proj x the inverse view)
uniform vec2 u_tileUvMin;        // the tile's part of the full map's light uv
uniform vec2 u_tileUvMax;
uniform vec2 u_texelsPerFullUv;  // the tile's texels per unit of full-map uv
uniform uint u_mapIndex;
// Only pixels still empty after the tiles (fvsm's fallback map): the hard target so far.
uniform bool u_onlyEmpty;
layout(binding = SL_UNIT_HARD) uniform usampler2D u_hardSoFar;

#include "common/tiled/eye_depth.glsl"
#include "common/tiled/tile_lookup.glsl"

// The full map's uv of eye-space position e (the pixels outside the tile stop here: one
// matrix, no world position).
vec2 fullUv(vec3 e) {
  vec4 c = u_fullFromEye * vec4(e, 1.0);
  return c.xy / c.w * 0.5 + 0.5;
}

// The tile's texel coordinate at pixel p (clamped into the frame); 0 without a surface.
vec2 texelAt(ivec2 p) {
  p = clamp(p, ivec2(0), u_size - 1);
  float d = eyeDepthAt(p);
  return d > 0.0 ? fullUv(eyePositionAt(p, d)) * u_texelsPerFullUv : vec2(0.0);
}

void main() {
  ivec2 px = u_rectMin + ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(px, min(u_rectMax, u_size)))) return;
  float d = eyeDepthAt(px);
  if (!(d > 0.0)) return;
  if (u_onlyEmpty && texelFetch(u_hardSoFar, px, 0).r != SL_MASK_EMPTY) return;
  vec3 e = eyePositionAt(px, d);
  vec2 uv = fullUv(e);
  if (any(lessThan(uv, u_tileUvMin)) || any(greaterThanEqual(uv, u_tileUvMax))) return;
  vec3 P = worldFromEye(e);

  // The quad: dX along the pixel's row, dY along its column, each between the quad's two
  // pixels — this one (its own coordinate, `own`) and its partner.
  ivec2 q = px & ~1;
  vec2 own = uv * u_texelsPerFullUv;
  vec2 dX = px.x == q.x ? texelAt(px + ivec2(1, 0)) - own : own - texelAt(px - ivec2(1, 0));
  vec2 dY = px.y == q.y ? texelAt(px + ivec2(0, 1)) - own : own - texelAt(px - ivec2(0, 1));
  float area = abs(dX.x * dY.y - dX.y * dY.x);
  vec3 N = texelFetch(u_gNormal, px, 0).xyz;
  ShadowCoord c = shadowLookupCoord(P, N);
  imageStore(o_texel, px, vec4(c.uvz.xy, 0.0, 0.0));
  imageStore(o_aliasing, px, vec4(area > 0.0 ? inversesqrt(area) : 0.0));
  imageStore(o_map, px, uvec4(u_mapIndex));
  uint hard;
  float filtered;
  if (dot(N, towardsLight(P)) <= 0.0 || lightIlluminates(P) < 0.5) {
    hard = SL_MASK_SHADOWED;
    filtered = 0.0;
  } else {
    hard = shadowHardAt(c) >= 0.5 ? SL_MASK_LIT : SL_MASK_SHADOWED;
    filtered = shadowFilteredAt(c);
  }
  imageStore(o_hard, px, uvec4(hard));
  imageStore(o_filtered, px, vec4(filtered));
}
