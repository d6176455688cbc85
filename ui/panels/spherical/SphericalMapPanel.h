// The Spherical map panel: the `spherical` technique's latitude-longitude map drawn whole
// (longitude -180°..180° left to right, the south pole at the bottom), the seam (its left and
// right edges, one meridian), the poles (its top and bottom edges, each one point) and the
// halves' border marked; the value under the cursor (distance from the light in metres); a
// texel-density view (log2 texels per steradian from algo/omni/LatLongMapping, on the Omni
// map panel's scale, so the three parameterisations compare); and a marker where the view's
// pixel under the mouse looks up (ViewportWidget::pixelProbed).
#pragma once

#include <memory>
#include <optional>

#include "panels/common/PanelKit.h"

class QCheckBox;
class QLabel;
class QPainter;

namespace sl::ui {

class SphericalMapPanel : public PublicationPanel {
  Q_OBJECT

 public:
  explicit SphericalMapPanel(QWidget* parent = nullptr);

  std::set<std::string> observedKeys() const override;
  void showPublication(const sl::Publication& publication) override;
  void highlightPass(const QString& passId) override;
  QJsonObject drawnValues() const override;
  void showProbe(const std::optional<sl::PixelProbe>& probe) override;
  bool wantsProbe() const override { return true; }

 private:
  void redraw();
  /// The probe's place in the drawn map (texels, v up), or nothing.
  std::optional<QPointF> probeInLayout() const;
  /// Seam, poles, the halves' border, and the probe's marker.
  void drawOverlay(QPainter& painter, const QRectF& imageRect) const;

  ImageView* view_ = nullptr;
  QCheckBox* density_ = nullptr;
  QLabel* info_ = nullptr;
  QLabel* probeInfo_ = nullptr;
  std::optional<sl::PixelProbe> probe_;
  /// The map as drawn: depth (1 = empty) and density (log2 texels/sr).
  std::shared_ptr<sl::FloatImage> depth_, density_log2_;
  int resolution_ = 0;  ///< the map's height H (each half H x H)
  double farM_ = 0.0;   ///< sph.far_m: stored = distance / far
  QJsonObject drawn_;
};

}  // namespace sl::ui
