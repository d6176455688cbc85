// The Covariance panel (DA-RTW, seed 000): the 1σ and 2σ ellipses of the importance
// distribution over the IM with its principal axis, the eigenvalues, e_x against the
// vibration threshold on a gauge, whether the rotation was held this frame, and a history
// of the rotation angle and e_x: the view for exploring the PCA vibration threshold.
#pragma once

#include <deque>

#include "panels/common/PanelKit.h"
#include "panels/rtw/RtwPanelKeys.h"

class QLabel;

namespace sl::ui {

class ThresholdGauge;

class CovariancePanel : public PublicationPanel {
  Q_OBJECT

 public:
  explicit CovariancePanel(QWidget* parent = nullptr);

  std::set<std::string> observedKeys() const override { return rtw::covariancePanelKeys(); }
  void showPublication(const sl::Publication& publication) override;
  void highlightPass(const QString& passId) override;
  /// "axis_deg": the principal axis the panel computed from the published moment sums and
  /// drew (degrees, light-frustum metres, as the rotation uses it), "axis_image_deg": the
  /// same line's angle in the IM's texel grid, eigenvalues, "source".
  QJsonObject drawnValues() const override;
  void resetHistory() override;

  static constexpr std::size_t kHistoryFrames = 240;

 private:
  void updateHistoryPlots();

  ImageView* view_ = nullptr;
  QLabel* numbers_ = nullptr;
  QLabel* state_ = nullptr;
  ThresholdGauge* gauge_ = nullptr;
  PlotWidget* anglePlot_ = nullptr;
  PlotWidget* exPlot_ = nullptr;

  struct Sample {
    std::uint64_t frame;
    double angleDeg;
    double ex;
    bool held;
  };
  std::deque<Sample> history_;
  double threshold_ = 0.9999;
  QJsonObject drawn_;
};

}  // namespace sl::ui
