// Cube shadow map (seed 001; docs/techniques.md §7): six 90° perspective faces around a
// point light (a spot: only the faces its cone reaches, algo/omni/CubeFit), in one depth
// texture array storing the DISTANCE from the light (gl_FragDepth, omni::storedDistance),
// rendered in one layered pass (a geometry shader) or six, looked up through the shared
// per-map bias model as distance maps, the face chosen by the direction's major axis.
#pragma once

#include <vector>

#include "algo/omni/CubeFit.h"
#include "core/ShadowPass.h"
#include "core/Technique.h"

namespace sl {

class CubeShadowMap : public Technique {
 public:
  static TechniqueInfo info();
  explicit CubeShadowMap(const gl::ShaderLibrary& lib);

  void renderShadows(FrameContext& ctx) override;
  std::string lookupShader() const override { return "cube/lookup.glsl"; }
  void bindLookup(const gl::Program& resolve, int firstUnit) const override;
  std::vector<const gl::Program*> programs() const override {
    return {&depthProgram_, &layeredProgram_};
  }
  MemoryStats memory() const override;
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) override;

 private:
  /// The light and the faces' near/far: what cube/distance.glsl normalises distances by.
  void setDistance(const gl::Program& program) const;

  gl::Program depthProgram_, layeredProgram_;
  DepthMapArray faces_;  ///< one layer per rendered face (six-pass or layered mode)
  omni::CubeFit fit_;
  std::vector<DepthMapView> views_;  ///< per FACE (map index = face), all six
};

}  // namespace sl
