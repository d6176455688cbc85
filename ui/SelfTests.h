// GUI self-tests (`shadowlab --self-test NAME[=ARG]`, driven by tests/gui/*.sh under Xvfb):
// params, bad-gltf=FILE[,FILE…], teaching=DIR, charts=DIR, split-resize[=TECHNIQUE],
// omni-probe[=DIR]. They act as a
// user would and check what the renderer and the window did; each check prints "ok   ..." or "FAIL
// ...".
#pragma once

#include <QObject>
#include <QString>

namespace sl::ui {

class MainWindow;

class SelfTests : public QObject {
  Q_OBJECT

 public:
  explicit SelfTests(MainWindow& window);

  /// Runs test `name` once the renderer has drawn a frame: exits 0 (pass) or 1.
  void start(const QString& name, const QString& argument);
  /// True while a self-test drives the window (it then uses Qt's own file dialog).
  bool running() const { return !name_.isEmpty(); }

 private:
  void run();
  bool params();
  /// bad-gltf=FILE[,FILE…]: each broken file opened through File > Open, then dropped on
  /// the window; each time the error is shown (elided) and the scene stays.
  bool badGltf(const QString& paths);
  void badGltfOpen(const QString& path, bool drop);
  /// Pass stepping, overlays, split view and lessons; PNGs of each step into `dir`.
  bool teaching(const QString& dir);
  /// A tiny Charts sweep, its PNG into `dir`, and a click on a point switching the view.
  bool charts(const QString& dir);
  /// Part of charts(): x: memory and back through the combo box (axis, front).
  bool chartsAxis(const QString& dir);
  /// split-resize[=TECHNIQUE]: the split view measures the same errors after the window
  /// was shrunk to 3x3 and restored.
  bool splitResize(const QString& splitTechnique);
  /// omni-probe[=DIR]: the mouse over the view (no button) puts the Omni map's marker on the
  /// face or hemisphere and uv algo/omni computes for that pixel's direction from the light;
  /// leaving the view removes it. PNG of the window into `dir`.
  bool omniProbe(const QString& dir);
  void check(bool ok, const QString& what);

  MainWindow& w_;
  QString name_, argument_;
  int failures_ = 0;
};

}  // namespace sl::ui
