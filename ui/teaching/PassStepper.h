// Pass stepping: walks through the passes of one frame as the technique and the renderer
// declare them (core/Renderer.h framePassDecls: id, title, explanation, panel), pausing the
// view, raising and marking the panel that shows each pass's output and explaining it in
// the banner; past the last pass it renders the next frame and starts over.
#pragma once

#include <vector>

#include <QObject>
#include <QString>

class QDockWidget;

namespace sl::ui {

class MainWindow;

class PassStepper : public QObject {
  Q_OBJECT

 public:
  struct Step {
    QString id;                   ///< the pass's timer id ("blur")
    QString title;                ///< "Blur and floor"
    QString text;                 ///< what the pass does and what to look at
    QDockWidget* dock = nullptr;  ///< the panel showing its output (null: the view)
  };

  explicit PassStepper(MainWindow& window);

  /// ] (+1) and [ (-1): starts stepping at the first pass of a published frame.
  void step(int delta);
  /// Esc: back to the view, resumed if it was running before.
  void stop();
  /// After "step one frame" while stepping: start again at the new frame's first pass.
  void restartAtNextFrame();
  /// A frame was rendered: when one was awaited, show its first pass.
  void onFrameRendered();

  bool active() const { return index_ >= 0 || waitingForFrame_; }
  bool waitingForFrame() const { return waitingForFrame_; }
  int index() const { return index_; }
  const std::vector<Step>& steps() const { return steps_; }
  /// Banner title and text for the pass shown; empty when not stepping.
  QString bannerTitle() const;
  QString bannerText() const;

 private:
  void show();
  void buildSteps();

  MainWindow& w_;
  std::vector<Step> steps_;
  int index_ = -1;  ///< -1: not stepping
  bool waitingForFrame_ = false;
  bool pausedBefore_ = false;
};

}  // namespace sl::ui
