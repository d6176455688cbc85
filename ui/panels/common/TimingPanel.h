// The Timing panel: per-pass times of the current frame (bars), the recent frame-time
// history, the shadow-related GPU memory and the bytes the panels read back, all read from
// the renderer's FrameStats; the passes are named and explained by their declarations.
#pragma once

#include <QStringList>
#include <QWidget>

#include <vector>

#include "core/Renderer.h"

class QBoxLayout;
class QLabel;
class QTreeWidget;

namespace sl::ui {

class PassBarsWidget;
class FrameHistoryWidget;

class TimingPanel : public QWidget {
  Q_OBJECT

 public:
  explicit TimingPanel(QWidget* parent = nullptr);

  /// The technique whose declared passes (core/Renderer.h framePassDecls) name the bars.
  void setTechnique(const sl::TechniqueInfo* technique);
  /// Shows the stats of the frame just rendered. `failure` (the frame's problem): its time is
  /// n/a with the reason, no bars, and it stays out of the history.
  void showStats(const sl::FrameStats& stats, const QString& failure = {});
  /// The summary line as shown ("Frame 12 · 640 × 400 px · total 3.1 ms · …").
  QString summaryText() const;
  /// Forgets the history (new scene or technique: old times are not comparable).
  void resetHistory();

  /// The bars' pass names, and each as it is drawn at the panel's present size (its wrapped
  /// lines joined: a name too wide for its room wraps, never elided).
  QStringList passNames() const;
  QStringList shownPassNames() const;
  /// Whether the three boxes stand one above the other (a narrow panel, large fonts).
  bool stacked() const;

 protected:
  void resizeEvent(QResizeEvent* event) override;
  /// The boxes' widest width (one above the other, as the panel arranges them when narrow)
  /// and their tallest height (side by side): the row's sum of widths must never hold the
  /// window wider than its screen.
  QSize minimumSizeHint() const override;
  void changeEvent(QEvent* event) override;

 private:
  void arrangeBoxes();

  QBoxLayout* row_ = nullptr;
  QLabel* summary_ = nullptr;
  PassBarsWidget* passes_ = nullptr;
  FrameHistoryWidget* history_ = nullptr;
  QTreeWidget* memory_ = nullptr;
  QLabel* memoryTotal_ = nullptr;
  QStringList memoryKey_;
  std::vector<sl::PassDecl> declared_;  ///< what the memory list shows, to skip identical rebuilds
};

}  // namespace sl::ui
