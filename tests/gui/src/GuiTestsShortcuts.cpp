// shortcuts (GuiTests.h): the window's keys act whatever widget of the window has the focus —
// a slider of the Parameters panel, the Timing panel's tree, the lesson text — and a spin box
// being typed into keeps its keys. Keys go through Qt's own path (QTest: the shortcut
// override, the shortcut map, then the focus widget), as a keyboard's would.
#include <cmath>
#include <numbers>

#include <QAbstractItemView>
#include <QAction>
#include <QComboBox>
#include <QLineEdit>
#include <QMouseEvent>
#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QSlider>
#include <QSpinBox>
#include <QTest>
#include <QTextBrowser>
#include <QWheelEvent>

#include "GuiTests.h"
#include "window/MainWindow.h"
#include "teaching/PassStepper.h"
#include "view/ViewportWidget.h"
#include "window/WindowShortcuts.h"
#include "panels/common/ParamPanel.h"

namespace sl::ui {

namespace {
/// Lets the event loop run for `ms` (the fly timer ticks, frames render).
void spin(int ms) {
  QElapsedTimer clock;
  clock.start();
  while (clock.elapsed() < ms) QApplication::processEvents(QEventLoop::AllEvents, 20);
}

QString describe(const QWidget* w) {
  if (!w) return QStringLiteral("(no widget)");
  return QStringLiteral("%1 '%2'").arg(QString::fromLatin1(w->metaObject()->className()),
                                       w->objectName());
}

/// A visible widget of type T inside `root` that accepts the focus (not inside the view).
template <typename T>
T* focusable(QWidget* root) {
  for (T* w : root->findChildren<T*>())
    if (w->isVisible() && w->isEnabled() && w->focusPolicy() != Qt::NoFocus) return w;
  return nullptr;
}
}  // namespace

bool GuiTests::shortcuts() {
  ViewportWidget* view = w_.viewport();
  sl::ViewSide* renderer = view->mainSide();
  if (!renderer) {
    check(false, tr("no renderer"));
    return false;
  }
  w_.activateWindow();
  w_.raise();
  for (int i = 0; i < 100 && !w_.isActiveWindow(); ++i) spin(20);
  check(w_.isActiveWindow(), tr("the main window is active"));

  // Widgets a user may have clicked last: none of them types text.
  QWidget* slider = focusable<QSlider>(w_.paramPanel());
  QWidget* tree = nullptr;
  for (QDockWidget* dock : w_.findChildren<QDockWidget*>())
    if (dock->isVisible())
      if (auto* v = focusable<QAbstractItemView>(dock)) {
        tree = v;
        break;
      }
  QWidget* spinBox = focusable<QAbstractSpinBox>(w_.paramPanel());
  check(slider && tree && spinBox, tr("a slider (%1), a dock's list or tree (%2), a spin box (%3)")
                                       .arg(describe(slider), describe(tree), describe(spinBox)));
  if (!slider || !tree || !spinBox) return false;

  auto focusOn = [&](QWidget* w) {
    w->setFocus(Qt::OtherFocusReason);
    spin(30);
    return QApplication::focusWidget() == w;
  };
  auto key = [](Qt::Key k, Qt::KeyboardModifiers mods = Qt::NoModifier) {
    QTest::keyClick(QApplication::focusWidget(), k, mods);
    spin(60);
  };
  auto overlay = [renderer] { return renderer->rendererParams().getInt("view.overlay"); };
  /// Holds `k` for `ms` and returns how far the camera moved (metres).
  auto hold = [&](Qt::Key k, int ms) {
    const sl::Camera before = view->camera()->camera();
    QTest::keyPress(QApplication::focusWidget(), k);
    spin(ms);
    QTest::keyRelease(QApplication::focusWidget(), k);
    spin(40);
    return glm::length(view->camera()->camera().position - before.position);
  };

  for (QWidget* w : {slider, tree}) {
    const QString where = describe(w);
    check(focusOn(w), tr("%1 has the focus").arg(where));
    const bool outside = view->camera()->outsideView();
    key(Qt::Key_V);
    check(view->camera()->outsideView() != outside,
          tr("V from %1 toggles the outside view").arg(where));
    key(Qt::Key_V);
    check(view->camera()->outsideView() == outside, tr("V again turns it back"));

    const bool continuous = view->frames()->continuous();
    key(Qt::Key_F6);
    check(view->frames()->continuous() != continuous,
          tr("F6 from %1 toggles continuous rendering").arg(where));
    key(Qt::Key_F6);
    check(view->frames()->continuous() == continuous, tr("F6 again turns it back"));

    const bool paused = view->frames()->paused();
    key(Qt::Key_Space);
    check(view->frames()->paused() != paused, tr("Space from %1 toggles pause").arg(where));
    key(Qt::Key_Space);
    check(view->frames()->paused() == paused, tr("Space again resumes"));

    const int overlayBefore = overlay();
    key(Qt::Key_O);
    check(overlay() != overlayBefore, tr("O from %1 changes the overlay (%2 -> %3)")
                                          .arg(where)
                                          .arg(overlayBefore)
                                          .arg(overlay()));
    (void)renderer->rendererParams().set("view.overlay", overlayBefore);

    const double movedM = hold(Qt::Key_W, 400);
    check(movedM > 1e-3, tr("W held 0.4 s from %1 flies the camera %2 m").arg(where).arg(movedM));
    check(QApplication::focusWidget() == w, tr("%1 keeps the focus").arg(where));
  }

  // One widget of each kind the window holds (combo boxes, buttons, tab bars, the lesson
  // text, ...), text fields aside: V and Space act from each.
  QStringList kinds;
  for (QWidget* w : w_.findChildren<QWidget*>()) {
    const QString kind = QString::fromLatin1(w->metaObject()->className());
    if (!w->isVisible() || !w->isEnabled() || w->focusPolicy() == Qt::NoFocus ||
        kinds.contains(kind) || w == view || view->isAncestorOf(w) ||
        qobject_cast<QAbstractSpinBox*>(w) || qobject_cast<QLineEdit*>(w) ||
        (qobject_cast<QComboBox*>(w) && static_cast<QComboBox*>(w)->isEditable()))
      continue;
    if (!focusOn(w)) continue;  // a container that passes the focus on
    kinds << kind;
    const bool outside = view->camera()->outsideView();
    const bool paused = view->frames()->paused();
    key(Qt::Key_V);
    key(Qt::Key_Space);
    check(view->camera()->outsideView() != outside && view->frames()->paused() != paused,
          tr("V and Space from %1 act").arg(describe(w)));
    if (QApplication::focusWidget() == w) {
      key(Qt::Key_V);
      key(Qt::Key_Space);
    }
    (void)view->camera()->setOutsideView(outside);
    auto_.setPaused(paused);
  }

  // A floating dock is a window of its own: its tree still drives the view.
  QDockWidget* treeDock = nullptr;
  for (QWidget* p = tree; p && !treeDock; p = p->parentWidget())
    treeDock = qobject_cast<QDockWidget*>(p);
  if (QDockWidget* dock = treeDock) {
    dock->setFloating(true);
    dock->activateWindow();
    for (int i = 0; i < 50 && !dock->isActiveWindow(); ++i) spin(20);
    if (focusOn(tree)) {
      const bool outside = view->camera()->outsideView();
      const bool paused = view->frames()->paused();
      key(Qt::Key_V);
      key(Qt::Key_Space);
      check(view->camera()->outsideView() != outside && view->frames()->paused() != paused,
            tr("V and Space from the tree of the floating dock '%1' act").arg(dock->windowTitle()));
      (void)view->camera()->setOutsideView(outside);
      auto_.setPaused(paused);
      const double movedM = hold(Qt::Key_W, 300);
      check(movedM > 1e-3, tr("W held from the floating dock flies %1 m").arg(movedM));
    } else {
      check(false, tr("the floating dock's tree takes the focus"));
    }
    dock->setFloating(false);
    w_.activateWindow();
    for (int i = 0; i < 50 && !w_.isActiveWindow(); ++i) spin(20);
  }

  // Typing into a number field: its keys stay its own.
  check(focusOn(spinBox), tr("%1 has the focus").arg(describe(spinBox)));
  const bool outside = view->camera()->outsideView();
  const bool paused = view->frames()->paused();
  key(Qt::Key_V);
  key(Qt::Key_Space);
  check(view->camera()->outsideView() == outside && view->frames()->paused() == paused,
        tr("V and Space typed into %1 neither toggle the outside view nor pause")
            .arg(describe(spinBox)));
  const double typedM = hold(Qt::Key_W, 300);
  check(typedM == 0.0, tr("W typed into the spin box moves the camera %1 m").arg(typedM));
  const bool continuous = view->frames()->continuous();
  key(Qt::Key_F6);
  check(view->frames()->continuous() != continuous,
        tr("F6 (no text) still acts from the spin box"));
  key(Qt::Key_F6);

  // Frame and pass stepping from the tree: "." renders one frame and pauses, "]" steps
  // through the frame's passes, Esc stops.
  check(focusOn(tree), tr("the tree has the focus again"));
  const std::uint64_t frames = view->frames()->framesRendered();
  key(Qt::Key_Period);
  for (int i = 0; i < 100 && view->frames()->framesRendered() == frames; ++i) spin(20);
  check(view->frames()->paused() && view->frames()->framesRendered() > frames,
        tr(". from the tree renders a frame (%1 -> %2) and pauses")
            .arg(frames)
            .arg(view->frames()->framesRendered()));
  key(Qt::Key_BracketRight);
  check(w_.passes()->active(), tr("] from the tree steps through the passes"));
  if (QApplication::focusWidget() != tree) focusOn(tree);
  key(Qt::Key_Escape);
  check(!w_.passes()->active(), tr("Esc from the tree stops stepping"));
  auto_.setPaused(false);

  // The view's rates (algo/CameraNavigation) through its own handlers: a drag across the
  // view's height orbits half a turn whatever the view's size (about half of it here: whole
  // pixels), a wheel notch moves 15 % of the distance to the target.
  (void)view->camera()->setOutsideView(false);
  const sl::Camera beforeDrag = view->camera()->camera();
  const int h = view->height();
  const int dxPx = h / 2;
  const QPointF from(view->width() / 4, h / 2), to = from + QPointF(dxPx, 0);
  auto mouse = [view](QEvent::Type type, QPointF at, Qt::MouseButton button,
                      Qt::MouseButtons buttons) {
    QMouseEvent e(type, at, view->mapToGlobal(at), button, buttons, Qt::NoModifier);
    QApplication::sendEvent(view, &e);
  };
  mouse(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
  mouse(QEvent::MouseMove, to, Qt::NoButton, Qt::LeftButton);
  mouse(QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
  const glm::vec3 a = beforeDrag.position - beforeDrag.target,
                  b = view->camera()->camera().position - view->camera()->camera().target;
  const double turnDeg = glm::degrees(std::abs(
      std::remainder(std::atan2(double(b.x), double(b.z)) - std::atan2(double(a.x), double(a.z)),
                     2.0 * std::numbers::pi)));
  const double expectedDeg = 180.0 * dxPx / h;
  check(std::abs(turnDeg - expectedDeg) < 0.01 && std::abs(glm::length(b) - glm::length(a)) < 1e-3f,
        tr("a drag of %1 px in a %2 px high view orbits %3° (%4°)")
            .arg(dxPx)
            .arg(h)
            .arg(turnDeg)
            .arg(expectedDeg));
  const float distanceBefore =
      glm::length(view->camera()->camera().position - view->camera()->camera().target);
  const QPointF centre(view->width() / 2.0, h / 2.0);
  QWheelEvent wheel(centre, view->mapToGlobal(centre), QPoint(), QPoint(0, 120), Qt::NoButton,
                    Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(view, &wheel);
  const float ratio =
      glm::length(view->camera()->camera().position - view->camera()->camera().target) /
      distanceBefore;
  check(std::abs(ratio - 0.85f) < 1e-4f,
        tr("a wheel notch towards the target: distance x %1 (0.85)").arg(ratio));

  // One table: the Help window (F1) lists the view's fly keys and every command, and no two
  // commands share a key (Qt would then run neither).
  const QList<WindowShortcuts::Row> rows = WindowShortcuts::commandRows(&w_);
  QStringList keys, shared;
  for (const WindowShortcuts::Row& r : rows) {
    if (keys.contains(r.keys)) shared << r.keys;
    keys << r.keys;
  }
  check(rows.size() >= 20 && shared.isEmpty(), tr("%1 command shortcuts, none shared (%2)")
                                                   .arg(rows.size())
                                                   .arg(shared.join(QStringLiteral(", "))));
  check(focusOn(tree), tr("the tree has the focus again"));
  key(Qt::Key_F1);
  QTextBrowser* help = nullptr;
  for (QTextBrowser* t : w_.findChildren<QTextBrowser*>())
    if (t->isVisible() && t->window() != &w_) help = t;
  const QString helpText = help ? help->toPlainText() : QString();
  bool listsAll = helpText.contains(QStringLiteral("Fly forward"));
  for (const WindowShortcuts::Row& r : rows) listsAll = listsAll && helpText.contains(r.what);
  check(help && listsAll, tr("F1 from the tree opens the Help window listing the fly keys and "
                             "every command (%1 characters)")
                              .arg(helpText.size()));
  if (help) help->window()->close();
  return true;
}

}  // namespace sl::ui
