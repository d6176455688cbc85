// Uniform (standard) shadow map, Williams 1978: one orthographic depth map from a
// directional light, focused on the part of the scene the camera sees (techniques.md §1), or
// one perspective map over a spot's cone. The baseline every other technique is compared
// against at the same texel budget.
#pragma once

#include "core/ShadowPass.h"
#include "core/Technique.h"

namespace sl {

class UniformShadowMap : public SingleDepthMapTechnique {
 public:
  static TechniqueInfo info();
  explicit UniformShadowMap(const gl::ShaderLibrary& lib);

  void renderShadows(FrameContext& ctx) override;
  std::string lookupShader() const override { return "uniform/lookup.glsl"; }
};

}  // namespace sl
