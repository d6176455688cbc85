// Dual-paraboloid shadow map (Brabec, Annen, Seidel 2002; seed 001, docs/techniques.md §7):
// two hemispheres around a point light (a spot: one, along its axis), each a disc through
// the non-linear paraboloid mapping, applied per TESSELLATED vertex (long triangles bend)
// with exact depth per texel; its own lookup (shaders/dual-paraboloid/lookup.glsl).
#pragma once

#include "algo/omni/OmniMapping.h"
#include "core/ShadowPass.h"
#include "core/Technique.h"

namespace sl {

class DualParaboloidShadowMap : public Technique {
 public:
  static TechniqueInfo info();
  explicit DualParaboloidShadowMap(const gl::ShaderLibrary& lib);

  void renderShadows(FrameContext& ctx) override;
  std::string lookupShader() const override { return "dual-paraboloid/lookup.glsl"; }
  void bindLookup(const gl::Program& resolve, int firstUnit) const override;
  std::vector<const gl::Program*> programs() const override { return {&depthProgram_}; }
  MemoryStats memory() const override;
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) override;

 private:
  /// The frame and depth range of this frame, set on `program` (paraboloid.glsl).
  void setMapping(const gl::Program& program) const;

  gl::Program depthProgram_;
  DepthMapArray maps_;  ///< one layer per hemisphere
  omni::ParaboloidFrame frame_;
  glm::vec3 lightPosM_{0.0f};
  float nearM_ = 0.0f, farM_ = 1.0f;
  int halves_ = 2;
};

}  // namespace sl
