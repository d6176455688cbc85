// The light frusta of cascaded shadow maps (z-partitioning, Lloyd et al. 2006 §5.2): the
// depth range the splits cut (view frustum ∩ scene bounds, optionally ∩ a depth range
// measured from the G-buffer), the k slices, and one orthographic frustum per slice, either
// fitted tightly to slice ∩ scene bounds or stabilised (Stabilize.h), or warped with a
// LiSPSM perspective fitted around slice ∩ scene (Lloyd et al. §5: warping combined with
// z-partitioning; algo/warp/PerspectiveWarp). Plain C++: the
// `cascades` technique (renderer/techniques/cascades) renders what this computes.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "Splits.h"
#include "algo/Camera.h"
#include "algo/warp/PerspectiveWarp.h"

namespace sl::partition {

struct CascadeSettings {
  int partitions = 4;  ///< k, 1..8
  SplitScheme split = SplitScheme::Practical;
  double lambda = kDefaultSplitLambda;  ///< practical split blend
  int resolution = 1024;                ///< texels per side of every partition's map
  /// Stabilised: the split range quantised to 1/8 octave, each frustum the slice's bounding
  /// sphere (extent quantised, centre snapped to whole texels). Else fitted tightly.
  bool stabilize = true;
  /// Stabilised only: a slice whose bounding sphere is wider than the scene's light-space
  /// square covers that square instead (camera-free, so as stable; finer in a small scene
  /// seen whole, e.g. a room or one model). False: the sphere always.
  bool clampToScene = true;
  /// View-depth range of the visible surfaces (e.g. last frame's G-buffer min/max); the
  /// split range is clipped to it. Unset: view frustum ∩ scene bounds only.
  std::optional<glm::dvec2> visibleDepthM;
  /// Warp each partition with a perspective along light-space z (eq. 11 with `eta`: 0 =
  /// LiSPSM) fitted around slice ∩ scene bounds. A warped map is fitted tightly (not
  /// stabilised: its texels are not a translation-invariant grid); a partition whose warp
  /// falls back to uniform (the frustum looks square from the light) is stabilised as usual.
  bool warp = false;
  double eta = 0.0;  ///< in [-1, 1]
};

struct CascadePart {
  double nearM = 0.0, farM = 0.0;  ///< the slice, view depth along the camera's forward axis
  glm::mat4 view{1.0f}, proj{1.0f}, viewProj{1.0f};  ///< world -> light clip (orthographic)
  glm::dvec2 extentM{0.0};                           ///< light frustum width and height, metres
  double depthRangeM = 0.0;                          ///< light frustum depth, metres
  double texelM = 0.0;  ///< the larger texel side, metres (warped: at clip w = 1)
  /// CascadeSettings::warp: the partition's warp as fitted (its fallback and cause, n').
  std::optional<warp::WarpFit> warpFit;
  /// Stabilised and CascadeSettings::clampToScene: the map covers the scene's square, not
  /// the slice's (wider) bounding sphere.
  bool sceneClamped = false;
  bool warped() const { return warpFit && warpFit->warped(); }
  /// The 12 edges of the partition's slice of the view frustum in its map's uv (0..1 =
  /// the map), clipped to the map's w > 0 side: 4 values (u0, v0, u1, v1) per segment.
  std::vector<float> sliceUv;
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

/// The 12 edges of the view-frustum slice `corners` (ViewFrustum::corners order) in the uv
/// of the map `viewProj` (0..1 = the map; after the divide by clip w), each clipped to
/// w > 0 and to the square [-1, 2]^2 around the map: 4 values (u0, v0, u1, v1) per segment
/// that survives.
std::vector<float> sliceEdgesInMapUv(const std::array<glm::dvec3, 8>& corners,
                                     const glm::mat4& viewProj);

/// Fits the k partitions. Errors name the bad input (camera, light, bounds, settings).
std::optional<std::string> fitCascades(const Camera& camera, float aspect, const Aabb& sceneBounds,
                                       const glm::vec3& towardsLight,
                                       const CascadeSettings& settings, CascadeFit& out);

}  // namespace sl::partition
