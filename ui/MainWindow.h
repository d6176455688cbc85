// The main window: the viewport in the middle, the Parameters dock on the right, the
// Timing dock at the bottom, a toolbar for scene / technique / sun / camera, and the
// status line (frame time, error, GL renderer). Also drives `--grab` runs.
#pragma once

#include <memory>
#include <string>

#include <QElapsedTimer>
#include <QMainWindow>
#include <QStringList>
#include <QTimer>

class QComboBox;
class QDockWidget;
class QLabel;
class QSlider;

namespace sl {
struct Scene;
}

namespace sl::ui {

class ParamPanel;
class ShortcutsDialog;
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

 protected:
  void closeEvent(QCloseEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  void createActions();
  void createToolBar();
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
  void showLightValues();
  void updateLightFromControls();
  void updateTitle();
  void showShortcuts();
  void saveScreenshot();

  void grabTick();
  void finishGrab();
  /// stderr always; status bar; a dialog titled `title` when interactive and non-empty.
  void report(const QString& message, const QString& dialogTitle = {});
  /// A status-bar note that does not hide a problem reported in the last seconds.
  void info(const QString& message);

  const bool interactive_;
  ViewportWidget* viewport_ = nullptr;
  ParamPanel* paramPanel_ = nullptr;
  TimingPanel* timingPanel_ = nullptr;
  QDockWidget* paramDock_ = nullptr;
  QDockWidget* timingDock_ = nullptr;
  ShortcutsDialog* shortcuts_ = nullptr;

  QComboBox* sceneCombo_ = nullptr;
  QComboBox* techniqueCombo_ = nullptr;
  QComboBox* bookmarkCombo_ = nullptr;
  QSlider* azimuthSlider_ = nullptr;
  QSlider* elevationSlider_ = nullptr;
  QLabel* azimuthLabel_ = nullptr;
  QLabel* elevationLabel_ = nullptr;

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
