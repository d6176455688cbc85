// Final shading: albedo lit by the light (Lambert, shadowed by the technique's filtered
// visibility, a spot's cone falloff and the range window: common/light.glsl) plus a sky
// ambient; a sky gradient where there is no surface.
#include "common/shared_constants.h"
#include "common/light.glsl"
layout(binding = SL_UNIT_G_POSITION) uniform sampler2D u_gPosition;
layout(binding = SL_UNIT_G_NORMAL) uniform sampler2D u_gNormal;
layout(binding = SL_UNIT_G_ALBEDO) uniform sampler2D u_gAlbedo;
layout(binding = SL_UNIT_VISIBILITY) uniform sampler2D u_visibility;
uniform float u_ambient;  // shading.ambient
uniform vec3 u_cameraPos;
layout(binding = SL_UNIT_HARD) uniform usampler2D u_hard;  // technique's hard mask (SL_MASK_*)
layout(binding = SL_UNIT_REFERENCE) uniform usampler2D u_reference;  // Embree mask of this view
layout(binding = SL_UNIT_ALIASING) uniform sampler2D u_aliasing;  // m per pixel
layout(binding = SL_UNIT_TEXEL) uniform sampler2D u_texel;  // selected map's uv (through any warp)
layout(binding = SL_UNIT_MAP_INDEX) uniform usampler2D u_mapIndex;  // selected map per pixel
layout(binding = SL_UNIT_PREV_HARD) uniform usampler2D u_prevHard;  // last frame's hard mask
uniform int u_overlay;  // view.overlay: SL_OVERLAY_*
// Pages per side of each map the lookup selects (Technique::pageGrid; 0: the map has no pages).
uniform int u_pageCells[SL_MAX_DEPTH_MAPS];
in vec2 v_uv;

// Diverging heat map for log2(m) in [-4, 4]: blue (oversampled), white, red (undersampled).
vec3 aliasingColor(float m) {
  float t = clamp(log2(max(m, 1e-6)) / 4.0, -1.0, 1.0);
  return t < 0.0 ? mix(vec3(1.0), vec3(0.15, 0.35, 0.95), -t) : mix(vec3(1.0), vec3(0.9, 0.1, 0.1), t);
}
// The partition overlay's colours, index mod SL_PARTITION_COLOURS (legend: view.overlay's
// help in rendererParamDecls).
vec3 partitionColor(uint i) {
  const vec3 c[SL_PARTITION_COLOURS] = vec3[](
      vec3(SL_PARTITION_COLOUR_0), vec3(SL_PARTITION_COLOUR_1), vec3(SL_PARTITION_COLOUR_2),
      vec3(SL_PARTITION_COLOUR_3), vec3(SL_PARTITION_COLOUR_4), vec3(SL_PARTITION_COLOUR_5),
      vec3(SL_PARTITION_COLOUR_6), vec3(SL_PARTITION_COLOUR_7));
  return c[i % uint(SL_PARTITION_COLOURS)];
}
out vec4 o_color;

// The page a pixel's lookup used (the pages overlay; CPU mirror sl::pages::pageBorders): its
// map and floor(uv * pages per side) in that map's page grid; x = -1 when uncovered or pageless.
ivec3 pageOf(ivec2 px) {
  if (texelFetch(u_gPosition, px, 0).w <= 0.0) return ivec3(-1);
  uint m = texelFetch(u_mapIndex, px, 0).r;
  int n = m < uint(SL_MAX_DEPTH_MAPS) ? u_pageCells[m] : 0;
  if (n <= 0) return ivec3(-1);
  ivec2 cell = ivec2(floor(texelFetch(u_texel, px, 0).xy * float(n)));
  return ivec3(int(m), clamp(cell, ivec2(0), ivec2(n - 1)));
}

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, px, 0);
  if (P.w <= 0.0) {
    vec3 horizon = vec3(0.78, 0.85, 0.93), zenith = vec3(0.36, 0.55, 0.80);
    o_color = vec4(mix(horizon, zenith, clamp(v_uv.y * 1.3 - 0.2, 0.0, 1.0)), 1.0);
    return;
  }
  vec3 N = texelFetch(u_gNormal, px, 0).xyz;
  vec3 albedo = texelFetch(u_gAlbedo, px, 0).rgb;
  float vis = texelFetch(u_visibility, px, 0).r;
  float ndl = max(dot(N, towardsLight(P.xyz)), 0.0) * lightFalloff(P.xyz);
  float sky = 0.5 + 0.5 * N.y;
  vec3 light = vec3(1.0, 0.96, 0.88) * ndl * vis + u_ambient * mix(vec3(0.55, 0.5, 0.45), vec3(0.75, 0.85, 1.0), sky);
  vec3 c = albedo * light;
  // Soft distance fog keeps far geometry readable.
  float d = length(P.xyz - u_cameraPos);
  c = mix(c, vec3(0.78, 0.85, 0.93), clamp((d - 150.0) / 900.0, 0.0, 0.6));
  c = pow(c, vec3(1.0 / 2.2));
  if (u_overlay == SL_OVERLAY_ERROR) {  // colours as in makeErrorImage (metrics/ErrorMetrics.h)
    uint h = texelFetch(u_hard, px, 0).r, r = texelFetch(u_reference, px, 0).r;
    float grey = dot(c, vec3(0.299, 0.587, 0.114)) * 0.5;
    c = vec3(grey);
    if (h == SL_MASK_LIT && r == SL_MASK_SHADOWED) c = vec3(1.0, 0.0, 1.0);
    if (h == SL_MASK_SHADOWED && r == SL_MASK_LIT) c = vec3(0.0, 1.0, 1.0);
  } else if (u_overlay == SL_OVERLAY_ALIASING) {
    c = mix(c, aliasingColor(texelFetch(u_aliasing, px, 0).r), 0.7);
  } else if (u_overlay == SL_OVERLAY_GRID) {
    vec2 g = texelFetch(u_texel, px, 0).xy * float(SL_GRID_LINES_PER_MAP);
    vec2 w = fwidth(g);
    vec2 d = abs(fract(g - 0.5) - 0.5) / max(w, vec2(1e-6));
    float line = 1.0 - clamp(min(d.x, d.y), 0.0, 1.0);
    c = mix(c, vec3(1.0, 0.85, 0.1), line * 0.85);
  } else if (u_overlay == SL_OVERLAY_PARTITION) {
    c = mix(c, partitionColor(texelFetch(u_mapIndex, px, 0).r), 0.55);
  } else if (u_overlay == SL_OVERLAY_CHANGED) {
    // The pixels common/mask_change.comp counts (CPU: compareConsecutiveMasks), in one vivid
    // colour over the scene dimmed to grey, so that a few changed pixels stand out.
    uint now = texelFetch(u_hard, px, 0).r, before = texelFetch(u_prevHard, px, 0).r;
    c = vec3(dot(c, vec3(0.299, 0.587, 0.114)) * 0.6);
    if (now != SL_MASK_EMPTY && before != SL_MASK_EMPTY && (now == SL_MASK_LIT) != (before == SL_MASK_LIT))
      c = vec3(SL_CHANGED_COLOUR);
  } else if (u_overlay == SL_OVERLAY_PAGES) {
    // The scene in grey, a pixel whose covered 4-neighbour uses another page (another level
    // or another page of its level) in one colour: the borders of the pages on the scene.
    c = vec3(dot(c, vec3(0.299, 0.587, 0.114)) * 0.8);
    ivec3 k = pageOf(px);
    ivec2 size = textureSize(u_gPosition, 0);
    const ivec2 d[4] = ivec2[](ivec2(-1, 0), ivec2(1, 0), ivec2(0, -1), ivec2(0, 1));
    bool border = false;
    for (int i = 0; i < 4 && k.x >= 0; ++i) {
      ivec2 q = px + d[i];
      if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
      ivec3 o = pageOf(q);
      border = border || (o.x >= 0 && o != k);
    }
    if (border) c = vec3(SL_PAGE_BORDER_COLOUR);
  }
  o_color = vec4(c, 1.0);
}
