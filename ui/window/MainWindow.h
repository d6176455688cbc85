// The main window: the viewport in the middle, dockable panels around it (Parameters,
// Timing, Lesson, Light, Charts and the publication panels of panels/PanelRegistry.h),
// toolbars for scene / technique / camera, the status line (its construction in
// MainWindowSetup.cpp, its scenes in MainWindowScenes.cpp). Its parts live in their own
// classes: TeachingBar (overlays, split view, pause), PassStepper, LessonController,
// GrabRun (`--grab`), SessionFiles, PresenterMode, SplitSideParams, StatusLine (the status
// line's readouts), WindowImages (saved images, figures, full-size grabs); they and ui/Automation.h
// (scripted control) reach the window's widgets through the accessors below, none is a friend.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <QElapsedTimer>
#include <QImage>
#include <QJsonObject>
#include <QMainWindow>
#include <QStringList>
#include <QTimer>

#include "window/PublicationDocks.h"

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
class SessionFiles;
class ShortcutsDialog;
class SplitSideParams;
class StatusLine;
class TeachingBar;
class TimingPanel;
class ViewportWidget;
class WindowImages;

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
  const QStringList& pendingAssignments() const { return pendingAssignments_; }

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

  /// Presenter mode on or off (F11, View > Presenter mode, --presenter; PresenterMode.h).
  void setPresenterMode(bool on);

  /// A script drives the window (ui/Automation.h): problems also in message boxes (as a user
  /// would see them) and file dialogs are Qt's own (a script can fill them in).
  void setScripted(bool scripted);
  bool scripted() const { return scripted_; }
  bool interactive() const { return interactive_; }

  // The window's parts, for its helpers (GrabRun, LessonController, PassStepper, PresenterMode,
  // SessionFiles, SplitSideParams, TeachingBar, WindowImages) and ui/Automation.h.
  ViewportWidget* viewport() const { return viewport_; }
  PublicationDocks& docks() { return docks_; }
  const QString& sceneSpec() const { return sceneSpec_; }  ///< name or path of the scene shown
  LessonController* lessons() const { return lessons_.get(); }
  PassStepper* passes() const { return passes_.get(); }
  TeachingBar* teaching() const { return teaching_.get(); }
  SessionFiles* sessions() const { return sessions_.get(); }
  PresenterMode* presenter() const { return presenter_; }
  SplitSideParams* splitSide() const { return splitSide_; }
  ParamPanel* paramPanel() const { return paramPanel_; }
  TimingPanel* timingPanel() const { return timingPanel_; }
  LessonPanel* lessonPanel() const { return lessonPanel_; }
  ChartsPanel* chartsPanel() const { return chartsPanel_; }
  QDockWidget* paramDock() const { return paramDock_; }
  QDockWidget* timingDock() const { return timingDock_; }
  QDockWidget* lessonDock() const { return lessonDock_; }
  QDockWidget* chartsDock() const { return chartsDock_; }
  QComboBox* sceneCombo() const { return sceneCombo_; }
  QComboBox* techniqueCombo() const { return techniqueCombo_; }
  StatusLine* statusLine() const { return status_; }  ///< the status line's readouts
  WindowImages& images() const { return *images_; }
  QAction* openAction() const { return openAction_; }
  QAction* continuousAction() const { return continuousAction_; }
  QAction* pauseAction() const { return pauseAction_; }
  QAction* passStopAction() const { return passStopAction_; }
  /// Adds `action` to the commands the Help window lists.
  void addCommandAction(QAction* action) { commandActions_ << action; }
  bool rendererBound() const { return rendererBound_; }  ///< the renderer's panels are bound
  bool failed() const { return failed_; }  ///< the GL context or renderer failed to start

  /// Renders until `frames` more frames are drawn; false on timeout.
  bool waitForFrames(int frames, int timeoutMs = 30000);
  void stepFrame();
  void setPaused(bool paused);
  /// stderr always; status bar; a dialog titled `title` when dialogs are on and non-empty.
  void report(const QString& message, const QString& dialogTitle = {});
  /// A status-bar note that does not hide a problem reported in the last seconds.
  void info(const QString& message);
  /// Requests from the renderer the keys of the visible publication panels (every panel's
  /// while a grab runs or passes are stepped); a hidden dock requests nothing.
  void updatePublishing();
  /// The banner over the view: the pass being stepped, else the lesson.
  void updateBanner();
  /// A new frame or error: the lesson's texts that quote live numbers are filled again.
  void refreshLiveTexts();
  void rebuildParamPanel();
  void syncLightControls();
  void refreshBookmarks();
  /// Shows `message` in the status bar, elided (shownMessage()); its full text as the status
  /// bar's tooltip while it is shown, when short enough (messageDetails()).
  void showStatus(const QString& message, int timeoutMs = 10000);
  /// A toolbar that cannot be moved or floated (layout stays predictable for lessons).
  QToolBar* addFixedToolBar(const QString& title, const QString& objectName);
  static void addToolBarLabel(QToolBar* bar, const QString& text);
  /// The Scene box's data of its "Open…" item (no scene name or path can be it).
  static QString openItemData() { return QStringLiteral("\x01open"); }

 protected:
  void closeEvent(QCloseEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  void createActions();
  void createToolBar();
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
  void onSceneComboActivated(int index);
  void onTechniqueComboActivated(int index);
  void onChartsConfigurationChosen(const QString& id, const QStringList& assignments);

  void openSceneDialog();
  void syncSceneCombo();
  void syncTechniqueCombo();
  void updateTitle();
  void showShortcuts();

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
  bool dialogs_ = false;  ///< message boxes for problems (interactive or scripted runs)
  bool scripted_ = false;

  QComboBox* sceneCombo_ = nullptr;
  QComboBox* techniqueCombo_ = nullptr;
  QComboBox* bookmarkCombo_ = nullptr;
  LightPanel* lightPanel_ = nullptr;  ///< the Light dock (ui/panels/light)

  StatusLine* status_ = nullptr;  ///< the status line's readouts (a child QObject)

  QString sceneSpec_;          ///< name or path of the scene shown
  bool sceneLoading_ = false;  ///< a scene loads off the UI thread (loadScene)
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
  std::unique_ptr<SessionFiles> sessions_;
  PresenterMode* presenter_ = nullptr;    ///< a child QObject of the window
  SplitSideParams* splitSide_ = nullptr;  ///< the split view's parameters (a child QObject)
  WindowImages* images_ = nullptr;        ///< File's images, full-size grabs (a child QObject)
};

}  // namespace sl::ui
