// The split view's own parameters in the Parameters dock (issue 15): while the split view
// is on, a second ParamPanel under the main one edits the right half's technique (read from
// its ParamDecls like the main panel), and "Equal memory" sets its memory knob
// (ParamDecl::memoryKnob) so that it spends the main technique's bytes
// (ViewportWidget::matchSplitMemory), showing both counts. While the toggle is on, a change of the
// main side's memory matches again.
#pragma once

#include <cstdint>
#include <optional>

#include <QObject>
#include <QString>

class QCheckBox;
class QLabel;
class QWidget;

namespace sl::ui {

class MainWindow;
class ParamPanel;

class SplitSideParams : public QObject {
  Q_OBJECT

 public:
  explicit SplitSideParams(MainWindow& window);

  /// The Parameters dock's widget: the main ParamPanel above, the compare side below.
  QWidget* createDockWidget(ParamPanel* mainPanel);
  /// Rebuilds the compare side's panel for the split technique (hidden when off).
  void rebuild();
  /// Rebuilds only the compare side's rows (presenter mode's font: the rows scale the font
  /// they were built with); no new memory match.
  void rebuildRows();
  /// After each frame: the byte counts, and a new match when equal memory is on and the
  /// main side's memory changed.
  void onFrameRendered();
  /// Drops references into the split renderer (it is about to go).
  void clear();

  ParamPanel* panel() const { return panel_; }
  QCheckBox* equalMemoryBox() const { return equalMemory_; }
  /// The last match (equal memory), if any.
  const std::optional<std::uint64_t>& matchedMainBytes() const { return matchedMainBytes_; }
  QString bytesText() const;

 private:
  void match();

  MainWindow& w_;
  QWidget* area_ = nullptr;  ///< the scroll area holding box_ (hidden while the split is off)
  QWidget* box_ = nullptr;
  QLabel* title_ = nullptr;
  QLabel* bytes_ = nullptr;
  QCheckBox* equalMemory_ = nullptr;
  ParamPanel* panel_ = nullptr;
  std::optional<std::uint64_t> matchedMainBytes_;  ///< main bytes the last match aimed at
  QString matchNote_;
  bool matching_ = false;
};

}  // namespace sl::ui
