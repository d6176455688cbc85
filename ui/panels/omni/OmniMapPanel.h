// The Omni map panel: a cube shadow map unfolded as a cross (+y above, -y below the row
// +x, +z, -x, -z, so neighbouring texels touch across every drawn edge) or the dual
// paraboloid's two discs; the value under the cursor (both store the distance from the
// light: shown in metres); and a texel-density view (log2 texels
// per steradian from algo/omni, ONE fixed colour scale for both, so a class can compare);
// and a marker where the view's pixel under the mouse looks up (the renderer's own face or
// hemisphere and uv for that pixel, ViewportWidget::pixelProbed).
#pragma once

#include <memory>
#include <optional>

#include "panels/common/PanelKit.h"

class QCheckBox;
class QLabel;
class QPainter;

namespace sl::ui {

class OmniMapPanel : public PublicationPanel {
  Q_OBJECT

 public:
  explicit OmniMapPanel(QWidget* parent = nullptr);

  std::set<std::string> observedKeys() const override;
  void showPublication(const sl::Publication& publication) override;
  void highlightPass(const QString& passId) override;
  QJsonObject drawnValues() const override;
  void showProbe(const std::optional<sl::PixelProbe>& probe) override;
  bool wantsProbe() const override { return true; }

 private:
  void redraw();
  /// The probe's place in the drawn layout (texels, v up), or nothing.
  std::optional<QPointF> probeInLayout() const;
  void drawProbe(QPainter& painter, const QRectF& imageRect) const;

  ImageView* view_ = nullptr;
  QCheckBox* density_ = nullptr;
  QLabel* info_ = nullptr;
  QLabel* probeInfo_ = nullptr;
  std::optional<sl::PixelProbe> probe_;
  /// The layout as drawn: depth (1 = empty) and density (log2 texels/sr, NaN = no texel).
  std::shared_ptr<sl::FloatImage> depth_, density_log2_;
  QString kind_;  ///< "cube", "paraboloid" or empty
  int resolution_ = 0;
  /// What the stored values are normalised by (cube.near_m / far_m; the paraboloid: 0 and
  /// dp.far_m): both store (distance - near) / (far - near), omni::storedDistance.
  double nearM_ = 0.0, farM_ = 0.0;
  QJsonObject drawn_;
};

}  // namespace sl::ui
