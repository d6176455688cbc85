// OmniRayMap, the omni family's base of the two techniques whose map is two halves of one
// depth texture array storing per texel the exact distance from the light along the texel's
// own ray (`dual-paraboloid`: two hemispheres, `spherical`: two halves of the
// latitude-longitude map). Their shaders share common/omni/.
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "core/ShadowPass.h"
#include "core/Technique.h"
#include "core/omni/OmniDeclarations.h"

namespace sl {

/// Base of `dual-paraboloid` and `spherical`: one depth program, the halves' array, the light's
/// frame and the depth range (near 0, far just past the scene), bound as
/// common/omni/frame.glsl's uniforms on the depth program and the lookup.
class OmniRayMap : public Technique {
 public:
  std::vector<const gl::Program*> programs() const override { return {&depthProgram_}; }
  MemoryStats memory() const override;
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) override;

 protected:
  /// `mapsLabel` names the array in memory().
  OmniRayMap(const gl::ShaderLibrary& lib, const gl::ProgramDesc& depth, std::string mapsLabel);

  /// Refuses an invalid light or an empty scene; then this frame's light position, `frame`
  /// (unit x, y and axis, x × y = axis) and depth range: from 0 to 1.01 times the distance to
  /// the scene bounds' farthest corner (at most the light's range).
  void fitFrame(const FrameContext& ctx, const glm::dvec3& x, const glm::dvec3& y,
                const glm::dvec3& axis);
  /// `halves` maps of `resolution`^2 (`what` names them in messages).
  void ensureHalves(int resolution, int halves, const std::string& what);
  /// Starts half `half`'s depth pass: its layer cleared as the target, the depth program in
  /// use with the frame's mapping set.
  void beginHalf(int half, int resolution) const;
  /// Publishes the depth range's far end as `farKey` and half i as "<mapPrefix>i.map".
  void publishHalves(FrameContext& ctx, const std::string& farKey, const std::string& mapPrefix,
                     int halves) const;
  /// The lookup's bindings: the array on `firstUnit` as `sampler`, the frame's mapping.
  void bindHalves(const gl::Program& resolve, int firstUnit, const char* sampler) const;

  gl::Program depthProgram_;

 private:
  /// The light, frame and depth range, set on `program` (common/omni/frame.glsl).
  void setMapping(const gl::Program& program) const;

  DepthMapArray maps_;  ///< layer i = half i
  std::string mapsLabel_;
  glm::vec3 lightPosM_{0.0f};
  glm::vec3 x_{1.0f, 0.0f, 0.0f}, y_{0.0f, 0.0f, -1.0f}, axis_{0.0f, 1.0f, 0.0f};
  float nearM_ = 0.0f, farM_ = 1.0f;
};

}  // namespace sl
