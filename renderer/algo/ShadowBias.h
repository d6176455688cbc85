// The one bias model of every depth-map lookup, as plain math (the CPU mirror of
// shaders/common/depth_map_test.glsl). Maps store exact depth at their texel centres; the
// receiver's plane is evaluated at the centre of the texel it samples (receiver-plane
// depth, in UNWARPED light space), so a planar receiver compares against itself exactly.
// Normal offset, slope term and constant are scaled by the LOCAL texel size, so warped,
// partitioned or paged maps reuse the model by saying where their texel centres are and
// how large their texels are locally.
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

/// transpose(inverse(mat3(lightViewProj))): maps a world normal to the clip-space plane
/// normal. The GLSL uniform u_lightNormalMatrix.
glm::mat3 lightNormalMatrix(const glm::mat4& lightViewProj);

/// d(window depth) / d(light uv) on the plane with world normal N, for an orthographic
/// light: m = normalMatrix * N, gradient = -m.xy / m.z; (0, 0) when the light sees the
/// plane edge-on (|m.z| <= 1e-4 |m|).
glm::vec2 receiverDepthGradient(const glm::mat3& normalMatrix, const glm::vec3& N);

/// The receiver's window depth carried along its plane to the light uv `centre`:
/// z + gradient . (centre - uv).
float receiverDepthAt(glm::vec2 uv, float z, glm::vec2 gradient, glm::vec2 centre);

/// The slope and constant terms, in window depth: slopeTexels * min(|g.x| t.x + |g.y| t.y,
/// 10 * texelM * depthPerM) + constantM * depthPerM, with t the local texel size in light uv,
/// texelM the largest local texel in metres, depthPerM = 1 / light depth range (m).
float shadowDepthBias(const ShadowBiasSettings& s, glm::vec2 gradient, glm::vec2 localTexelUv,
                      float texelM, float depthPerM);

}  // namespace sl
