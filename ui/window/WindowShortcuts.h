// The window's keyboard and mouse controls in one table, and the keys held to fly, taken
// wherever the focus is in the window. Commands are the window's QActions (their shortcuts
// declared where each action is made, Qt's shortcut map delivering them from any widget);
// the view's own controls are declared here. A text or number field being typed into keeps
// its keys: Qt gives an editor its printable keys, Space and arrows before any shortcut, and
// the fly keys go to it too.
#pragma once

#include <span>

#include <QList>
#include <QObject>
#include <QPointer>
#include <QString>

class QAction;
class QWidget;

namespace sl::ui {

class ViewportWidget;

class WindowShortcuts : public QObject {
  Q_OBJECT

 public:
  /// A control of the view, or of the panels' image views and plots.
  struct Control {
    const char* input;  ///< what the user does: "W", "Left drag"
    const char* what;   ///< what it does
    int flyKey = 0;     ///< the Qt::Key flown with while held (0: not a fly key)
  };
  /// The view's controls (mouse, fly keys) and the panels' (PanelKit's ImageView, PlotWidget).
  static std::span<const Control> viewControls();
  static std::span<const Control> panelControls();
  /// Whether `key` is one of viewControls()' fly keys.
  static bool isFlyKey(int key);

  /// A row of the table: the keys and what they do.
  struct Row {
    QString keys;
    QString what;
  };
  /// Every command shortcut: of `first` in their order, then of every other action of
  /// `window` (its menus, its own actions, its docks' toggles; none when null).
  static QList<Row> commandRows(QWidget* window, const QList<QAction*>& first = {});
  /// Whether `focus` is a field a user types into (line edit, spin box, editable combo box or
  /// text): it keeps the keys that type.
  static bool typesText(const QWidget* focus);

  /// Takes the fly keys for `view` wherever the focus is in `window` (an application event
  /// filter); a child of `window`.
  WindowShortcuts(QWidget& window, ViewportWidget& view);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  /// Whether `widget` belongs to the window (also inside a floating dock of it).
  bool inWindow(const QWidget* widget) const;

  QWidget& window_;
  /// Null once the view is gone (the window deletes it before its own teardown, which still
  /// deactivates the window).
  QPointer<ViewportWidget> view_;
};

}  // namespace sl::ui
