// The one bias model of every depth-map lookup, as plain math (the CPU mirror of
// shaders/common/depth_map_test.glsl). Maps store exact depth at their texel centres; the
// receiver's plane is evaluated at the centre of the texel it samples (receiver-plane
// depth, in UNWARPED light space), so a planar receiver compares against itself exactly.
// Normal offset, slope term and constant are scaled by the LOCAL texel size, so warped,
// partitioned or paged maps reuse the model by saying where their texel centres are and
// how large their texels are locally. Orthographic (directional) and perspective (spot)
// light matrices alike: a plane stays a plane under the projective map, so window depth is
// affine in light uv on it; metres per uv and window depth per metre vary with clip w.
#pragma once

#include <glm/glm.hpp>

namespace sl {

/// Bias parameters (the shared declarations bias.normal, bias.slope, bias.constant).
struct ShadowBiasSettings {
  float normalTexels = 0.0f;  ///< normal offset, in local texels (x sin of the light angle)
  float slopeTexels = 0.0f;   ///< extra depth, in local texels of the receiver plane's rise
  float constantM = 0.0f;     ///< extra depth, metres along the light
  bool operator==(const ShadowBiasSettings&) const = default;
};

/// How a world plane (N, -N.P) maps to a clip-space plane: the first three rows of
/// transpose(inverse(lightViewProj)) split into the part that multiplies N (`normal`, the
/// GLSL u_lightNormalMatrix) and the one that multiplies the plane's offset -N.P
/// (`offset`, u_lightPlaneOffset). For an affine (orthographic) matrix `normal` is
/// transpose(inverse(mat3(lightViewProj))) and `offset` is exactly zero.
struct LightPlaneMatrix {
  glm::mat3 normal{1.0f};
  glm::vec3 offset{0.0f};
};
LightPlaneMatrix lightPlaneMatrix(const glm::mat4& lightViewProj);
/// transpose(inverse(mat3(lightViewProj))) (the orthographic case of lightPlaneMatrix).
glm::mat3 lightNormalMatrix(const glm::mat4& lightViewProj);

/// d(window depth) / d(light uv) on the plane through P with world normal N: the clip
/// plane m = normal * N - offset * dot(N, P), gradient = -m.xy / m.z (the 0.5 factors of uv
/// and window depth cancel); (0, 0) when the light sees the plane edge-on
/// (|m.z| <= 1e-4 |m|).
glm::vec2 receiverDepthGradient(const LightPlaneMatrix& plane, const glm::vec3& N,
                                const glm::vec3& P);
/// The orthographic case (no dependence on P).
glm::vec2 receiverDepthGradient(const glm::mat3& normalMatrix, const glm::vec3& N);

/// Window depth per metre along the light at a point of clip w: `depthPerMAtUnitW` / w^power
/// (power 2 for a spot's frustum, 1 for a warp along light-space z; DepthMapFrame).
/// Orthographic: w = 1 and depthPerMAtUnitW = 1 / depth range; perspective (glm, depth -1..1
/// to window 0..1): depthPerMAtUnitW = far * near / (far - near), w = view depth.
float windowDepthPerM(float depthPerMAtUnitW, float clipW, float power = 2.0f);
/// The window depth per metre at w = 1 of a light fit (see windowDepthPerM).
float depthPerMAtUnitW(bool perspective, float depthRangeM, float nearM, float farM);

/// The receiver's window depth carried along its plane to the light uv `centre`:
/// z + gradient . (centre - uv).
float receiverDepthAt(glm::vec2 uv, float z, glm::vec2 gradient, glm::vec2 centre);

/// The slope and constant terms, in window depth: slopeTexels * min(|g.x| t.x + |g.y| t.y,
/// 10 * texelM * depthPerM) + constantM * depthPerM, with t the local texel size in light uv,
/// texelM the largest local texel in metres AT THE RECEIVER (extent x clip w), depthPerM the
/// window depth per metre at the receiver (windowDepthPerM).
float shadowDepthBias(const ShadowBiasSettings& s, glm::vec2 gradient, glm::vec2 localTexelUv,
                      float texelM, float depthPerM);

/// One depth map as the bias model sees it: a technique with several maps (an array, an
/// atlas, cascades, cube faces) has one per map, each with its own matrix, orthographic or
/// perspective. GLSL: u_mapViewProj / u_mapExtentM / u_mapDepthPerM[i] of
/// depth_map_test.glsl.
struct DepthMapFrame {
  glm::mat4 viewProj{1.0f};  ///< world -> the map's clip space (orthographic: w = 1)
  glm::vec2 extentM{1.0f};   ///< metres per unit of the map's light uv, at clip w = 1
  float depthPerM = 1.0f;    ///< window depth per metre along the light, at clip w = 1
  /// How extent and depth per metre scale with clip w: metres per uv = extentM * w^p.xy,
  /// depth per metre = depthPerM / w^q. A spot's frustum: p = (1, 1), q = 2 (glm's depth);
  /// a warp along light-space z (PSM, LiSPSM: w = z' does not change along a light ray):
  /// p = (1, 2), q = 1. Orthographic: w = 1, the powers do not matter.
  glm::vec2 extentWPower{1.0f};
  float depthWPower = 2.0f;
  /// A general projective map (the post-perspective PSM: the camera's projection composed
  /// with the light's): metres per uv and depth per metre are taken from the matrix's
  /// derivatives at the point (projectiveMetresPerUv, projectiveDepthPerM) instead of
  /// extentM / depthPerM and the w powers, which it ignores.
  bool projective = false;
};

/// Metres per unit of light u and v at world point P of a projective map whose light rays
/// run along `towardsLight` (uv is constant along them): the 2x2 derivative of uv across the
/// light (two unit directions perpendicular to it), inverted; the lengths of its columns.
/// For an orthographic map this is the extent of its uv, for a perspective one extent x w.
glm::vec2 projectiveMetresPerUv(const glm::mat4& viewProj, glm::vec3 P, glm::vec3 towardsLight);
/// |d(window depth) / d(metre along the light)| at P of a projective map.
float projectiveDepthPerM(const glm::mat4& viewProj, glm::vec3 P, glm::vec3 towardsLight);

/// World point P in `map`: xyz = light uv and window depth (after the divide by clip w),
/// w = clip w (1 for an orthographic map; kept >= 1e-6 behind a perspective light, where
/// nothing is lit). GLSL: mapUvzw.
glm::vec4 mapUvzw(const DepthMapFrame& map, glm::vec3 P);

/// A pixel's receiver in the SELECTED map (GLSL: the g_receiver* of shadowLookupCoord):
/// after the normal offset, in that map's light uv and window depth.
struct MapReceiver {
  glm::vec2 uv{0.0f};        ///< the map's unwarped light uv
  float z = 0.0f;            ///< window depth
  glm::vec2 gradient{0.0f};  ///< d(window depth) / d(the map's light uv) on the plane
  float bias = 0.0f;         ///< slope + constant terms, window depth
};

/// The receiver of world point P with normal N in `map`, whose texels are `localTexelUv`
/// wide (in its light uv) around P: normal offset by the largest local texel in metres at P
/// (extent x clip w) times sin(theta_L), then the plane (through the map's full matrix)
/// and the bias terms in that map, with the window depth per metre at P's clip w. Comparing
/// receiverDepthAt(r.uv, r.z, r.gradient, centre) - r.bias with the depth the map stores at
/// `centre` is the hard test.
MapReceiver receiverInMap(const DepthMapFrame& map, glm::vec3 P, glm::vec3 N,
                          glm::vec3 towardsLight, glm::vec2 localTexelUv,
                          const ShadowBiasSettings& s);

// --- Distance maps (the cube: texels store the distance from a point light along their
// centre's ray; GLSL: the SL_DEPTH_MAP_STORES_DISTANCE branch of depth_map_test.glsl).

/// Distance from `lightPosM` along unit `dir` to the plane through P with normal N; -1 when
/// the ray runs (nearly) inside the plane (|N.dir| < 1e-6 |N|) or meets it behind the
/// light. GLSL: planeDistanceAlongRay (common/light_distance.glsl).
float planeDistanceAlongRay(glm::vec3 lightPosM, glm::vec3 dir, glm::vec3 P, glm::vec3 N);
/// The receiver (offset point P, normal N) at the texel whose centre's ray is `dir`: its
/// plane met by that ray, or its own distance |P - light| when the ray does not meet it.
/// Compared, less distanceBiasM, with the distance the texel stores. GLSL:
/// receiverDistanceAt.
float receiverDistanceAt(glm::vec3 lightPosM, glm::vec3 dir, glm::vec3 P, glm::vec3 N);
/// A window-depth bias of a perspective map (shadowDepthBias, at the receiver's
/// `depthPerM` = windowDepthPerM) as metres along the receiver's ray: bias / depthPerM is
/// metres of the map's axial depth (clip w), times distance / w, the ray's secant.
float distanceBiasM(float windowBias, float depthPerM, float clipW, float distanceM);

}  // namespace sl
