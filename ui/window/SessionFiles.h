// Sessions (issue 15): File > Save session… / Open session… / Recent sessions. A session is
// a preset (core/Preset: scene, technique, every parameter, camera, light, the split view's
// compare technique with its own parameters, the layout), so it opens as a lesson does
// (LessonController::start) and `shadowlab --lesson FILE` / `--open-session FILE` open one.
#pragma once

#include <QFileDialog>
#include <QObject>
#include <QString>
#include <QStringList>

#include "core/Preset.h"

class QAction;
class QMenu;

namespace sl::ui {

class MainWindow;

class SessionFiles : public QObject {
  Q_OBJECT

 public:
  /// At most this many recent sessions (QSettings "sessions/recent" when interactive).
  static constexpr int kMaxRecent = 8;

  explicit SessionFiles(MainWindow& window);

  /// Adds Save session…, Open session… and the Recent sessions submenu to `file`.
  void createMenu(QMenu* file);

  /// The window's state as a preset (title: the file's base name).
  sl::Preset current(const QString& path) const;
  /// Writes current(path) to `path`; false (reported, naming the file) on failure.
  bool save(const QString& path);
  /// Opens a session through the lesson path; false (reported) when it cannot be read, and
  /// then nothing of the current state changes.
  bool open(const QString& path);
  /// Applies a session's layout (visible docks, the dock state); problems appended.
  void applyLayout(const sl::PresetLayout& layout, QStringList* problems);

  /// Most recent first; files that no longer exist are dropped (and reported).
  QStringList recent();
  QMenu* recentMenu() const { return recentMenu_; }
  QAction* saveAction() const { return saveAction_; }  ///< File > Save session…
  QAction* openAction() const { return openAction_; }  ///< File > Open session…

 private:
  /// applyLayout's docks: the state or the listed docks, the large one sized.
  void applyLayoutDocks(const sl::PresetLayout& layout, QStringList* problems);
  QFileDialog::Options dialogOptions() const;
  void remember(const QString& path);
  void storeRecent();
  void fillRecentMenu();

  MainWindow& w_;
  QStringList recent_;
  QMenu* recentMenu_ = nullptr;
  QAction* saveAction_ = nullptr;
  QAction* openAction_ = nullptr;
};

}  // namespace sl::ui
