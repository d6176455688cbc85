// The Help window (F1): mouse and keyboard controls of the viewport, and every menu
// shortcut, read from the actions themselves so the list cannot drift from the menus.
#pragma once

#include <QDialog>
#include <QList>

class QAction;

namespace sl::ui {

class ShortcutsDialog : public QDialog {
  Q_OBJECT

 public:
  ShortcutsDialog(const QList<QAction*>& actions, QWidget* parent = nullptr);
};

}  // namespace sl::ui
