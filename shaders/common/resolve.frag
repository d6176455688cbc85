// Resolve pass: per camera pixel, the technique's shadow test. Writes the hard mask
// (1 lit, 0 shadowed, 255 no surface) that the metrics compare with the Embree reference,
// and the filtered visibility used for shading. Surfaces facing away from the light are
// shadowed, exactly as in ShadowReference::isLit (C++), and so is what lies outside a
// spot's cone or a light's range (common/light.glsl).
// A technique's lookup ("@lookup") defines:
//   vec3 shadowLookupCoord(vec3 P, vec3 N)  final map uv (through any warp) and depth
//   vec2 shadowMapSize()                    texels
//   float shadowHardAt(vec3 uvz), float shadowFilteredAt(vec3 uvz)   1 = lit
// so the (possibly warped) coordinate is computed once per pixel.
uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
#include "common/light.glsl"

#include "@lookup"

layout(location = 0) out uint o_hard;
layout(location = 1) out float o_filtered;
layout(location = 2) out float o_aliasing;  // m: texel footprint / pixel footprint
layout(location = 3) out vec2 o_texel;      // final (warped) shadow-map uv, for the grid

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, px, 0);
  vec3 N = texelFetch(u_gNormal, px, 0).xyz;
  // Derivatives first, in uniform control flow (techniques.md, "Measuring"; RMSM's LOD):
  // A = |dX x dY| texels per pixel, m = 1 / sqrt(A).
  vec3 uvz = P.w > 0.0 ? shadowLookupCoord(P.xyz, N) : vec3(0.0);
  vec2 texel = uvz.xy * shadowMapSize();
  vec2 dX = dFdx(texel), dY = dFdy(texel);
  float area = abs(dX.x * dY.y - dX.y * dY.x);
  o_texel = uvz.xy;
  o_aliasing = P.w > 0.0 && area > 0.0 ? inversesqrt(area) : 0.0;
  if (P.w <= 0.0) {
    o_hard = 255u;
    o_filtered = 1.0;
    return;
  }
  if (dot(N, towardsLight(P.xyz)) <= 0.0 || lightIlluminates(P.xyz) < 0.5) {
    o_hard = 0u;
    o_filtered = 0.0;
    return;
  }
  o_hard = shadowHardAt(uvz) >= 0.5 ? 1u : 0u;
  o_filtered = shadowFilteredAt(uvz);
}
