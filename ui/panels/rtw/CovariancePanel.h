// The Covariance panel (DA-RTW, seed 000): the 1σ and 2σ ellipses of the importance
// distribution over the IM with its principal axis, the eigenvalues, e_x against the
// vibration threshold on a gauge, whether the rotation was held this frame, and a history
// of the rotation angle and e_x: the view for exploring the PCA vibration threshold.
#pragma once

#include <deque>
#include <map>

#include <QString>
#include <QStringList>

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
  /// What in `drawn` (drawnValues() of a frame) disagrees with the renderer's publication of
  /// that frame: the frame, R turned, the turn, e_x as shown, the axis drawn, λ1, and the state
  /// against the renderer's flags. Empty: every readout agrees.
  static QStringList readoutProblems(const QJsonObject& drawn, const sl::Publication& pub);

  static constexpr std::size_t kHistoryFrames = 240;

 private:
  void updateHistoryPlots();

  /// One row of the numbers beside the image: its name and value labels (the tooltip of
  /// both defines the number), hidden while the frame does not publish it.
  struct Row {
    QLabel* name = nullptr;
    QLabel* value = nullptr;
  };
  void setRow(const QString& key, const QString& value);

  ImageView* view_ = nullptr;
  QWidget* numbers_ = nullptr;
  std::map<QString, Row> rows_;
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
