// The Shadow map panel: the technique's shadow map as rendered (warped for RTW) with the
// warp grid over it, beside the unwarped uniform map of the same resolution (RTW publishes
// it for contrast) with the warped map's texel grid pulled back onto it.
#pragma once

#include <memory>
#include <vector>

#include "panels/common/PanelKit.h"
#include "panels/rtw/RtwPanelKeys.h"

class QCheckBox;
class QLabel;

namespace sl::ui {

class ShadowMapPanel : public PublicationPanel {
  Q_OBJECT

 public:
  explicit ShadowMapPanel(QWidget* parent = nullptr);

  std::set<std::string> observedKeys() const override { return rtw::shadowMapPanelKeys(); }
  void showPublication(const sl::Publication& publication) override;
  void highlightPass(const QString& passId) override;
  QJsonObject drawnValues() const override;

  /// Grid lines per axis (every 1/kGridLines of the map).
  static constexpr int kGridLines = 16;

 private:
  void updateOverlays();

  ImageView* warped_ = nullptr;
  ImageView* uniform_ = nullptr;
  QCheckBox* grid_ = nullptr;
  QLabel* info_ = nullptr;
  std::vector<float> warpX_, warpY_;
  QJsonObject drawn_;
};

}  // namespace sl::ui
