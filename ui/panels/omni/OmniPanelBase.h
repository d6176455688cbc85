// The omni family's map panels' shared frame (the Omni map panel: cube faces and paraboloid
// discs; the Spherical map panel: the latitude-longitude map): a texel-density check box over
// the map view (depth, or log2 texels per steradian on ONE fixed scale for every omni
// mapping, so a class can compare them), a line about the map, a line about the view's pixel
// under the mouse and its marker where that pixel looks up (ViewportWidget::pixelProbed), and
// the drawn values for --grab.
#pragma once

#include <memory>
#include <optional>
#include <set>
#include <string>

#include <QStringList>

#include "panels/common/PanelKit.h"

class QCheckBox;
class QLabel;
class QPainter;

namespace sl::ui {

class OmniPanelBase : public PublicationPanel {
  Q_OBJECT

 public:
  std::set<std::string> observedKeys() const override { return keys_; }
  void highlightPass(const QString& passId) override;
  QJsonObject drawnValues() const override;
  void showProbe(const std::optional<sl::PixelProbe>& probe) override;
  bool wantsProbe() const override { return true; }

 protected:
  /// What a panel of the family is made of.
  struct Setup {
    QString name;                ///< prefixes the widgets' object names (+ "Density", "Map", ...)
    QString densityText;         ///< labels the density check box
    QString mapNoun;             ///< ends "not looked up in ..." ("an omni map")
    std::set<std::string> keys;  ///< observedKeys()
    QStringList passes;          ///< the passes whose maps it draws (highlightPass)
  };
  OmniPanelBase(Setup setup, QWidget* parent);

  /// Draws the layout again (the density box toggled): showLayout, then the panel's value
  /// reader, caption and overlay.
  virtual void redraw() = 0;
  /// The probe's place in the drawn layout (texels, v up), or nothing.
  virtual std::optional<QPointF> probeInLayout() const = 0;
  /// The probe line for a covered pixel the layout shows.
  virtual QString probeText(const sl::PixelProbe& probe) const = 0;

  /// depth_ and density_log2_ of width x height texels, every one NaN (no texel).
  void allocateLayout(int width, int height);
  /// The layout into the view: depth (grey over its finite range) or, with the box checked,
  /// density (on the family's scale), with its legend; the scale into the drawn values.
  void showLayout();
  /// The probe's marker over the drawn image in `imageRect` (nothing without a probe).
  void drawProbeMarker(QPainter& painter, const QRectF& imageRect) const;
  /// "d m (stored s)" for a stored value s = (d - near) / (far - near) (1: empty).
  static QString storedDistanceText(float stored, double nearM, double farM);

  ImageView* view_ = nullptr;
  QLabel* info_ = nullptr;
  std::optional<sl::PixelProbe> probe_;
  /// The layout as drawn: depth (1 = empty) and density (log2 texels/sr, NaN = no texel).
  std::shared_ptr<sl::FloatImage> depth_, density_log2_;
  int resolution_ = 0;
  QJsonObject drawn_;

 private:
  QString hoverText() const;

  QCheckBox* density_ = nullptr;
  QLabel* probeInfo_ = nullptr;
  QString mapNoun_;
  std::set<std::string> keys_;
  QStringList passes_;
};

}  // namespace sl::ui
