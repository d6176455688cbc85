// The Charts panel: runs a small speed-against-accuracy sweep of the current scene (the
// CLI's `bench` in miniature: configurations "ID[:KEY=V1,V2]...", N frames along the
// scene's camera path, medians of frame time and shadow error) as one render-service job
// (measure/Sweep.h, the measuring library's sweep), with a progress bar and Cancel, and draws the
// same scatter chart with its Pareto front as results arrive. x is the frame time or the shadow
// memory (a combo box; switching redraws without measuring again). Clicking a point asks the main
// window to switch the view to that configuration (configurationChosen).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <QPointer>
#include <QStringList>
#include <QTimer>
#include <QWidget>

#include "algo/metrics/BenchStats.h"
#include "core/Renderer.h"
#include "measure/Sweep.h"

class QChart;
class QChartView;
class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace sl::ui {

class ViewportWidget;

class ChartsPanel : public QWidget {
  Q_OBJECT

 public:
  /// One configuration of the sweep and what it measured.
  struct Config {
    QString techniqueId;
    QStringList assignments;                  ///< "KEY=VALUE", technique or shared parameters
    QString label;                            ///< "uniform resolution=1024"
    std::vector<double> ms, bytes, errorPct;  ///< per frame (bytes: shadow memory)
    double medianMs = 0.0, medianBytes = 0.0, medianErrorPct = 0.0;
    bool done = false;
  };

  explicit ChartsPanel(ViewportWidget* viewport, QWidget* parent = nullptr);
  ~ChartsPanel() override;

  /// The sweep text, "ID[:KEY=V1,V2,...] ..." (empty: the default for the technique shown).
  void setSweepText(const QString& text);
  void setFramesPerConfig(int frames);
  /// What the chart's x axis and Pareto front are against (the combo box follows).
  void setChartX(sl::ChartX x);
  sl::ChartX chartX() const { return chartX_; }
  /// The configurations on the drawn Pareto front (indices into configs(), by cost).
  const std::vector<std::size_t>& drawnFront() const { return drawnFront_; }
  /// The drawn chart's x-axis title.
  QString xAxisTitle() const;
  /// Starts the sweep (false, with the reason in the status line, on a bad sweep text).
  bool startSweep();
  void cancelSweep();
  bool running() const { return running_; }
  const std::vector<Config>& configs() const { return configs_; }
  /// What a click on configuration `index` does (emits configurationChosen).
  void choose(int index);
  /// Stops the sweep (the view is about to go); a frame still on the render thread is
  /// dropped when it returns.
  void releaseRenderer();
  /// The sweep an empty text runs: the technique shown and a baseline that renders the
  /// view's light, each at 3 resolutions.
  QString defaultSweepText() const;

  QSize sizeHint() const override { return {520, 420}; }

 Q_SIGNALS:
  void configurationChosen(const QString& techniqueId, const QStringList& assignments);
  /// The sweep finished (or was cancelled, `completed` false).
  void sweepFinished(bool completed);

 private:
  /// Posts the sweep from `from` on to the render service as one job ("charts" renderer).
  void postSweep(sl::measure::SweepPosition from);
  /// Back on the UI thread: records frame `frame` of configuration `config` (a stale `serial`
  /// is dropped).
  void measured(std::uint64_t serial, std::size_t config, std::size_t frame,
                const sl::measure::SweepFrame& m);
  /// The job ended at `at`: done, or stopped by another job (a blocking call): it goes on.
  void sweepEnded(std::uint64_t serial, sl::measure::SweepPosition at);
  void finish(bool completed);
  void redrawChart();
  /// Where configuration c sits on the x axis now (ms, or bytes in the axis' unit).
  double chartXOf(const Config& c) const;
  /// Parses the sweep text into configs_; the error, or empty.
  QString parseSweep(const QString& text);

  QPointer<ViewportWidget> viewport_;  ///< (gone first when the window closes)
  QLineEdit* sweepEdit_ = nullptr;
  QSpinBox* framesSpin_ = nullptr;
  QComboBox* xCombo_ = nullptr;
  QPushButton* runButton_ = nullptr;
  QPushButton* cancelButton_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QLabel* status_ = nullptr;
  QChartView* chartView_ = nullptr;

  std::vector<Config> configs_;
  std::vector<sl::measure::SweepConfig> sweep_;  ///< configs_ with every value, as rendered
  std::vector<sl::Camera> cameras_;              ///< the sweep's frames
  bool running_ = false;
  std::uint64_t sweepSerial_ = 0;  ///< bumped by every start, finish and cancel
  int frames_ = 6;
  sl::ChartX chartX_ = sl::ChartX::TimeMs;
  double xUnitScale_ = 1.0;  ///< data units per x-axis unit of the drawn chart
  std::vector<std::size_t> drawnFront_;
};

}  // namespace sl::ui
