// The Help window (F1): the controls of the view and the panels and every command shortcut,
// listed from WindowShortcuts' table (the commands read from the actions themselves, so the
// list cannot drift from the menus).
#pragma once

#include <QDialog>
#include <QList>

class QAction;

namespace sl::ui {

class ShortcutsDialog : public QDialog {
  Q_OBJECT

 public:
  /// `actions` first, then every other action of `parent`'s window with a shortcut.
  ShortcutsDialog(const QList<QAction*>& actions, QWidget* parent = nullptr);
};

}  // namespace sl::ui
