// The one bias model of every depth-map lookup (uniform, RTW; partitioned, cascaded or paged
// maps): the receiver's plane is evaluated AT THE CENTRE OF THE TEXEL IT SAMPLES, in the
// SELECTED map's unwarped light space, and compared with the depth that map stores for that
// same centre. Maps store exact depth at texel centres (no polygon offset), so a planar
// receiver compares against itself exactly; the remaining terms, all scaled by the LOCAL
// texel size of the selected map (warp compression included), only cover curvature,
// rounding and contact edges:
//   normal offset  P += N * bias.normal * T * sin(theta_L),   T = largest local texel (m)
//   slope term     bias.slope * (|dz/du| * t_u + |dz/dv| * t_v)   (t: local texel in uv),
//                  at most the depth of a slope of 10 over T
//   constant       bias.constant metres along the light, in the map's window depth
// Orthographic and perspective map matrices alike (clip w = 1 for the former), per map: the
// receiver's plane is carried through the map's full 4x4 matrix (a plane stays a plane,
// window depth stays affine in light uv on it); metres per uv grow with w; window depth per
// metre falls with w^2 (glm's perspective depth; other powers for a light-space warp:
// u_map*WPower), so both terms convert per pixel. The
// w-divide is in mapUvzw, the one place a world point enters a map.
// Needs common/light.glsl (towardsLight) included before.
// CPU mirror: sl::receiverInMap and its parts (algo/ShadowBias.h); C++ binding:
// bindDepthLookup (core/ShadowPass.cpp) for the per-map uniforms, bindParams for the
// bias.* / pcf parameters (their ParamDecl names the uniform).
//
// The technique's lookup file defines, BEFORE including this file:
//   int   selectShadowMap(vec3 P)             the map serving world point P (its selection
//                                             function: by light uv, depth, direction...)
//   ivec2 shadowMapTexels(int map)            the map's size in texels
//   float shadowMapDepth(int map, ivec2 t)    the depth the map stores at texel t
//   vec2  lightToMapUv(int map, vec2 uv)      the map's unwarped light uv -> its texture uv
//                                             (identity when unwarped; a warp, a page table)
//   vec2  texelCentreLightUv(int map, ivec2 t)  centre of texel t, in the map's light uv
//   vec2  localTexelLightUv(int map, vec2 uv) extent of the map's texel at light uv, in uv
// (common/single_depth_map.glsl has the first three for one sampler2D), and gets the
// contract of shaders/common/resolve.frag: shadowLookupCoord / shadowMapSize /
// shadowHardAt / shadowFilteredAt. Nearest texels via the technique's fetch: metrics see
// the map's true resolution; PCF averages the hard tests of a (2r+1)^2 neighbourhood
// inside the selected map.
//
// DISTANCE MAPS (the cube): a perspective map whose texels store the distance from a point
// light along the texel centre's own ray (normalised: shadowMapDepth returns the stored
// value) instead of window depth. The lookup then also defines SL_DEPTH_MAP_STORES_DISTANCE
// and, before including this file,
//   vec3  shadowMapLight(int map)             the point distances are measured from (world)
//   vec3  shadowMapTexelRay(int map, ivec2 t) unit world direction through texel t's centre
//   float shadowMapStoredDistance(int map, float m)  metres -> the stored value (affine)
// and the receiver's plane is met by the SAMPLED TEXEL'S RAY (planeDistanceAlongRay): the
// same exact-at-the-centre comparison, in distances. Selection, normal offset and the slope
// and constant terms are the window-depth model's, the terms turned into metres along the
// receiver's ray (sl::distanceBiasM). CPU mirror: sl::planeDistanceAlongRay,
// sl::receiverDistanceAt, sl::distanceBiasM.
#include "common/shared_constants.h"
#include "common/shadow_coord.glsl"
#ifdef SL_DEPTH_MAP_STORES_DISTANCE
#include "common/light_distance.glsl"
#endif

// Per map (bindDepthLookup, one DepthMapView each): its own orthographic or perspective
// matrix (sl::lightPlaneMatrix splits its plane transform into the two next arrays).
uniform mat4 u_mapViewProj[SL_MAX_DEPTH_MAPS];
uniform mat3 u_mapNormalMatrix[SL_MAX_DEPTH_MAPS];  // LightPlaneMatrix::normal
uniform vec3 u_mapPlaneOffset[SL_MAX_DEPTH_MAPS];   // LightPlaneMatrix::offset (0 ortho)
uniform vec2 u_mapExtentM[SL_MAX_DEPTH_MAPS];  // metres per unit of light u, v at clip w = 1
uniform float u_mapDepthPerM[SL_MAX_DEPTH_MAPS];  // window depth per metre at clip w = 1
// How they scale with clip w (DepthMapFrame::extentWPower, depthWPower): metres per uv =
// extent * w^p, depth per metre = depthPerM / w^q; spot (1, 1; 2), light-space warp (1, 2; 1).
uniform vec2 u_mapExtentWPower[SL_MAX_DEPTH_MAPS];
uniform float u_mapDepthWPower[SL_MAX_DEPTH_MAPS];
// 1: a general projective map (the post-perspective PSM): metres per uv and depth per metre
// from the matrix's derivatives at the point, across and along the light (the four arrays
// above are ignored). CPU: sl::projectiveMetresPerUv, sl::projectiveDepthPerM.
uniform int u_mapProjective[SL_MAX_DEPTH_MAPS];
// The shared parameters (shadowMapParamDecls).
uniform int u_pcfRadius;        // pcf
uniform float u_biasNormal;     // bias.normal, local texels
uniform float u_biasSlope;      // bias.slope, local texels
uniform float u_biasConstantM;  // bias.constant, metres along the light

// The receiver of this pixel in the selected map, set by shadowLookupCoord.
vec2 g_receiverUv;   // unwarped light uv of the map (after the normal offset)
float g_receiverZ;   // window depth
vec2 g_receiverDz;   // d(window depth) / d(light uv) on the receiver's plane
float g_receiverBias;
#ifdef SL_DEPTH_MAP_STORES_DISTANCE
vec3 g_receiverP;        // the offset receiver (world): its plane is met by each tap's ray
vec3 g_receiverN;        // its world normal
float g_receiverBiasM;   // g_receiverBias in metres along the receiver's ray
#endif

vec2 shadowMapSize(int map) { return vec2(shadowMapTexels(map)); }

// Depth gradient of the plane through P with world normal N, per unit of the map's light
// uv: the plane in clip space m = u_mapNormalMatrix * N - u_mapPlaneOffset * dot(N, P);
// dz/du = -m.x / m.z (the 0.5 factors of uv and window depth cancel). A plane seen edge-on
// by the light (|m.z| tiny) gets 0: it is shadowed by the N.L test of the resolve pass, or
// covered by the slope term's clamp. CPU: sl::receiverDepthGradient.
vec2 receiverDepthGradient(int map, vec3 N, vec3 P) {
  vec3 m = u_mapNormalMatrix[map] * N - u_mapPlaneOffset[map] * dot(N, P);
  if (!(abs(m.z) > 1e-4 * length(m))) return vec2(0.0);
  return -m.xy / m.z;
}

// World point P in the map: xyz = its light uv and window depth, w = its clip w (1 for an
// orthographic map). Behind a perspective light (w <= 0) nothing is lit anyway
// (lightIlluminates): w is kept positive so the arithmetic stays finite.
vec4 mapUvzw(int map, vec3 P) {
  vec4 c = u_mapViewProj[map] * vec4(P, 1.0);
  float w = c.w > 1e-6 ? c.w : 1e-6;
  return vec4(c.xyz / w * 0.5 + 0.5, w);
}

// World point P's texture uv in `map` (resolve.frag's derivatives across seams): no
// selection, no normal offset; outside [0, 1] beyond the map's edge.
vec2 shadowMapUvOf(int map, vec3 P) { return lightToMapUv(map, mapUvzw(map, P).xy); }

// Largest local texel of the map at P's light uv, in metres at P (extent x clip w^p).
float localTexelM(int map, vec2 t, float w) {
  vec2 scale = u_mapExtentM[map] * pow(vec2(w), u_mapExtentWPower[map]);
  return max(t.x * scale.x, t.y * scale.y);
}

// d(ndc) / dP along world direction d at clip position h of a projective map.
vec3 mapNdcDerivative(int map, vec4 h, vec3 d) {
  vec4 dh = u_mapViewProj[map] * vec4(d, 0.0);
  return (dh.xyz * h.w - h.xyz * dh.w) / (h.w * h.w);
}

// Metres per unit light u, v at P of a projective map: d(uv) across the light (two unit
// directions perpendicular to it), inverted. CPU: sl::projectiveMetresPerUv.
vec2 projectiveMetresPerUv(int map, vec3 P) {
  vec3 l = normalize(towardsLight(P));
  vec3 a0 = abs(l.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 0.0, 1.0);
  vec3 e1 = normalize(a0 - dot(a0, l) * l);
  vec3 e2 = cross(l, e1);
  vec4 h = u_mapViewProj[map] * vec4(P, 1.0);
  vec2 a = 0.5 * mapNdcDerivative(map, h, e1).xy;
  vec2 b = 0.5 * mapNdcDerivative(map, h, e2).xy;
  float det = a.x * b.y - b.x * a.y;
  if (!(abs(det) > 0.0)) return vec2(0.0);
  return vec2(length(vec2(b.y, -a.y)), length(vec2(-b.x, a.x))) / abs(det);
}

// Largest local texel of the map at P (light uv c.xy, clip w c.w), in metres.
float localTexelMAt(int map, vec2 t, vec4 c, vec3 P) {
  if (u_mapProjective[map] != 0) {
    vec2 perUv = projectiveMetresPerUv(map, P);
    return max(t.x * perUv.x, t.y * perUv.y);
  }
  return localTexelM(map, t, c.w);
}

// Window depth per metre along the light at P (sl::windowDepthPerM; projective:
// sl::projectiveDepthPerM).
float depthPerMAt(int map, float w, vec3 P) {
  if (u_mapProjective[map] != 0) {
    vec4 h = u_mapViewProj[map] * vec4(P, 1.0);
    return abs(0.5 * mapNdcDerivative(map, h, normalize(towardsLight(P))).z);
  }
  return u_mapDepthPerM[map] / pow(w, u_mapDepthWPower[map]);
}

// CPU: sl::receiverInMap. The map is selected for P; the normal offset is that map's local
// texel; the offset receiver is selected again (it may cross into a neighbouring map, whose
// local texel then sets the slope term).
ShadowCoord shadowLookupCoord(vec3 P, vec3 N) {
  int map = selectShadowMap(P);
  vec4 c = mapUvzw(map, P);
  vec2 t = localTexelLightUv(map, c.xy);
  float texelM = localTexelMAt(map, t, c, P);
  float cosL = clamp(dot(N, towardsLight(P)), -1.0, 1.0);
  float sinL = sqrt(max(1.0 - cosL * cosL, 0.0));
  vec3 Po = P + N * (u_biasNormal * texelM * sinL);
  int offsetMap = selectShadowMap(Po);
  if (offsetMap != map) {
    map = offsetMap;
    c = mapUvzw(map, Po);
    t = localTexelLightUv(map, c.xy);
    texelM = localTexelMAt(map, t, c, Po);
  }  // else the offset moved the point by under a texel: same local texel size and w
  vec3 uvz = mapUvzw(map, Po).xyz;
  g_receiverUv = uvz.xy;
  g_receiverZ = uvz.z;
  g_receiverDz = receiverDepthGradient(map, N, P);
  // Window depth per metre at the receiver (sl::windowDepthPerM): falls with w^q.
  float depthPerM = depthPerMAt(map, c.w, P);
  // Capped at a slope of 10 (84 degrees from the light) so grazing receivers do not leak.
  float slope = min(abs(g_receiverDz.x) * t.x + abs(g_receiverDz.y) * t.y,
                    10.0 * texelM * depthPerM);
  g_receiverBias = u_biasSlope * slope + u_biasConstantM * depthPerM;
#ifdef SL_DEPTH_MAP_STORES_DISTANCE
  // Window depth -> metres of the face's axial depth (/ depthPerM) -> metres along the
  // receiver's ray (x distance / w: the ray's secant to the face axis). sl::distanceBiasM.
  float distanceM = length(Po - shadowMapLight(map));
  g_receiverP = Po;
  g_receiverN = N;
  g_receiverBiasM = g_receiverBias / depthPerM * distanceM / c.w;
  return ShadowCoord(map, vec3(lightToMapUv(map, uvz.xy), shadowMapStoredDistance(map, distanceM)));
#else
  return ShadowCoord(map, vec3(lightToMapUv(map, uvz.xy), uvz.z));
#endif
}

#ifdef SL_DEPTH_MAP_STORES_DISTANCE
// The receiver's distance along unit `ray` from the map's light: its plane met by the ray,
// or (the ray runs inside the plane or away from it: a plane edge-on to the light, which
// the resolve's N.L test shadows) the offset receiver's own distance. CPU:
// sl::receiverDistanceAt.
float receiverDistanceAt(int map, vec3 ray) {
  vec3 light = shadowMapLight(map);
  float t = planeDistanceAlongRay(light, ray, g_receiverP, g_receiverN);
  return t > 0.0 ? t : length(g_receiverP - light);
}
#endif

// A PCF tap beyond the selected map's edge is clamped to the edge texel, unless the lookup
// stores distances and defines SL_DEPTH_MAP_ACROSS_EDGES and (declared before, defined after
// including this file)
//   float shadowMapDistanceAcross(int map, ivec2 t, out vec3 ray)
// which reads the neighbouring map's texel in the direction of t and returns the value it
// stores and its centre's ray (the cube's faces: PCF continues across face edges, and the
// receiver's plane is met by that texel's own ray, exactly as inside the face).
float depthMapTexelTest(ShadowCoord c, ivec2 offset) {
  ivec2 size = shadowMapTexels(c.map);
  ivec2 t = clamp(ivec2(floor(c.uvz.xy * vec2(size))), ivec2(0), size - 1) + offset;
  float stored;
#ifdef SL_DEPTH_MAP_STORES_DISTANCE
  vec3 ray;
#ifdef SL_DEPTH_MAP_ACROSS_EDGES
  if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, size))) {
    stored = shadowMapDistanceAcross(c.map, t, ray);
  } else
#endif
  {
    t = clamp(t, ivec2(0), size - 1);
    ray = shadowMapTexelRay(c.map, t);
    stored = shadowMapDepth(c.map, t);
  }
  float z = shadowMapStoredDistance(c.map, receiverDistanceAt(c.map, ray) - g_receiverBiasM);
#else
  t = clamp(t, ivec2(0), size - 1);
  vec2 centre = texelCentreLightUv(c.map, t);
  stored = shadowMapDepth(c.map, t);
  float z = g_receiverZ + dot(g_receiverDz, centre - g_receiverUv) - g_receiverBias;
#endif
  return z <= stored ? 1.0 : 0.0;
}

float shadowHardAt(ShadowCoord c) {
  if (any(lessThan(c.uvz.xy, vec2(0.0))) || any(greaterThan(c.uvz.xy, vec2(1.0)))) return 1.0;
  return depthMapTexelTest(c, ivec2(0));
}

float shadowFilteredAt(ShadowCoord c) {
  if (u_pcfRadius == 0) return shadowHardAt(c);
  float sum = 0.0;
  for (int y = -u_pcfRadius; y <= u_pcfRadius; ++y)
    for (int x = -u_pcfRadius; x <= u_pcfRadius; ++x) sum += depthMapTexelTest(c, ivec2(x, y));
  return sum / float((2 * u_pcfRadius + 1) * (2 * u_pcfRadius + 1));
}
