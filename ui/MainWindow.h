// The main window: the viewport in the middle, dockable panels around it (Parameters,
// Lesson, Importance map, Covariance, Warp functions, Moment mip chain, Shadow map, Timing),
// toolbars for scene / technique / camera, the Light dock and for overlays, split view, pause,
// frame and pass stepping, the Lessons menu, and the status line. Also drives `--grab` runs and the
// `--self-test` checks.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <QElapsedTimer>
#include <QJsonObject>
#include <QMainWindow>
#include <QStringList>
#include <QTimer>

class QComboBox;
class QToolBar;
class QDockWidget;
class QLabel;
class QSlider;

namespace sl {
struct Scene;
struct Publication;
}  // namespace sl

namespace sl::ui {

class ChartsPanel;
class CovariancePanel;
class ImportancePanel;
class LessonPanel;
class LightPanel;
class MomentPanel;
class ParamPanel;
class PublicationPanel;
class ShadowMapPanel;
class ShortcutsDialog;
class TimingPanel;
class ViewportWidget;
class WarpPanel;
struct Lesson;

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
  bool startLesson(const QString& lesson);

  /// Runs GUI self-test `name` (params, bad-gltf=FILE, teaching=DIR, charts=DIR) once
  /// the renderer has drawn a frame: prints "ok"/"FAIL" lines, exits 0 (pass) or 1.
  void startSelfTest(const QString& name, const QString& argument);

 protected:
  void closeEvent(QCloseEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  void createActions();
  void createToolBar();
  /// A toolbar that cannot be moved or floated (layout stays predictable for lessons).
  QToolBar* addFixedToolBar(const QString& title, const QString& objectName);
  static void addToolBarLabel(QToolBar* bar, const QString& text);
  void createDocks();
  void createStatusBar();
  void restoreSettings();
  void saveSettings();

  void onRendererReady();
  void onRendererAboutToBeDestroyed();
  void onFrameRendered();
  void onRenderProblem(const QString& message);
  void onInitializationFailed(const QString& message);
  void onErrorComputed(double errorPct);
  void onSceneComboActivated(int index);
  void onTechniqueComboActivated(int index);

  void openSceneDialog();
  void rebuildParamPanel();
  void refreshBookmarks();
  void syncSceneCombo();
  void syncTechniqueCombo();
  void syncLightControls();
  void updateTitle();
  void showShortcuts();
  void saveScreenshot();

  void createTeachingToolBar();
  void createPanelDocks();
  void createLessonsMenu(QMenu* menu);
  QDockWidget* addPanelDock(QWidget* panel, const QString& title, const QString& name,
                            Qt::DockWidgetArea area);

  // Lessons.
  void applyLesson(int index);
  void updateBanner();

  // Panels that observe the Publication.
  void updatePublishing();
  /// Gives the current publication to the visible panels (`all`: to every panel).
  void feedPanels(bool all);
  bool publicationIsCurrent() const;

  // Pause, frame and pass stepping.
  void setPaused(bool paused);
  void stepFrame();
  void stepPass(int delta);
  void stopPassStepping();
  void showPass();

  // Overlays and split view (bound to the renderer's `view.overlay` declaration).
  void syncOverlayCombo();
  void setOverlay(int value);
  void cycleOverlay();
  void setSplitTechnique(const QString& id);
  void toggleSplit();

  // Screenshots.
  void savePanelImage(QDockWidget* dock);
  void saveAllImages();
  /// window.png, viewport.png and panel-<name>.png into `dir`; returns failures.
  QStringList writeImages(const QString& dir, bool printPaths);
  QJsonObject publicationJson() const;

  void grabTick();
  void finishGrab();

  // Self-tests (MainWindowSelfTest.cpp).
  bool waitForFrames(int frames, int timeoutMs = 30000);
  bool selfTestParams();
  /// bad-gltf=FILE[,FILE…]: each broken file opened through File > Open, then dropped on
  /// the window; each time the error is shown (elided) and the scene stays.
  bool selfTestBadGltf(const QString& paths);
  void selfTestBadGltfOpen(const QString& path, bool drop);
  /// Pass stepping, overlays, split view and lessons; PNGs of each step into `dir`.
  bool selfTestTeaching(const QString& dir);
  /// A tiny Charts sweep, its PNG into `dir`, and a click on a point switching the view.
  bool selfTestCharts(const QString& dir);
  /// Part of selfTestCharts: x: memory and back through the combo box (axis, front).
  bool selfTestChartsAxis(const QString& dir);
  void selfTestCheck(bool ok, const QString& what);
  void runSelfTest();
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

  ImportancePanel* importancePanel_ = nullptr;
  MomentPanel* momentPanel_ = nullptr;
  CovariancePanel* covariancePanel_ = nullptr;
  WarpPanel* warpPanel_ = nullptr;
  ShadowMapPanel* shadowMapPanel_ = nullptr;
  LessonPanel* lessonPanel_ = nullptr;
  QDockWidget* importanceDock_ = nullptr;
  QDockWidget* momentDock_ = nullptr;
  QDockWidget* covarianceDock_ = nullptr;
  QDockWidget* warpDock_ = nullptr;
  QDockWidget* shadowMapDock_ = nullptr;
  QDockWidget* lessonDock_ = nullptr;
  ChartsPanel* chartsPanel_ = nullptr;
  QDockWidget* chartsDock_ = nullptr;
  /// Every dock with a panel that shows the Publication.
  std::vector<std::pair<QDockWidget*, PublicationPanel*>> publicationDocks_;
  QMenu* saveImageMenu_ = nullptr;

  QComboBox* overlayCombo_ = nullptr;
  QComboBox* splitCombo_ = nullptr;
  QAction* pauseAction_ = nullptr;
  QAction* openAction_ = nullptr;
  QAction* bannerAction_ = nullptr;
  QAction* passStopAction_ = nullptr;
  QString lastSplitTechnique_;

  std::vector<Lesson> lessons_;
  int lessonIndex_ = -1;

  struct PassStep {
    QString id;                   ///< what the panels highlight ("im", "collapse", ...)
    QString title;                ///< "Importance map"
    QString text;                 ///< what the pass does and what to look at
    QDockWidget* dock = nullptr;  ///< the panel showing its output (null: the view)
  };
  std::vector<PassStep> passSteps_;
  int passIndex_ = -1;  ///< -1: not stepping
  bool passWaitingForFrame_ = false;
  bool pausedBeforePasses_ = false;
  bool dialogs_ = false;  ///< message boxes for problems (interactive runs and self-tests)

  // --self-test
  QString selfTest_, selfTestArgument_;
  int selfTestFailures_ = 0;

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

  // --grab
  QString grabDir_;
  int grabFrames_ = 0;
  int grabFramesRendered_ = 0;
  QStringList grabProblems_;
  QTimer grabTimer_;
  QElapsedTimer grabClock_;

  QList<QAction*> commandActions_;  ///< listed in the Help window
  QAction* continuousAction_ = nullptr;
};

}  // namespace sl::ui
