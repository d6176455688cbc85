// Test technique "uniform-deferred" (tests/gl/TestTechniques.cpp): the uniform map resolved
// in the technique's own compute pass, writing the four resolve targets as images
// (ResolveTargets::bindForCompute) the way a tiled or screen-space technique would.
// Aliasing m by finite differences over the pixel's 2x2 quad (what dFdx/dFdy see in the
// renderer's fragment resolve), on the selected map's texel coordinate.
#include "common/shared_constants.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = SL_UNIT_G_POSITION) uniform sampler2D u_gPosition;
layout(binding = SL_UNIT_G_NORMAL) uniform sampler2D u_gNormal;
layout(r8ui, binding = SL_IMAGE_RESOLVE_HARD) writeonly uniform uimage2D o_hard;
layout(r8, binding = SL_IMAGE_RESOLVE_FILTERED) writeonly uniform image2D o_filtered;
layout(r32f, binding = SL_IMAGE_RESOLVE_ALIASING) writeonly uniform image2D o_aliasing;
layout(rg32f, binding = SL_IMAGE_RESOLVE_TEXEL) writeonly uniform image2D o_texel;
// The light: common/light.glsl, bound by sl::bindLight.
#include "common/light.glsl"
uniform ivec2 u_size;

#include "uniform/lookup.glsl"

// The selected map's texel coordinate at pixel p (clamped into the image).
vec2 texelAt(ivec2 p) {
  p = clamp(p, ivec2(0), u_size - 1);
  vec4 P = texelFetch(u_gPosition, p, 0);
  if (P.w <= 0.0) return vec2(0.0);
  ShadowCoord c = shadowLookupCoord(P.xyz, texelFetch(u_gNormal, p, 0).xyz);
  return c.uvz.xy * shadowMapSize(c.map);
}

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(px, u_size))) return;
  ivec2 q = px & ~1;  // the quad: dX along the pixel's row, dY along its column
  vec2 dX = texelAt(ivec2(q.x + 1, px.y)) - texelAt(ivec2(q.x, px.y));
  vec2 dY = texelAt(ivec2(px.x, q.y + 1)) - texelAt(ivec2(px.x, q.y));
  float area = abs(dX.x * dY.y - dX.y * dY.x);
  vec4 P = texelFetch(u_gPosition, px, 0);
  vec3 N = texelFetch(u_gNormal, px, 0).xyz;
  // Last: shadowLookupCoord leaves this pixel's receiver for the tests below.
  ShadowCoord c = P.w > 0.0 ? shadowLookupCoord(P.xyz, N) : ShadowCoord(0, vec3(0.0));
  imageStore(o_texel, px, vec4(c.uvz.xy, 0.0, 0.0));
  imageStore(o_aliasing, px, vec4(P.w > 0.0 && area > 0.0 ? inversesqrt(area) : 0.0));
  uint hard;
  float filtered;
  if (P.w <= 0.0) {
    hard = SL_MASK_EMPTY;
    filtered = 1.0;
  } else if (dot(N, towardsLight(P.xyz)) <= 0.0 || lightIlluminates(P.xyz) < 0.5) {
    hard = SL_MASK_SHADOWED;
    filtered = 0.0;
  } else {
    hard = shadowHardAt(c) >= 0.5 ? SL_MASK_LIT : SL_MASK_SHADOWED;
    filtered = shadowFilteredAt(c);
  }
  imageStore(o_hard, px, uvec4(hard));
  imageStore(o_filtered, px, vec4(filtered));
}
