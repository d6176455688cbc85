// The six light frusta of a cube shadow map (seed 001): 90° perspective faces around a point
// or spot light (algo/omni/OmniMapping's face frames), near/far from the scene bounds within
// the light's range, and the faces a spot's cone reaches. Rendered by techniques/cube.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "algo/Camera.h"
#include "algo/Light.h"
#include "algo/omni/OmniMapping.h"

namespace sl::omni {

struct CubeFit {
  glm::vec3 lightPosM{0.0f};
  float nearM = 0.0f, farM = 0.0f;               ///< every face's perspective near and far plane
  std::uint32_t faceMask = 0;                    ///< bit f: face f is rendered (point: all six)
  std::array<glm::mat4, kCubeFaces> viewProj{};  ///< world -> face clip (90°, aspect 1)
  /// The rendered faces, in face order; layer[f] = its index among them or -1.
  std::array<int, kCubeFaces> layer{-1, -1, -1, -1, -1, -1};
  int layers = 0;
};

/// Fits the faces for a point or spot light over `sceneBounds`: far = the farthest bounds
/// corner (or the range, if nearer) + 1 %, near = far / 1000 (depth is 32-bit float), faces
/// all six for a point, cubeFacesInCone for a spot. An error for other kinds, an invalid
/// light or empty bounds.
std::optional<std::string> fitCube(const Light& light, const Aabb& sceneBounds, CubeFit& out);

}  // namespace sl::omni
