// Final shading: albedo lit by the light (Lambert, shadowed by the technique's filtered
// visibility, a spot's cone falloff and the range window: common/light.glsl) plus a sky
// ambient; a sky gradient where there is no surface.
uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
uniform sampler2D u_gAlbedo;
uniform sampler2D u_visibility;
#include "common/light.glsl"
uniform float u_ambient;
uniform vec3 u_cameraPos;
uniform usampler2D u_hard;       // technique's hard mask (1 lit, 0 shadow, 255 empty)
uniform usampler2D u_reference;  // Embree reference mask of this view
uniform sampler2D u_aliasing;    // m per pixel
uniform sampler2D u_texel;       // final shadow-map uv (through the warp) per pixel
uniform int u_overlay;           // 0 none, 1 error, 2 aliasing, 3 warp grid
in vec2 v_uv;

// Diverging heat map for log2(m) in [-4, 4]: blue (oversampled), white, red (undersampled).
vec3 aliasingColor(float m) {
  float t = clamp(log2(max(m, 1e-6)) / 4.0, -1.0, 1.0);
  return t < 0.0 ? mix(vec3(1.0), vec3(0.15, 0.35, 0.95), -t) : mix(vec3(1.0), vec3(0.9, 0.1, 0.1), t);
}
out vec4 o_color;

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
  if (u_overlay == 1) {  // colours as in makeErrorImage (metrics/ErrorMetrics.h)
    uint h = texelFetch(u_hard, px, 0).r, r = texelFetch(u_reference, px, 0).r;
    float grey = dot(c, vec3(0.299, 0.587, 0.114)) * 0.5;
    c = vec3(grey);
    if (h == 1u && r == 0u) c = vec3(1.0, 0.0, 1.0);
    if (h == 0u && r == 1u) c = vec3(0.0, 1.0, 1.0);
  } else if (u_overlay == 2) {
    c = mix(c, aliasingColor(texelFetch(u_aliasing, px, 0).r), 0.7);
  } else if (u_overlay == 3) {
    vec2 g = texelFetch(u_texel, px, 0).xy * 16.0;  // a line every 1/16 of the map
    vec2 w = fwidth(g);
    vec2 d = abs(fract(g - 0.5) - 0.5) / max(w, vec2(1e-6));
    float line = 1.0 - clamp(min(d.x, d.y), 0.0, 1.0);
    c = mix(c, vec3(1.0, 0.85, 0.1), line * 0.85);
  }
  o_color = vec4(c, 1.0);
}
