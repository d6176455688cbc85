// The main window: the viewport in the middle, dockable panels around it (Parameters,
// Timing, Lesson, Light, Charts and the publication panels of panels/PanelRegistry.h),
// toolbars for scene / technique / camera, the status line. Its parts live in their own
// classes: TeachingBar (overlays, split view, pause), PassStepper, LessonController,
// GrabRun (`--grab`) and SelfTests (`--self-test`).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <QElapsedTimer>
#include <QJsonObject>
#include <QMainWindow>
#include <QStringList>
#include <QTimer>

#include "PublicationDocks.h"

class QComboBox;
class QToolBar;
class QDockWidget;
class QLabel;

namespace sl {
struct Scene;
struct Publication;
}  // namespace sl

namespace sl::ui {

class ChartsPanel;
class GrabRun;
class LessonController;
class LessonPanel;
class LightPanel;
class ParamPanel;
class PassStepper;
class PresenterMode;
class SelfTests;
class SessionFiles;
class ShortcutsDialog;
class SplitSideParams;
class TeachingBar;
class TimingPanel;
class ViewportWidget;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  /// `interactive` false (grab runs): no dialogs, no QSettings, problems go to stderr.
  explicit MainWindow(bool interactive, QWidget* parent = nullptr);
  ~MainWindow() override;

  /// Loads a built-in scene or a .gltf/.glb file. On failure reports it (dialog when
  /// interactive, always status bar + stderr), keeps the previous scene, returns false.
  bool loadScene(const QString& nameOrPath);
  /// The scene to open at start: the last one used (interactive), else defaultSceneName().
  QString initialSceneName() const;
  /// "default" when it is a built-in scene (or there are none), else the first built-in.
  static QString defaultSceneName();

  /// Technique to start with; reported (not fatal) when unknown.
  void setTechnique(const QString& id);
  QString lastTechnique() const;  ///< from QSettings (interactive), else empty
  /// KEY=VALUE assignments applied once the renderer exists.
  void setPendingAssignments(const QStringList& assignments);

  /// Renders `frames` frames once the renderer is up, saves the window, the viewport and
  /// every dock into `dir`, prints the paths and quits the event loop (0 ok, 1 failure).
  void startGrab(const QString& dir, int frames);

  /// Window size and dock layout for a first start (or View > Default layout).
  void applyDefaultLayout();

  /// Starts a lesson: its 1-based number, its file's base name ("04-diagonal-pca") or a
  /// path to a preset. False (reported) when there is no such lesson or it cannot load.
  bool startLesson(const QString& lesson, int caseIndex = 0);

  /// `text` (a lesson's) with its live numbers ("{error_pct}", "{compare.error_pct}",
  /// "{pca.anisotropy}") filled from the last frame of the view and of its split half.
  std::string fillLiveText(const std::string& text) const;

  /// Runs GUI self-test `name` (params, bad-gltf=FILE, teaching=DIR, charts=DIR) once
  /// the renderer has drawn a frame: prints "ok"/"FAIL" lines, exits 0 (pass) or 1.
  void startSelfTest(const QString& name, const QString& argument);

  /// Presenter mode on or off (F11, View > Presenter mode, --presenter; PresenterMode.h).
  void setPresenterMode(bool on);

 protected:
  void closeEvent(QCloseEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  // The helpers below are the window's parts; each works on the window's widgets.
  friend class GrabRun;
  friend class LessonController;
  friend class PassStepper;
  friend class PresenterMode;
  friend class SelfTests;
  friend class SessionFiles;
  friend class SplitSideParams;
  friend class TeachingBar;

  void createActions();
  void createToolBar();
  /// A toolbar that cannot be moved or floated (layout stays predictable for lessons).
  QToolBar* addFixedToolBar(const QString& title, const QString& objectName);
  static void addToolBarLabel(QToolBar* bar, const QString& text);
  void createDocks();
  void createPanelDocks();
  QDockWidget* addPanelDock(QWidget* panel, const QString& title, const QString& name,
                            Qt::DockWidgetArea area);
  void createStatusBar();
  void restoreSettings();
  void saveSettings();

  void onRendererReady();
  void onRendererAboutToBeDestroyed();
  void onFrameRendered();
  void onRenderProblem(const QString& message);
  void onInitializationFailed(const QString& message);
  void onErrorComputed(double errorPct);
  void onErrorUnmeasured(const QString& why);
  /// Continuous rendering: the live error with its reference's age (greyed when stale).
  void updateLiveErrorLabel();
  void onSceneComboActivated(int index);
  void onTechniqueComboActivated(int index);
  void onChartsConfigurationChosen(const QString& id, const QStringList& assignments);

  void openSceneDialog();
  void rebuildParamPanel();
  void refreshBookmarks();
  void syncSceneCombo();
  void syncTechniqueCombo();
  void syncLightControls();
  void updateTitle();
  void showShortcuts();
  void saveScreenshot();
  void exportFigureDialog();
  /// File > Export figure to `path` (ViewportWidget::figureCells, ui/FigureKit.h); the
  /// problem, or nothing.
  std::optional<QString> exportFigure(const QString& path);
  void savePanelImage(QDockWidget* dock);
  void saveAllImages();

  /// Requests from the renderer the keys of the visible publication panels (every panel's
  /// while a grab runs or passes are stepped); a hidden dock requests nothing.
  void updatePublishing();
  /// The banner over the view: the pass being stepped, else the lesson.
  void updateBanner();
  /// A new frame or error: the lesson's texts that quote live numbers are filled again.
  void refreshLiveTexts();
  void setPaused(bool paused);
  void stepFrame();
  /// Renders until `frames` more frames are drawn (self-tests, grabs); false on timeout.
  bool waitForFrames(int frames, int timeoutMs = 30000);

  /// stderr always; status bar; a dialog titled `title` when interactive and non-empty.
  void report(const QString& message, const QString& dialogTitle = {});
  /// A status-bar note that does not hide a problem reported in the last seconds.
  void info(const QString& message);
  /// Shows `message` in the status bar, elided (shownMessage()); its full text as the status
  /// bar's tooltip while it is shown, when short enough (messageDetails()).
  void showStatus(const QString& message, int timeoutMs = 10000);

  const bool interactive_;
  ViewportWidget* viewport_ = nullptr;
  ParamPanel* paramPanel_ = nullptr;
  TimingPanel* timingPanel_ = nullptr;
  QDockWidget* paramDock_ = nullptr;
  QDockWidget* timingDock_ = nullptr;
  ShortcutsDialog* shortcuts_ = nullptr;
  LessonPanel* lessonPanel_ = nullptr;
  QDockWidget* lessonDock_ = nullptr;
  QDockWidget* lightDock_ = nullptr;
  ChartsPanel* chartsPanel_ = nullptr;
  QDockWidget* chartsDock_ = nullptr;
  /// The docks of the publication panels (panels/PanelRegistry.h), in registry order.
  PublicationDocks docks_;
  QMenu* saveImageMenu_ = nullptr;

  QAction* pauseAction_ = nullptr;
  QAction* openAction_ = nullptr;
  QAction* passStopAction_ = nullptr;
  bool dialogs_ = false;  ///< message boxes for problems (interactive runs and self-tests)

  QComboBox* sceneCombo_ = nullptr;
  QComboBox* techniqueCombo_ = nullptr;
  QComboBox* bookmarkCombo_ = nullptr;
  LightPanel* lightPanel_ = nullptr;  ///< the Light dock (ui/panels/light)

  QLabel* sceneLabel_ = nullptr;
  QLabel* frameLabel_ = nullptr;
  QLabel* errorLabel_ = nullptr;
  QLabel* glLabel_ = nullptr;

  QString sceneSpec_;  ///< name or path of the scene shown
  QStringList pendingAssignments_;
  bool rendererBound_ = false;  ///< onRendererReady ran for the current renderer
  bool failed_ = false;
  QElapsedTimer lastProblemClock_;  ///< since the last report()

  QList<QAction*> commandActions_;  ///< listed in the Help window
  QAction* continuousAction_ = nullptr;

  // Parts of the window (created in the constructor, in this order).
  std::unique_ptr<LessonController> lessons_;
  std::unique_ptr<PassStepper> passes_;
  std::unique_ptr<TeachingBar> teaching_;
  std::unique_ptr<GrabRun> grab_;
  std::unique_ptr<SelfTests> selfTests_;
  std::unique_ptr<SessionFiles> sessions_;
  PresenterMode* presenter_ = nullptr;    ///< a child QObject of the window
  SplitSideParams* splitSide_ = nullptr;  ///< the split view's parameters (a child QObject)
};

}  // namespace sl::ui
