// The Spherical map panel: the `spherical` technique's latitude-longitude map drawn whole
// (longitude -180°..180° left to right, the south pole at the bottom), the seam (its left and
// right edges, one meridian), the poles (its top and bottom edges, each one point) and the
// halves' border marked; the value under the cursor (distance from the light in metres); a
// texel-density view (log2 texels per steradian from algo/omni/LatLongMapping, on the omni
// family's one scale, so the three parameterisations compare); and a marker where the view's
// pixel under the mouse looks up. The frame around the map: OmniPanelBase.
#pragma once

#include "panels/omni/OmniPanelBase.h"

namespace sl::ui {

class SphericalMapPanel : public OmniPanelBase {
  Q_OBJECT

 public:
  explicit SphericalMapPanel(QWidget* parent = nullptr);

  void showPublication(const sl::Publication& publication) override;

 private:
  void redraw() override;
  std::optional<QPointF> probeInLayout() const override;
  QString probeText(const sl::PixelProbe& probe) const override;
  /// Seam, poles, the halves' border, and the probe's marker.
  void drawOverlay(QPainter& painter, const QRectF& imageRect) const;

  double farM_ = 0.0;  ///< sph.far_m: stored = distance / far
};

}  // namespace sl::ui
