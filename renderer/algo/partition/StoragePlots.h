// The data of the storage-factor plots (Lloyd et al. 2006, Fig. 6: M_x, M_z, S over eta;
// Fig. 7: S over the hemisphere of light directions), shared by `shadowlab-cli storage` and
// the GUI's Storage factor panel; renderer/figures/StorageChartKit.h draws them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "StorageFactor.h"

namespace sl::partition {

/// Fig. 6: one warp's maxima over eta (ascending), for one light.
struct EtaCurve {
  std::vector<double> eta, mx, mz, s;
  std::string title, subtitle;
};
/// `points` >= 2 samples of eta over [-1, 1]. Errors name the input (evaluateScheme's).
std::optional<std::string> etaCurve(const warp::ViewFrustum& view, const glm::dvec3& towardsLight,
                                    int points, EtaCurve& out);

/// The disk of light directions (equal-angle: the centre is `up`, overhead; the rim the
/// horizon, radius = zenith angle / 90 degrees). Disk coordinates (u, v) in [-1, 1]: u to
/// the right of the picture along `front`, v to its top along `right`.
struct HemisphereFrame {
  glm::dvec3 up{0.0, 1.0, 0.0};
  glm::dvec3 front{0.0, 0.0, -1.0};  ///< "in front of the viewer" (right of the disk)
  glm::dvec3 right{1.0, 0.0, 0.0};   ///< the viewer's right (top of the disk)

  /// World up `worldUp`, with "in front" the view's forward made horizontal (its up vector
  /// when it looks straight up or down), as the paper's Fig. 7 for a horizontal viewer.
  static HemisphereFrame forView(const warp::ViewFrustum& view, const glm::dvec3& worldUp);
  /// The unit direction at (u, v); nothing outside the disk (u^2 + v^2 > 1).
  std::optional<glm::dvec3> direction(double u, double v) const;
  /// (u, v) of a direction (below the horizon: mirrored onto the rim's outside, radius > 1).
  glm::dvec2 disk(const glm::dvec3& towardsLight) const;
};

/// Fig. 7 for one scheme: S (and M_x, M_z) at the centres of a grid x grid raster over the
/// disk, row-major, row 0 at the top (v = +1); NaN outside the disk.
struct HemispherePanel {
  std::string title;
  int grid = 0;
  std::vector<double> s, mx, mz;
  /// Cell (row, col)'s disk coordinates.
  glm::dvec2 cellCentre(int row, int col) const;
};
std::optional<std::string> hemispherePanel(const warp::ViewFrustum& view,
                                           const HemisphereFrame& frame,
                                           const SchemeSettings& settings, int grid,
                                           HemispherePanel& out);

/// Fig. 7: several schemes on one colour scale, the chosen light marked.
struct HemisphereFigure {
  std::string title, subtitle;
  std::vector<HemispherePanel> panels;
  double markU = 0.0, markV = 0.0;  ///< the light, in disk coordinates
};

}  // namespace sl::partition
