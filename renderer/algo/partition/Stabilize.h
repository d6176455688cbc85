// Stabilised cascades: an orthographic light frustum per z-partition whose size does not
// change as the camera turns (the slice's bounding sphere, quantised) and whose position
// moves by whole texels as the camera moves (texel snapping), so shadow edges do not shimmer.
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "algo/warp/PerspectiveWarp.h"

namespace sl::partition {

struct StableOrtho {
  glm::dvec3 right{1, 0, 0}, up{0, 1, 0}, towardsLight{0, 0, 1};  ///< light basis (camera-free)
  glm::dvec2 minXY{0.0}, maxXY{0.0};  ///< ortho bounds in the light basis, metres
  double zMin = 0.0, zMax = 0.0;      ///< along towardsLight, metres
  double extentM = 0.0;               ///< maxXY - minXY (both axes), quantised
  double texelM = 0.0;                ///< extentM / resolution
  double sphereRadiusM = 0.0;         ///< the slice's bounding sphere
  glm::mat4 view{1.0f}, proj{1.0f};   ///< world -> light view, light view -> clip
};

/// The stabilised frustum of the slice [sliceNear, sliceFar] of `view`. The extent is the
/// bounding sphere's diameter rounded up to a multiple of `extentQuantumM` (<= 0: not
/// rounded); the centre is snapped to whole texels of a `resolution`-texel map; depth covers
/// the sphere plus `casterExtraM` towards the light. Errors name the bad input.
std::optional<std::string> stabilizeCascade(const warp::ViewFrustum& view, double sliceNear,
                                            double sliceFar, const glm::dvec3& towardsLight,
                                            int resolution, double extentQuantumM,
                                            double casterExtraM, StableOrtho& out);

}  // namespace sl::partition
