// The Covariance panel (DA-RTW, seed 000): the 1σ and 2σ ellipses of the importance
// distribution over the IM with its principal axis, the eigenvalues, e_x against the
// vibration threshold on a gauge, what the rotation did this frame and why, the predicted
// score of every turn from -90° to 90° with the current angle, PCA's axis and the chosen
// angle marked (and, on request, the error measured at fixed turns beside it), and a history
// of the rotation angle and e_x: the view for exploring when turning pays.
#pragma once

#include <deque>
#include <map>
#include <optional>
#include <vector>

#include <QString>
#include <QStringList>

#include "algo/rtw/Rotation.h"
#include "panels/common/PanelKit.h"
#include "panels/rtw/RtwPanelKeys.h"

class QLabel;
class QPushButton;
class QVBoxLayout;

namespace sl::ui {

class ReadoutGrid;
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
  void showVariantError(const QString& tag, int index, double errorPct, std::uint64_t frame,
                        const QString& problem) override;
  /// The fixed turns the measure button sweeps: every kMeasureStepDeg from -90 to 90.
  static constexpr double kMeasureStepDeg = 15.0;
  /// What in `drawn` (drawnValues() of a frame) disagrees with the renderer's publication of
  /// that frame: the frame, R turned, the turn, e_x as shown, the axis drawn, λ1, and the state
  /// against the renderer's flags. Empty: every readout agrees.
  static QStringList readoutProblems(const QJsonObject& drawn, const sl::Publication& pub);

  static constexpr std::size_t kHistoryFrames = 240;
  /// The frames whose 1 - e_x the threshold gauge shows as a band (a second at 30 fps).
  static constexpr int kGaugeBandFrames = 30;
  /// The threshold gauge (a click or drag on it sets pca.threshold through parameterChosen)
  /// and the point of it where a click sets 1 - threshold = `oneMinusThreshold`.
  QWidget* thresholdGauge() const;
  QPoint thresholdGaugePoint(double oneMinusThreshold) const;
  void readableMinimumsChanged() override;

 protected:
  void resizeEvent(QResizeEvent* event) override;

 private:
  /// The numbers in two columns where the panel is wide enough beside the image, else one;
  /// the measure button under the shorter of the two.
  void arrangeNumbers();
  void updateHistoryPlots();
  /// The prediction plot: the predicted score over the angle relative to the current
  /// frame's, the markers, and the measured errors relative to the current angle's.
  void updatePredictionPlot();
  /// Asks for the error at every fixed turn of the sweep and at the current angle.
  void measureTurns();

  /// One row of the numbers beside the image: its name and value labels (the tooltip of
  /// both defines the number), hidden while the frame does not publish it.
  struct Row {
    QLabel* name = nullptr;
    QLabel* value = nullptr;
  };
  void setRow(const QString& key, const QString& value);

  ImageView* view_ = nullptr;
  ReadoutGrid* numbers_ = nullptr;
  QVBoxLayout* imageColumn_ = nullptr;    ///< the image, maybe the measure row under it
  QVBoxLayout* numbersColumn_ = nullptr;  ///< the numbers, maybe the measure row under them
  QWidget* measureRow_ = nullptr;         ///< the measure button and its status
  std::map<QString, Row> rows_;
  QLabel* state_ = nullptr;
  ThresholdGauge* gauge_ = nullptr;
  PlotWidget* anglePlot_ = nullptr;
  PlotWidget* exPlot_ = nullptr;
  PlotWidget* predictionPlot_ = nullptr;
  QPushButton* measureButton_ = nullptr;
  QLabel* measureStatus_ = nullptr;

  /// The last frame's prediction (rotation.mode, the curve and the marked angles).
  struct Prediction {
    std::uint64_t frame = 0;
    std::vector<double> curve;  ///< score at -90..90 every 5°, 0 = none
    double current = 0.0;       ///< score of the current frame
    double currentDeg = 0.0, chosenDeg = 0.0;
    std::optional<double> pcaDeg;
    bool valid = false;
  } prediction_;
  /// The measured sweep: angles, errors (NaN until measured), the frame it was asked for.
  struct Measured {
    std::vector<double> anglesDeg, errorPct;
    double currentDeg = 0.0;
    std::uint64_t frame = 0;
    int done = 0;
    QString problem;
  } measured_;
  struct Sample {
    std::uint64_t frame;
    double angleDeg;
    double ex;
    bool held;
  };
  std::deque<Sample> history_;
  double threshold_ = sl::rtw::kDefaultHoldThreshold;
  QJsonObject drawn_;
};

}  // namespace sl::ui
