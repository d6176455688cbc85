// `--grab DIR --grab-after N`: renders N frames once the renderer is up (every panel's
// publications requested), saves the window, the viewport and every dock as PNGs and
// published.json (the renderer's numbers, the keys published, what each panel drew) into
// DIR, and quits (0 ok, 1 on any problem). Also writes the images of File > Save all.
#pragma once

#include <QElapsedTimer>
#include <QJsonObject>
#include <QObject>
#include <QStringList>
#include <QTimer>

namespace sl::ui {

class MainWindow;

class GrabRun : public QObject {
  Q_OBJECT

 public:
  explicit GrabRun(MainWindow& window);

  void start(const QString& dir, int frames);
  bool running() const { return !dir_.isEmpty(); }
  /// A frame was drawn with the renderer bound.
  void countFrame() { ++framesRendered_; }
  void resetFrameCount() { framesRendered_ = 0; }
  /// A problem of a scripted run, from the window's start on (a lesson's scene that does not
  /// load, a light the technique refuses, a frame that fails): repeated at the end, and the
  /// grab exits 1.
  void noteProblem(const QString& message);
  void stop() { timer_.stop(); }

  /// window.png, viewport.png and panel-<name>.png into `dir`; returns failures.
  QStringList writeImages(const QString& dir, bool printPaths);

 private:
  void tick();
  void finish();
  QJsonObject publicationJson() const;

  MainWindow& w_;
  QString dir_;
  int frames_ = 0;
  int framesRendered_ = 0;
  QStringList problems_;
  QTimer timer_;
  QElapsedTimer clock_;
};

}  // namespace sl::ui
