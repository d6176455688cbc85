// Spherical (lat-long) lookup (C++: SphericalShadowMap::bindLookup; CPU mirror:
// omni::latLongHalfUv, omni::latLongWrapTexel). The mapping is not a matrix, so this file
// defines the contract functions of shaders/common/resolve.frag itself, with the bias model of
// the maps that store the distance along each texel's own direction
// (common/omni/texel_ray_lookup.glsl, as dual-paraboloid/lookup.glsl: the receiver's plane
// met by the ray through the centre of the texel it samples, the distance spherical/depth.frag
// stores); the local texel's height is pi / H radians (its width is cos(latitude) times that:
// narrower towards the poles).
// Map i = half i of the map (longitudes [-pi, 0) and [0, pi)), each H x H texels.
#include "common/shared_constants.h"
#include "common/omni/texel_ray_lookup.glsl"
#include "spherical/latlong.glsl"
uniform sampler2DArray u_sphMaps;

vec2 shadowMapSize(int map) { return vec2(textureSize(u_sphMaps, 0).xy); }

// P's uv in half `map`, continuing across its edges and the seam (resolve.frag's finite
// differences where a pixel's quad partner selected the other half).
vec2 shadowMapUvOf(int map, vec3 P) { return sphUvInHalf(map, P - u_omniLight); }

// Local texel at P in metres: its angular height times the distance.
float sphTexelM(vec3 P) { return length(P - u_omniLight) * kSphPi / shadowMapSize(0).y; }

ShadowCoord shadowLookupCoord(vec3 P, vec3 N) {
  vec3 d = omniSetReceiver(P, N, sphTexelM(P)) - u_omniLight;
  int m = sphHalf(d);
  return ShadowCoord(m, vec3(sphUvInHalf(m, d), omniStoredDistance(length(d))));
}

// A tap `offset` texels from c's texel on the whole 2H x H map; taps across the seam wrap,
// taps over a pole continue on the other side of it (sphWrapTexel).
float omniTapTest(ShadowCoord c, ivec2 offset) {
  int H = int(shadowMapSize(c.map).y);
  ivec2 local = clamp(ivec2(floor(c.uvz.xy * float(H))), ivec2(0), ivec2(H - 1));
  ivec2 t = sphWrapTexel(local + ivec2(c.map * H, 0) + offset, H);
  return omniReceiverTest(sphTexelDirection(t, H),
                          texelFetch(u_sphMaps, ivec3(t.x % H, t.y, t.x / H), 0).r);
}
