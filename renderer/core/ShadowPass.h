// Helpers shared by the shadow-map techniques: the depth-only light pass (with
// slope-scaled bias and alpha-tested casters) and publishing a depth map to the panels.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "core/Technique.h"

namespace sl {

/// shaders/common/depth.vert + depth.frag: transforms by u_lightViewProj, alpha test.
gl::ProgramDesc depthProgramDesc();

/// Binds `framebuffer`, sets the viewport and the depth-only state (less, write, no
/// culling) and clears depth to 1: the start of every depth pass.
void beginDepthPass(GLuint framebuffer, int width, int height);

/// Clears and renders the scene's depth into `framebuffer` (width x height) with
/// glPolygonOffset(slopeBias, constantBias) — the slope-scaled depth bias.
void renderDepth(const FrameContext& ctx, const gl::Program& program, GLuint framebuffer, int width,
                 int height, const glm::mat4& lightViewProj, float slopeBias, float constantBias);

/// Reads a depth texture back into the publication as a float image.
void publishDepth(Publication& pub, const std::string& key, const gl::Texture& depth);

}  // namespace sl
