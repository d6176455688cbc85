// The Omni map panel: a cube shadow map unfolded as a cross (+y above, -y below the row
// +x, +z, -x, -z, so neighbouring texels touch across every drawn edge) or the dual
// paraboloid's two discs; the value under the cursor (both store the distance from the
// light: shown in metres); and a texel-density view (log2 texels per steradian from
// algo/omni, on the omni family's one scale); and a marker where the view's pixel under the
// mouse looks up (the renderer's own face or hemisphere and uv for that pixel). The frame
// around the map: OmniPanelBase.
#pragma once

#include "panels/omni/OmniPanelBase.h"

namespace sl::ui {

class OmniMapPanel : public OmniPanelBase {
  Q_OBJECT

 public:
  explicit OmniMapPanel(QWidget* parent = nullptr);

  void showPublication(const sl::Publication& publication) override;

 private:
  void redraw() override;
  std::optional<QPointF> probeInLayout() const override;
  QString probeText(const sl::PixelProbe& probe) const override;

  QString kind_;  ///< "cube", "paraboloid" or empty
  /// What the stored values are normalised by (cube.near_m / far_m; the paraboloid: 0 and
  /// dp.far_m): both store (distance - near) / (far - near), omni::storedDistance.
  double nearM_ = 0.0, farM_ = 0.0;
};

}  // namespace sl::ui
