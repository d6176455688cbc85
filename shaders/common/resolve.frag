// Resolve pass: per camera pixel, the technique's shadow test. Writes the hard mask
// (1 lit, 0 shadowed, 255 no surface) that the metrics compare with the Embree reference,
// and the filtered visibility used for shading. Surfaces facing away from the light are
// shadowed, exactly as in ShadowReference::isLit (C++).
uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
uniform vec3 u_towardsLight;

#include "@lookup"

layout(location = 0) out uint o_hard;
layout(location = 1) out float o_filtered;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, px, 0);
  if (P.w <= 0.0) {
    o_hard = 255u;
    o_filtered = 1.0;
    return;
  }
  vec3 N = texelFetch(u_gNormal, px, 0).xyz;
  if (dot(N, u_towardsLight) <= 0.0) {
    o_hard = 0u;
    o_filtered = 0.0;
    return;
  }
  o_hard = shadowHard(P.xyz, N) >= 0.5 ? 1u : 0u;
  o_filtered = shadowFiltered(P.xyz, N);
}
