// The window's controls and the fly keys from anywhere (see WindowShortcuts.h).
#include "window/WindowShortcuts.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QKeyEvent>
#include <QLineEdit>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QPlainTextEdit>
#include <QTextEdit>

#include "view/ViewportWidget.h"

namespace sl::ui {

namespace {
// The view's controls (ViewportWidget's mouse and wheel handlers, algo/CameraNavigation's
// rates; the fly keys here, taken anywhere in the window).
constexpr WindowShortcuts::Control kViewControls[] = {
    {"Left drag", "Orbit around the target (the same turn per view height at any window size)"},
    {"Right drag / middle drag / Shift+left drag",
     "Pan (the point under the cursor, at the target's depth, follows it)"},
    {"Ctrl+left drag", "Look around in place (across the view's height: its field of view)"},
    {"Wheel", "Dolly: a share of the distance to the target per notch, never through it"},
    {"W", "Fly forward (at a share of the scene's size per second)", Qt::Key_W},
    {"S", "Fly back", Qt::Key_S},
    {"A", "Fly left", Qt::Key_A},
    {"D", "Fly right", Qt::Key_D},
    {"Q", "Fly down", Qt::Key_Q},
    {"E", "Fly up", Qt::Key_E},
    {"Shift (held)", "Fly four times faster"},
    {"Left drag / wheel in the outside view (V)",
     "Orbit / move the third camera; the main camera stays"},
    {"Alt+left drag", "Move the light"},
    {"Ctrl+Shift+drag / click", "Zoom inset of an area / off"},
    {"Drop a .gltf / .glb file", "Open it"},
};

// The image views and plots of the debug panels (PanelKit.h: ImageView, PlotWidget).
constexpr WindowShortcuts::Control kPanelControls[] = {
    {"Wheel over an image", "Zoom around the cursor"},
    {"Drag an image", "Pan"},
    {"Double-click an image", "Fit it to the panel"},
    {"Hover an image / a plot", "Value under the cursor / every curve at that x"},
    {"Right-click a panel", "Save it as a PNG"},
};

void addMenuActions(const QMenu& menu, QList<QAction*>& into) {
  for (QAction* a : menu.actions()) {
    if (a->menu()) addMenuActions(*a->menu(), into);
    if (!into.contains(a)) into << a;
  }
}
}  // namespace

std::span<const WindowShortcuts::Control> WindowShortcuts::viewControls() {
  return kViewControls;
}

std::span<const WindowShortcuts::Control> WindowShortcuts::panelControls() {
  return kPanelControls;
}

bool WindowShortcuts::isFlyKey(int key) {
  for (const Control& c : kViewControls)
    if (c.flyKey != 0 && c.flyKey == key) return true;
  return false;
}

QList<WindowShortcuts::Row> WindowShortcuts::commandRows(QWidget* window,
                                                         const QList<QAction*>& first) {
  QList<QAction*> actions = first;
  if (auto* main = qobject_cast<QMainWindow*>(window))
    for (QAction* a : main->menuBar()->actions())
      if (a->menu()) addMenuActions(*a->menu(), actions);
  if (window) {
    for (QAction* a : window->actions())
      if (!actions.contains(a)) actions << a;
    for (QAction* a : window->findChildren<QAction*>())
      if (!actions.contains(a)) actions << a;
  }
  QList<Row> rows;
  for (const QAction* a : actions) {
    if (a->shortcut().isEmpty()) continue;
    rows << Row{a->shortcut().toString(QKeySequence::NativeText),
                a->text().remove(QLatin1Char('&')).remove(QStringLiteral("…"))};
  }
  return rows;
}

bool WindowShortcuts::typesText(const QWidget* focus) {
  for (const QWidget* w = focus; w; w = w->parentWidget()) {
    if (auto* edit = qobject_cast<const QLineEdit*>(w)) return !edit->isReadOnly();
    if (qobject_cast<const QAbstractSpinBox*>(w)) return true;
    if (auto* combo = qobject_cast<const QComboBox*>(w)) return combo->isEditable();
    if (auto* text = qobject_cast<const QTextEdit*>(w)) return !text->isReadOnly();
    if (auto* text = qobject_cast<const QPlainTextEdit*>(w)) return !text->isReadOnly();
    if (w->isWindow()) break;
  }
  return false;
}

WindowShortcuts::WindowShortcuts(QWidget& window, ViewportWidget& view)
    : QObject(&window), window_(window), view_(&view) {
  qApp->installEventFilter(this);
}

bool WindowShortcuts::inWindow(const QWidget* widget) const {
  for (const QWidget* w = widget; w; w = w->parentWidget()) {
    if (w == &window_) return true;
    // A dialog of the window is not the window; a floating dock is.
    if (w->isWindow() && !qobject_cast<const QDockWidget*>(w)) return false;
  }
  return false;
}

bool WindowShortcuts::eventFilter(QObject* watched, QEvent* event) {
  const QEvent::Type type = event->type();
  if (!view_) return false;
  if (type == QEvent::WindowDeactivate && watched == &window_) {
    view_->camera()->stopFlying();  // its key releases go elsewhere now
    return false;
  }
  if (type != QEvent::KeyPress && type != QEvent::KeyRelease) return false;
  // The widget it is delivered to (not the QWindow passing it on, which sees it first).
  auto* widget = qobject_cast<QWidget*>(watched);
  auto* key = static_cast<QKeyEvent*>(event);
  if (!widget || !isFlyKey(key->key()) || !inWindow(widget)) return false;
  const bool typing = typesText(QApplication::focusWidget());
  if (type == QEvent::KeyRelease) {
    // Wherever the focus went while the key was held, its release stops it.
    view_->camera()->flyKeyReleased(key->key(), key->isAutoRepeat());
    return !typing;
  }
  constexpr Qt::KeyboardModifiers kNotFlying =
      Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier;
  if (typing || (key->modifiers() & kNotFlying) || !view_->isVisible()) return false;
  view_->camera()->flyKeyPressed(key->key(), key->isAutoRepeat());
  return true;
}

}  // namespace sl::ui
