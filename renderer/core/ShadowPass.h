// Helpers shared by the shadow-map techniques: the depth-only light pass (exact depth at
// texel centres, alpha-tested casters), the binding of the one bias model of every lookup
// (shaders/common/depth_map_test.glsl). Publishing: core/Publish.h.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "algo/Focus.h"
#include "algo/ShadowBias.h"
#include "core/Technique.h"

namespace sl {

/// shaders/common/depth.vert + depth.frag: transforms by u_lightViewProj, alpha test.
gl::ProgramDesc depthProgramDesc();

/// Binds `framebuffer`, sets the viewport and the depth-only state (less, write, no
/// culling) and clears depth to 1: the start of every depth pass.
void beginDepthPass(GLuint framebuffer, int width, int height);

/// Clears and renders the scene's depth into `framebuffer` (width x height). No bias: the
/// map holds the exact depth at each texel centre; the lookup applies the bias model.
void renderDepth(const FrameContext& ctx, const gl::Program& program, GLuint framebuffer, int width,
                 int height, const glm::mat4& lightViewProj);

/// What the shared depth-map lookup needs besides the map: the light fit and the bias.
struct DepthLookupState {
  glm::mat4 lightViewProj{1.0f};
  glm::vec2 extentM{1.0f};  ///< metres per unit of light uv
  float depthRangeM = 1.0f;
  ShadowBiasSettings bias;
  int pcfRadius = 0;
};
/// From this frame's fit and the shared parameters (bias.normal, bias.slope, bias.constant,
/// pcf).
DepthLookupState depthLookupState(const LightFit& fit, const ParamSet& params);
/// Binds `map` to `unit` and sets every uniform of common/depth_map_test.glsl.
void bindDepthLookup(const gl::Program& resolve, int unit, const gl::Texture& map,
                     const DepthLookupState& state);

}  // namespace sl
