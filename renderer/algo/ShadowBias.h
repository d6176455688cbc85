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

/// Window depth per metre along the light at a point of clip w: `depthPerMAtUnitW` / w^2.
/// Orthographic: w = 1 and depthPerMAtUnitW = 1 / depth range; perspective (glm, depth -1..1
/// to window 0..1): depthPerMAtUnitW = far * near / (far - near), w = view depth.
float windowDepthPerM(float depthPerMAtUnitW, float clipW);
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

}  // namespace sl
