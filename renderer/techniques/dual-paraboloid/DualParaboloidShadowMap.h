// Dual-paraboloid shadow map (Brabec, Annen, Seidel 2002; seed 001, docs/techniques.md §7):
// two hemispheres around a point light (a spot: one, along its axis), each a disc through
// the non-linear paraboloid mapping, applied per TESSELLATED vertex (long triangles bend)
// with exact depth per texel; its own lookup (shaders/dual-paraboloid/lookup.glsl). The
// frame, depth range and halves' array are the omni family's (core/omni/OmniRayMap).
#pragma once

#include "core/omni/OmniRayMap.h"

namespace sl {

class DualParaboloidShadowMap : public OmniRayMap {
 public:
  static TechniqueInfo info();
  explicit DualParaboloidShadowMap(const gl::ShaderLibrary& lib);

  void renderShadows(FrameContext& ctx) override;
  std::string lookupShader() const override { return "dual-paraboloid/lookup.glsl"; }
  void bindLookup(const gl::Program& resolve, int firstUnit) const override;

 private:
  int halves_ = 2;  ///< hemispheres rendered: 2, a spot's 1
};

}  // namespace sl
