// The one bias model of every depth-map lookup (uniform, RTW; later partitioned or paged
// maps): the receiver's plane is evaluated AT THE CENTRE OF THE TEXEL IT SAMPLES, in
// unwarped light space, and compared with the depth the map stores for that same centre.
// Maps store exact depth at texel centres (no polygon offset), so a planar receiver
// compares against itself exactly; the remaining terms, all scaled by the LOCAL texel
// size (warp compression included), only cover curvature, rounding and contact edges:
//   normal offset  P += N * bias.normal * T * sin(theta_L),   T = largest local texel (m)
//   slope term     bias.slope * (|dz/du| * t_u + |dz/dv| * t_v)   (t: local texel in uv),
//                  at most the depth of a slope of 10 over T
//   constant       bias.constant metres along the light, in window depth
// Orthographic and perspective light matrices alike (clip w = 1 for the former): the
// receiver's plane is carried through the full 4x4 matrix (a plane stays a plane, window
// depth stays affine in light uv on it); metres per uv grow with w; window depth per metre
// falls with w^2 (glm's perspective depth), so both terms convert per pixel.
// Needs common/light.glsl (towardsLight) included before.
// CPU mirror: sl::receiverDepthGradient / windowDepthPerM / shadowDepthBias
// (algo/ShadowBias.h); C++ binding: bindDepthLookup (core/ShadowPass.cpp).
//
// The technique's lookup file defines, BEFORE including this file:
//   vec2 lightToMapUv(vec2 uv)          unwarped light uv -> map uv (identity when unwarped)
//   vec2 texelCentreLightUv(ivec2 t)    centre of map texel t, in unwarped light uv
//   vec2 localTexelLightUv(vec2 uv)     extent of the map texel at light uv, per axis, in uv
// and gets shadowLookupCoord / shadowMapSize / shadowHardAt / shadowFilteredAt
// (the contract of shaders/common/resolve.frag). Nearest texels via texelFetch: metrics see
// the map's true resolution; PCF averages the hard tests of a (2r+1)^2 neighbourhood.
#include "common/light.glsl"

uniform sampler2D u_shadowMap;
uniform int u_pcfRadius;
uniform mat4 u_lightViewProj;
uniform mat3 u_lightNormalMatrix;  // plane of N in clip space (sl::lightPlaneMatrix().normal)
uniform vec3 u_lightPlaneOffset;   // times -dot(N, P) (sl::lightPlaneMatrix().offset; 0 ortho)
uniform vec2 u_lightExtentM;       // metres per unit of light u and v, at clip w = 1
uniform float u_biasNormal;        // texels (local)
uniform float u_biasSlope;         // texels (local)
uniform float u_biasConstant;      // window depth units, at clip w = 1
uniform float u_depthPerM;         // window depth per metre along the light, at clip w = 1

// The receiver of this pixel, set by shadowLookupCoord (one pixel per invocation).
vec2 g_receiverUv;   // unwarped light uv (after the normal offset)
float g_receiverZ;   // window depth
vec2 g_receiverDz;   // d(window depth) / d(light uv) on the receiver's plane
float g_receiverBias;

vec2 shadowMapSize() { return vec2(textureSize(u_shadowMap, 0)); }

// Depth gradient of the plane through P with world normal N, per unit of light uv: the
// plane in clip space m = u_lightNormalMatrix * N - u_lightPlaneOffset * dot(N, P);
// dz/du = -m.x / m.z (the 0.5 factors of uv and window depth cancel). A plane seen edge-on
// by the light (|m.z| tiny) gets 0: it is shadowed by the N.L test of the resolve pass, or
// covered by the slope term's clamp. C++: sl::receiverDepthGradient.
vec2 receiverDepthGradient(vec3 N, vec3 P) {
  vec3 m = u_lightNormalMatrix * N - u_lightPlaneOffset * dot(N, P);
  if (!(abs(m.z) > 1e-4 * length(m))) return vec2(0.0);
  return -m.xy / m.z;
}

vec3 shadowLookupCoord(vec3 P, vec3 N) {
  vec4 c0 = u_lightViewProj * vec4(P, 1.0);  // orthographic: w = 1
  // Behind a perspective light (w <= 0) nothing is lit anyway (lightIlluminates): keep the
  // arithmetic finite.
  float w = c0.w > 1e-6 ? c0.w : 1e-6;
  vec2 uv0 = c0.xy / w * 0.5 + 0.5;
  vec2 t0 = localTexelLightUv(uv0);
  float texelM = max(t0.x * u_lightExtentM.x, t0.y * u_lightExtentM.y) * w;
  float cosL = clamp(dot(N, towardsLight(P)), -1.0, 1.0);
  float sinL = sqrt(max(1.0 - cosL * cosL, 0.0));
  vec4 c = u_lightViewProj * vec4(P + N * (u_biasNormal * texelM * sinL), 1.0);
  vec3 uvz = c.xyz / (c.w > 1e-6 ? c.w : 1e-6) * 0.5 + 0.5;
  g_receiverUv = uvz.xy;
  g_receiverZ = uvz.z;
  g_receiverDz = receiverDepthGradient(N, P);
  vec2 t = t0;  // the offset moves the point by under a texel: same local texel size
  float perW2 = 1.0 / (w * w);  // window depth per metre falls with w^2 (sl::windowDepthPerM)
  // Capped at a slope of 10 (84 degrees from the light) so grazing receivers do not leak.
  float slope = min(abs(g_receiverDz.x) * t.x + abs(g_receiverDz.y) * t.y,
                    10.0 * texelM * (u_depthPerM * perW2));
  g_receiverBias = u_biasSlope * slope + u_biasConstant * perW2;
  return vec3(lightToMapUv(uvz.xy), uvz.z);
}

float depthMapTexelTest(vec3 uvz, ivec2 offset) {
  ivec2 size = textureSize(u_shadowMap, 0);
  ivec2 t = clamp(ivec2(floor(uvz.xy * vec2(size))) + offset, ivec2(0), size - 1);
  vec2 centre = texelCentreLightUv(t);
  float z = g_receiverZ + dot(g_receiverDz, centre - g_receiverUv) - g_receiverBias;
  return z <= texelFetch(u_shadowMap, t, 0).r ? 1.0 : 0.0;
}

float shadowHardAt(vec3 uvz) {
  if (any(lessThan(uvz.xy, vec2(0.0))) || any(greaterThan(uvz.xy, vec2(1.0)))) return 1.0;
  return depthMapTexelTest(uvz, ivec2(0));
}

float shadowFilteredAt(vec3 uvz) {
  if (u_pcfRadius == 0) return shadowHardAt(uvz);
  float sum = 0.0;
  for (int y = -u_pcfRadius; y <= u_pcfRadius; ++y)
    for (int x = -u_pcfRadius; x <= u_pcfRadius; ++x) sum += depthMapTexelTest(uvz, ivec2(x, y));
  return sum / float((2 * u_pcfRadius + 1) * (2 * u_pcfRadius + 1));
}
