// Spherical (latitude-longitude) shadow map: the third parameterisation of a point light's
// sphere of directions in the omni-light lecture slides (Romanick, after Brabec, Annen,
// Seidel 2002), beside the cube and the dual paraboloid: longitude and latitude about a pole
// axis are the map's u and v (algo/omni/LatLongMapping.h). Not a projection: each triangle
// is drawn over its image's bounds (seam and poles handled) and kept per texel where the
// texel's own ray hits it, with exact distance; its own lookup (shaders/spherical/lookup.glsl).
// The frame, depth range and halves' array are the omni family's (core/omni/OmniRayMap).
#pragma once

#include "core/omni/OmniRayMap.h"

namespace sl {

class SphericalShadowMap : public OmniRayMap {
 public:
  static TechniqueInfo info();
  explicit SphericalShadowMap(const gl::ShaderLibrary& lib);

  void renderShadows(FrameContext& ctx) override;
  std::string lookupShader() const override { return "spherical/lookup.glsl"; }
  void bindLookup(const gl::Program& resolve, int firstUnit) const override;
};

}  // namespace sl
