// Scripted control of the window: what a script needs to drive the GUI as a user would and
// read what it shows, without reaching into the window's internals. Open a scene, technique
// or lesson, set a parameter, wait for frames or for a lesson to settle, read the status
// line's readouts, the view's caption and the renderer's publications, grab images. No
// checks of its own: the GUI tests (tests/gui, shadowlab-gui-tests) assert on what it
// returns; a demo or a recording script could use it the same way.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>

#include <QImage>
#include <QKeySequence>
#include <QObject>
#include <QString>
#include <QStringList>

#include "view/ViewportWidget.h"
#include "core/Renderer.h"

namespace sl {
struct Publication;
class Renderer;
}  // namespace sl

namespace sl::ui {

class MainWindow;

class Automation : public QObject {
  Q_OBJECT

 public:
  /// Marks `window` scripted (MainWindow::setScripted: message boxes for problems, Qt's own
  /// file dialogs); a child of the window.
  explicit Automation(MainWindow& window);

  MainWindow& window() const { return w_; }
  ViewportWidget& viewport() const;
  /// The main side (technique, parameters, last frame), or null before the render service is ready.
  sl::ViewSide* mainSide() const;

  /// Calls `ready` from the event loop once the renderer is bound, has drawn two frames and
  /// a lesson being opened has settled; `failed` with the reason when the renderer failed or
  /// this did not happen within `timeoutMs`.
  void whenReady(std::function<void()> ready, std::function<void(const QString&)> failed,
                 int timeoutMs = 120000);

  /// As the toolbar's Scene box / File > Open: false (reported) when it cannot load.
  bool openScene(const QString& nameOrPath);
  /// As the Technique box; the problem when the id is unknown.
  std::optional<QString> setTechnique(const QString& id);
  /// As Lessons > N (a 1-based number, a file's base name or a path); false when refused.
  bool openLesson(const QString& lesson, int caseIndex = 0);
  /// KEY=VALUE on the main technique's parameters, else the shared ones (as --set); the
  /// problem (unknown key, value out of range), or nothing.
  std::optional<QString> setParameter(const QString& keyEqualsValue);

  /// As F6 (View > Render continuously): continuous rendering on when off, off when on.
  void toggleContinuous();
  /// As Space / the pause button: no new frames until resumed or stepped.
  void setPaused(bool paused);
  /// As `.`: one frame while paused (pausing first when running).
  void stepFrame();
  /// As F11 (View > Presenter mode).
  void setPresenterMode(bool on);
  /// As the teaching bar's "Compare with": `techniqueId` on the split view's right half with
  /// its own parameters (KEY -> text); empty: the split view off.
  void setSplit(const QString& techniqueId, const std::map<std::string, std::string>& params = {});
  /// As the teaching bar's Split button / View > Split view.
  void toggleSplit();
  /// As View > Next overlay.
  void cycleOverlay();
  /// As File > Save session / Open session (no dialog); false (reported) on failure.
  bool saveSession(const QString& path);
  bool openSession(const QString& path);
  /// File > Recent sessions, newest first.
  QStringList recentSessions() const;

  /// Renders until `frames` more frames are drawn; false on timeout.
  [[nodiscard]] bool waitForFrames(int frames, int timeoutMs = 30000);
  /// Waits until the probe of the pixel under the mouse has come back (it is read on the
  /// render thread); false on timeout.
  bool waitForProbe(int timeoutMs = 10000);
  /// Renders until an opened lesson has settled (LessonController); false on timeout.
  bool waitForSettled(int timeoutMs = 60000);

  /// The status line's error readout ("error 0.420 %", "error n/a (no covered pixel)").
  QString errorReadout() const;
  /// False while the error readout is greyed: its number is an earlier view's (continuous
  /// rendering, the live reference not yet of this view) or there is none yet.
  bool errorReadoutCurrent() const;
  /// The status line's text size in pixels (presenter mode enlarges it).
  int statusTextPixelSize() const;
  /// The status bar's current message (empty: none).
  QString statusMessage() const;
  /// Clears the status bar's message (a script then reads the next one).
  void clearStatusMessage();
  /// The scene shown: its built-in name or the path it was opened from.
  QString sceneShown() const;
  /// The view's resolution note ("internal resolution 240×150: frame took 610 ms" while
  /// adaptive resolution reduced it), empty at full size.
  QString resolutionNote() const;
  /// How the view drew its last frame: internal resolution, frame time, progressive tiles,
  /// captions and notes, the presenter's ring and zoom inset, the live reference workers.
  ViewportWidget::Readouts viewReadouts() const;
  /// The main renderer's publication of its last frame (null before the renderer exists).
  const sl::Publication* publication() const;

  /// The whole window / the view as shown (split half, captions, banner, legends), the view
  /// rendered for it at full size (never the adaptive resolution's reduced frame).
  QImage grabWindow() const;
  QImage grabView() const;
  /// The view's frame as rendered (both halves, no overlay; device pixels), a frame of the
  /// current view drawn first when the one shown is older.
  QImage renderedFrame() const;
  /// As File > Export figure to `path`; the problem, or nothing.
  std::optional<QString> exportFigure(const QString& path);
  /// As File > Save viewport image to `path`; the problem, or nothing.
  std::optional<QString> saveViewImage(const QString& path);
  /// As pressing `keys` in the window: triggers the window's enabled action with that
  /// shortcut (a menu command: O, Ctrl+E, F5, …); false when none has it.
  bool trigger(const QKeySequence& keys);
  /// As the Parameters dock's "Equal memory" box of the split view (a match runs at once).
  void setEqualMemory(bool on);

  // Reads of the main renderer's last frame, run on the render thread (the UI waits).
  /// The pixel (x, y) of the last frame (internal pixels), or nothing outside it.
  std::optional<sl::PixelProbe> probePixel(int x, int y) const;
  /// The exact error of the last frame (its readback, the reference mask and the stats).
  sl::Renderer::ErrorResult computeError() const;
  /// The last frame's per-pixel data.
  sl::FrameReadback readback() const;

 private:
  MainWindow& w_;
};

}  // namespace sl::ui
