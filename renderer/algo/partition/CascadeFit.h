// The light frusta of cascaded shadow maps (z-partitioning, Lloyd et al. 2006 §5.2): the
// depth range the splits cut (view frustum ∩ scene bounds, optionally ∩ a depth range
// measured from the G-buffer), the k slices, and one orthographic frustum per slice, either
// fitted tightly to slice ∩ scene bounds or stabilised (Stabilize.h). Plain C++: the
// `cascades` technique (renderer/techniques/cascades) renders what this computes.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "Splits.h"
#include "algo/Camera.h"

namespace sl::partition {

struct CascadeSettings {
  int partitions = 4;  ///< k, 1..8
  SplitScheme split = SplitScheme::Practical;
  double lambda = 0.5;    ///< practical split blend
  int resolution = 1024;  ///< texels per side of every partition's map
  /// Stabilised: the split range quantised to 1/8 octave, each frustum the slice's bounding
  /// sphere (extent quantised, centre snapped to whole texels). Else fitted tightly.
  bool stabilize = true;
  /// View-depth range of the visible surfaces (e.g. last frame's G-buffer min/max); the
  /// split range is clipped to it. Unset: view frustum ∩ scene bounds only.
  std::optional<glm::dvec2> visibleDepthM;
};

struct CascadePart {
  double nearM = 0.0, farM = 0.0;  ///< the slice, view depth along the camera's forward axis
  glm::mat4 view{1.0f}, proj{1.0f}, viewProj{1.0f};  ///< world -> light clip (orthographic)
  glm::dvec2 extentM{0.0};                           ///< light frustum width and height, metres
  double depthRangeM = 0.0;                          ///< light frustum depth, metres
  double texelM = 0.0;                               ///< the larger texel side, metres
};

struct CascadeFit {
  double nearM = 0.0, farM = 0.0;  ///< the range the splits cut
  std::vector<double> splits;      ///< k + 1 distances, nearM .. farM
  std::vector<CascadePart> parts;
};

/// The view-depth range [min, max] of view frustum ∩ box (camera near/far when they do not
/// intersect).
glm::dvec2 visibleDepthRange(const Camera& camera, float aspect, const Aabb& box);

/// Hysteresis for a measured depth range under stabilisation: keeps `held` while it contains
/// `measured` and is at most `slack` times wider at either end (near: held.x >= measured.x /
/// slack; far: held.y <= measured.y * slack); else returns `measured` widened by sqrt(slack)
/// at both ends, so small motions leave the splits, and every map, unchanged.
glm::dvec2 holdDepthRange(const std::optional<glm::dvec2>& held, const glm::dvec2& measured,
                          double slack = 2.0);

/// The q-quantile (0 < q <= 1) of values binned in `bins` equal bins of log2 over
/// [log2Min, log2Max): the upper edge (as a value, 2^edge) of the bin where the cumulative
/// count first reaches q * total; 0 when the bins are empty. Values below or above the range
/// are in the first or last bin.
double histogramQuantileLog2(const std::vector<std::uint32_t>& bins, double q, double log2Min,
                             double log2Max);

/// Fits the k partitions. Errors name the bad input (camera, light, bounds, settings).
std::optional<std::string> fitCascades(const Camera& camera, float aspect, const Aabb& sceneBounds,
                                       const glm::vec3& towardsLight,
                                       const CascadeSettings& settings, CascadeFit& out);

}  // namespace sl::partition
