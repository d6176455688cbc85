// Which storage-factor scheme (algo/partition, Lloyd et al. 2006) a technique's frame is: read
// from its declarations, its parameter values and what it published. Plain C++ (no Qt), so
// that the GL tests check exactly what the Storage factor panel analyses (part of the
// measuring library: the panel and the tests link it).
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "algo/partition/StorageFactor.h"
#include "core/Renderer.h"

namespace sl::measure {

/// What the analysis needs from a frame (the panel's inputs; equal inputs: no recompute).
struct StorageInputs {
  sl::warp::ViewFrustum view;
  glm::dvec3 towardsLight{0.0, 1.0, 0.0};
  sl::partition::SchemeSettings settings;
  std::string schemeLabel;    ///< "uniform (uniform)", "one warp, eta 0 (lispsm)", ...
  std::optional<double> eta;  ///< the scheme's eta, marked on the eta plot
  int grid = 41;              ///< hemisphere cells per side
  bool operator==(const StorageInputs& o) const;
};

/// A frame's value by key (nothing when absent or not finite).
using FrameValue = std::function<std::optional<double>(const std::string& key)>;

/// The scheme of technique `info` with parameter values `param` (by key, from the
/// declarations) and the frame's published numbers `published`: cascades' k when it
/// declares "partitions"; face partitions when it publishes "faces.front"; one warp with the
/// eta of its "warp.eta" parameter (psm, lispsm); one warp with the eta it PUBLISHED as
/// "warp.eta" when that is not a parameter (tsm: the eta its warp.focus gives at this light,
/// eq. 11 inverted; -1 = its uniform fallback); else uniform (uniform, RTW). Pure.
void schemeFromDeclarations(const sl::TechniqueInfo* info, const FrameValue& param,
                            const FrameValue& published, StorageInputs& out);

/// Whether the analysis models technique `info`'s own scheme (for a directional light):
/// `uniform`, one warp (a "warp.eta" parameter or publication), cascades (a "partitions"
/// parameter), face partitions (publishes "faces.front"). Others (RTW, paged and fitted
/// virtual maps) are analysed as if uniform, which says nothing about them. Pure.
bool analysesScheme(const sl::TechniqueInfo& info);

}  // namespace sl::measure
