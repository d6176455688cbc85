// The Warp functions panel (RTW, seed 002 / Rosen 2012): for the x and y axes, the 1D
// importance before and after the blur (and floor), and the warp curve — warped against
// unwarped shadow-map coordinate, u' = u + warp(u), the normalised CDF of importance —
// with the identity line (no warp). Hovering reads every curve at the cursor.
#pragma once

#include <array>

#include "panels/common/PanelKit.h"
#include "panels/rtw/RtwPanelKeys.h"

class QLabel;

namespace sl::ui {

class WarpPanel : public PublicationPanel {
  Q_OBJECT

 public:
  explicit WarpPanel(QWidget* parent = nullptr);

  std::set<std::string> observedKeys() const override { return rtw::warpPanelKeys(); }
  void showPublication(const sl::Publication& publication) override;
  void highlightPass(const QString& passId) override;
  QJsonObject drawnValues() const override;

 private:
  void applyHighlight();

  std::array<PlotWidget*, 2> importance_{};  ///< x, y
  std::array<PlotWidget*, 2> warp_{};
  QLabel* info_ = nullptr;
  QString pass_;
  QJsonObject drawn_;
};

}  // namespace sl::ui
