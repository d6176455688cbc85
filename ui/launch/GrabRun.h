// `--grab DIR --grab-after N`: renders N frames once the renderer is up (every panel's
// publications requested), saves the window, the viewport and every dock as PNGs and
// published.json (the renderer's numbers, the keys published, what each panel drew) into
// DIR, and quits (0 ok, 1 on any problem, 2 when DIR cannot take its files). Also writes the
// images of File > Save all. Every file the window writes (these, image exports, sessions)
// goes through the output policy of algo/OutputFile.h: checked before the work against the
// run's inputs (windowInputs), written to a temporary file and renamed, never into a FIFO or
// device.
#pragma once

#include <optional>
#include <vector>

#include <QByteArray>
#include <QElapsedTimer>
#include <QJsonObject>
#include <QObject>
#include <QStringList>
#include <QTimer>

#include "algo/OutputFile.h"

class QImage;

namespace sl::ui {

class MainWindow;

/// The files of this window's run that no output may replace: the scene's (its glTF, buffers
/// and images), the course file and, unless `forSession`, every lesson and session opened
/// (File > Save session may replace a session: its dialog asked).
std::vector<sl::InputTarget> windowInputs(const MainWindow& window, bool forSession = false);
/// Writes `bytes` to `path` under the output policy, the window's inputs protected: an error
/// naming the file ("P is the same file as the scene's ..."), or nothing.
std::optional<QString> writeWindowOutput(const MainWindow& window, const QString& path,
                                         const QByteArray& bytes, bool forSession = false);
/// The image as PNG bytes (empty when it cannot be encoded).
QByteArray pngBytes(const QImage& image);

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

  /// window.png, viewport.png and panel-<name>.png into `dir`, checked first (nothing is
  /// written when one cannot be); returns failures.
  QStringList writeImages(const QString& dir, bool printPaths);

 private:
  /// Every file a grab into `dir` writes (the images and, with `published`, published.json),
  /// checked against each other and the window's inputs: the first problem, or nothing.
  std::optional<QString> checkGrabFiles(const QString& dir, bool published) const;
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
