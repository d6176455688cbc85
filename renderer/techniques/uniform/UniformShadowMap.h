// Uniform (standard) shadow map, Williams 1978: one orthographic depth map from a
// directional light, focused on the part of the scene the camera sees (techniques.md §1), or
// one perspective map over a spot's cone. The baseline every other technique is compared
// against at the same texel budget.
#pragma once

#include "core/ShadowPass.h"
#include "core/Technique.h"

namespace sl {

class UniformShadowMap : public Technique {
 public:
  static TechniqueInfo info();
  explicit UniformShadowMap(const gl::ShaderLibrary& lib);

  void renderShadows(FrameContext& ctx) override;
  std::string lookupShader() const override { return "uniform/lookup.glsl"; }
  void bindLookup(const gl::Program& resolve, int firstUnit) const override {
    map_.bindLookup(resolve, firstUnit);
  }
  std::vector<const gl::Program*> programs() const override { return {&map_.program()}; }
  MemoryStats memory() const override { return map_.memory(); }
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) override {
    return map_.reloadShaders(lib);
  }

 private:
  SingleDepthMap map_;
};

}  // namespace sl
