// Spherical (latitude-longitude) shadow map: the third parameterisation of a point light's
// sphere of directions in the omni-light lecture slides (Romanick, after Brabec, Annen,
// Seidel 2002), beside the cube and the dual paraboloid: longitude and latitude about a pole
// axis are the map's u and v (algo/omni/LatLongMapping.h). Not a projection: each triangle
// is drawn over its image's bounds (seam and poles handled) and kept per texel where the
// texel's own ray hits it, with exact distance; its own lookup (shaders/spherical/lookup.glsl).
#pragma once

#include "algo/omni/LatLongMapping.h"
#include "core/ShadowPass.h"
#include "core/Technique.h"

namespace sl {

class SphericalShadowMap : public Technique {
 public:
  static TechniqueInfo info();
  explicit SphericalShadowMap(const gl::ShaderLibrary& lib);

  void renderShadows(FrameContext& ctx) override;
  std::string lookupShader() const override { return "spherical/lookup.glsl"; }
  void bindLookup(const gl::Program& resolve, int firstUnit) const override;
  std::vector<const gl::Program*> programs() const override { return {&depthProgram_}; }
  MemoryStats memory() const override;
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) override;

 private:
  /// The frame and depth range of this frame, set on `program` (spherical/latlong.glsl).
  void setMapping(const gl::Program& program) const;

  gl::Program depthProgram_;
  DepthMapArray maps_;  ///< layer i = half i of the 2H x H map (H x H each)
  omni::LatLongFrame frame_;
  glm::vec3 lightPosM_{0.0f};
  float nearM_ = 0.0f, farM_ = 1.0f;
};

}  // namespace sl
