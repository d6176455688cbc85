// Presenter mode (see PresenterMode.h).
#include "teaching/PresenterMode.h"

#include <algorithm>

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDockWidget>
#include <QLayout>
#include <QMenu>
#include <QScreen>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>

#include "panels/common/PanelKit.h"
#include "teaching/LessonController.h"
#include "window/MainWindow.h"
#include "window/Theme.h"
#include "view/ViewportWidget.h"
#include "core/Renderer.h"

namespace sl::ui {

namespace {
constexpr int kStateVersion = 0x5e55;  ///< saveState/restoreState tag of the saved layout

/// Lays `window` out now, its minimum size measured from every widget's current minimum: a
/// plot's or image's new minimum climbs one layout per posted LayoutRequest, so they are sent
/// until none is left (a few levels: panel, dock, window).
void layOutNow(QWidget& window) {
  for (int level = 0; level < 8; ++level)
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
  window.layout()->activate();
}
}  // namespace

PresenterMode::PresenterMode(MainWindow& window) : QObject(&window), w_(window) {
  w_.installEventFilter(this);
}

bool PresenterMode::eventFilter(QObject* watched, QEvent* event) {
  // The big panel's readable content (filled, its captions wrapped to its width) made the
  // window taller than its screen: it gives that up (after the events that grew it).
  if (watched == &w_ && event->type() == QEvent::Resize && active_ && !fullPanel_ && big_ &&
      !giveUpQueued_) {
    const QScreen* screen = w_.screen() ? w_.screen() : QGuiApplication::primaryScreen();
    if (screen && w_.height() > screen->geometry().height()) {
      giveUpQueued_ = true;
      QTimer::singleShot(0, this, &PresenterMode::giveUpReadable);
    }
  }
  return QObject::eventFilter(watched, event);
}

void PresenterMode::giveUpReadable() {
  giveUpQueued_ = false;
  if (!active_ || fullPanel_ || !big_) return;
  // Taller for a moment (a re-arrangement shows the docks before it fits the screen) is not
  // outgrowing it: fitted to the screen again, only a window still taller gives up.
  const QScreen* screen = w_.screen() ? w_.screen() : QGuiApplication::primaryScreen();
  if (!screen) return;
  resizeView([this] {
    layOutNow(w_);
    fitScreen();
    layOutNow(w_);
  });
  if (w_.height() <= screen->geometry().height()) return;
  // Arranged again with the content as it is now (a panel under the big one that no longer
  // fits goes behind it), a few times per lesson; then the big panel takes what there is.
  if (rearrangedForGrowth_ < kMaxRearrangedForGrowth) {
    ++rearrangedForGrowth_;
    resizeView([this] {
      arrangeDocks();
      fitScreen();
    });
    return;
  }
  resizeView([this] {
    for (QDockWidget* dock : w_.findChildren<QDockWidget*>()) setReadableMinimums(*dock, false);
    layOutNow(w_);
    fitScreen();
  });
}

void PresenterMode::createActions(QMenu* view) {
  // A checkable action of the View menu, also the window's own: the full panel hides the
  // menu's tool bars, the window keeps the shortcut.
  auto toggle = [&](const QString& text, const char* name, Qt::Key key, const QString& tip,
                    void (PresenterMode::*slot)(bool)) {
    QAction* a = view->addAction(text);
    a->setObjectName(QString::fromLatin1(name));
    a->setCheckable(true);
    a->setShortcut(key);
    a->setShortcutContext(Qt::ApplicationShortcut);
    a->setToolTip(tip);
    connect(a, &QAction::toggled, this, slot);
    w_.addAction(a);
    return a;
  };
  action_ = toggle(
      tr("&Presenter mode (large fonts, high contrast, one big panel)"), "presenterAction",
      Qt::Key_F11,
      tr("For a projector: fonts scaled to the screen, white on black, the window filling the "
         "screen, one panel beside the view as large as it fits, a ring around the pointer "
         "(F11)"),
      &PresenterMode::setActive);
  fullPanelAction_ =
      toggle(tr("Big panel &full screen (presenter mode)"), "fullPanelAction", Qt::Key_F12,
             tr("Presenter mode's big panel over the whole screen, the view hidden; again to bring "
                "the view back beside it (F12)"),
             &PresenterMode::setFullPanel);
  panelMenu_ = view->addMenu(tr("Presenter &panel"));
  panelMenu_->setObjectName(QStringLiteral("presenterPanelMenu"));
  connect(panelMenu_, &QMenu::aboutToShow, this, [this] {
    panelMenu_->clear();
    auto* group = new QActionGroup(panelMenu_);
    auto add = [&](const QString& title, const QString& name) {
      QAction* a = panelMenu_->addAction(title, this, [this, name] { choosePanel(name); });
      a->setCheckable(true);
      a->setChecked(chosen_ == name);
      group->addAction(a);
    };
    add(tr("Automatic (the lesson's, else the first showing this technique)"), QString());
    for (const PublicationDocks::Dock& d : w_.docks().docks())
      add(d.dock->windowTitle(), d.dock->objectName());
  });
}

QDockWidget* PresenterMode::bigDock() const {
  return active_ ? big_.data() : nullptr;
}

void PresenterMode::choosePanel(const QString& dockName) {
  chosen_ = dockName;
  if (active_) arrangeDocks();
}

void PresenterMode::setLessonPanel(const QString& dockName, const QStringList& others) {
  lessonPanel_ = dockName;
  lessonOthers_ = others;
  rearrangedForGrowth_ = 0;
  if (!active_) return;
  arrangeDocks();
  fitScreen();
}

QDockWidget* PresenterMode::pickBigDock() const {
  for (const QString& name : {chosen_, lessonPanel_})
    if (!name.isEmpty())
      if (auto* dock = w_.findChild<QDockWidget*>(name)) return dock;
  const sl::TechniqueInfo* info = sl::Renderer::findTechnique(w_.viewport()->techniqueId());
  if (info)
    if (QDockWidget* dock = w_.docks().firstShowing(*info)) return dock;
  return w_.lessonDock();
}

void PresenterMode::setActive(bool on) {
  if (on == active_) return;
  auto* app = qobject_cast<QApplication*>(QCoreApplication::instance());
  if (on) {
    savedState_ = w_.saveState(kStateVersion);
    savedGeometry_ = w_.saveGeometry();
    savedMaximized_ = w_.isMaximized();
    savedFont_ = QApplication::font();
    const QScreen* screen = w_.screen() ? w_.screen() : QGuiApplication::primaryScreen();
    const double dpi = screen ? screen->logicalDotsPerInch() : 96.0;
    const int px = presenterBodyPixelSize(screen ? screen->size() : QSize(1920, 1080), dpi);
    if (app) applyPresenterTheme(*app, px, dpi);
    active_ = true;
    w_.rebuildParamPanel();  // its titles scale the font they were built with
    // The docks first: with every dock shown at the large font the window's minimum may be
    // larger than the screen. Then the screen's geometry (a window manager-less X server,
    // e.g. Xvfb, ignores the full-screen request), full screen, the big panel's width.
    arrangeDocks();
    fitScreen();
    w_.viewport()->painter()->setPointerHighlight(true);
    w_.viewport()->frames()->setPresenting(true);  // full-size frames only: numbers a class reads
  } else {
    setFullPanel(false);
    active_ = false;
    for (QDockWidget* dock : w_.findChildren<QDockWidget*>()) setReadableMinimums(*dock, false);
    w_.viewport()->painter()->setPointerHighlight(false);
    w_.viewport()->frames()->setPresenting(false);
    if (app) {
      applyTheme(*app);
      QApplication::setFont(savedFont_);
    }
    w_.showNormal();
    w_.restoreGeometry(savedGeometry_);
    w_.restoreState(savedState_, kStateVersion);
    w_.rebuildParamPanel();
    if (savedMaximized_) w_.showMaximized();
    big_.clear();
  }
  if (action_ && action_->isChecked() != on) action_->setChecked(on);
  w_.updatePublishing();
  w_.viewport()->frames()->requestFrame();
}

void PresenterMode::setFullPanel(bool on) {
  if (on && !active_) setActive(true);
  if (on == fullPanel_) {
    if (fullPanelAction_ && fullPanelAction_->isChecked() != on) fullPanelAction_->setChecked(on);
    return;
  }
  fullPanel_ = on;
  if (on) {
    // The view, the tool bars and the status line go; the big panel takes the window (a
    // main window without a visible central widget gives its dock areas all the room).
    hiddenForPanel_.clear();
    for (QToolBar* bar : w_.findChildren<QToolBar*>(Qt::FindDirectChildrenOnly))
      if (bar->isVisible()) hiddenForPanel_.push_back(bar);
    if (w_.statusBar()->isVisible()) hiddenForPanel_.push_back(w_.statusBar());
    for (QWidget* widget : hiddenForPanel_) widget->hide();
    w_.viewport()->hide();
  } else {
    w_.viewport()->show();
    for (QWidget* widget : hiddenForPanel_)
      if (widget) widget->show();
    hiddenForPanel_.clear();
  }
  arrangeDocks();
  if (fullPanelAction_ && fullPanelAction_->isChecked() != on) fullPanelAction_->setChecked(on);
  w_.viewport()->frames()->requestFrame();
}

void PresenterMode::arrangeDocks() {
  keptOnScreen_ = 0;
  fedSinceArranged_ = 0;
  askedSettled_ = false;
  panelShare_ = kPanelShare;
  big_ = pickBigDock();
  // Everything but the big panel hidden; the Lesson and Parameters tabbed behind it (a
  // lecturer's notes and knobs, one click away).
  // The plots and images of the panels in view ask for their readable size (PlotWidget::
  // kReadableHeight, ImageView::kReadableSide, with their titles and captions): a panel is
  // shown under the big one only where it reads there, and the big panel gives that up only
  // where it cannot have it (askReadable). Panels tabbed behind ask for nothing.
  for (QDockWidget* dock : w_.findChildren<QDockWidget*>()) {
    dock->setFloating(false);
    setReadableMinimums(*dock, false);
    if (dock != big_) dock->hide();
  }
  if (!big_) return;
  w_.addDockWidget(Qt::RightDockWidgetArea, big_);
  setReadableMinimums(*big_, true);  // first: a panel goes under it only where both read
  big_->show();
  // The lesson's other panels under the big one (the lesson's own big panel only: a panel
  // the user chose stands alone); split before anything is tabbed behind it (Qt adds a dock
  // split off a tabbed one as one more tab).
  QList<QDockWidget*> column{big_};
  // The lesson's strip (its few parameters) at the bottom of the column, on every screen:
  // first, so that the panels below the big one are only added where they still fit with it.
  QDockWidget* strip = fullPanel_ ? nullptr : w_.lessons()->stripDock();
  if (strip == big_) strip = nullptr;
  if (strip) {
    w_.addDockWidget(Qt::RightDockWidgetArea, strip);
    w_.splitDockWidget(big_, strip, Qt::Vertical);
    strip->show();
  }
  const QScreen* screen = w_.screen() ? w_.screen() : QGuiApplication::primaryScreen();
  const int screenHeight = screen ? screen->geometry().height() : 0;
  int belowHeight = strip ? strip->sizeHint().height() : 0;  // what stands under the big panel
  if (!fullPanel_ && chosen_.isEmpty() && big_->objectName() == lessonPanel_ &&
      screenHeight >= kMinScreenHeightForPanelsBelow)
    for (const QString& name : lessonOthers_) {
      QDockWidget* dock = w_.findChild<QDockWidget*>(name);
      if (!dock || dock == big_ || dock == strip || dock == w_.lessonDock() ||
          dock == w_.paramDock() || column.size() > kMaxPanelsBelow)
        continue;
      w_.addDockWidget(Qt::RightDockWidgetArea, dock);
      w_.splitDockWidget(column.back(), dock, Qt::Vertical);  // above the strip
      setReadableMinimums(*dock, true);
      dock->show();
      layOutNow(w_);
      // Only where the window still fits the screen and the big panel keeps its share of the
      // height (what stands under it, at its least, takes the rest); else one more tab behind
      // the big panel.
      const int under = belowHeight + dock->minimumSizeHint().height();
      if (screenHeight > 0 && (w_.minimumSizeHint().height() > screenHeight ||
                               under > screenHeight * (1.0 - kMinBigPanelShare))) {
        setReadableMinimums(*dock, false);
        w_.tabifyDockWidget(big_, dock);
        continue;
      }
      belowHeight = under;
      column << dock;
    }
  for (QDockWidget* behind : {w_.lessonDock(), w_.paramDock()}) {
    if (!behind || behind == big_ || fullPanel_) continue;
    w_.addDockWidget(Qt::RightDockWidgetArea, behind);
    w_.tabifyDockWidget(big_, behind);
    behind->show();
  }
  big_->raise();
  // The big panel keeps its share of the height; the strip, as tall as its rows, comes out of
  // what the panels under it share.
  const int stripHeight = strip ? strip->sizeHint().height() : 0;
  const int bigHeight =
      column.size() > 1 ? int(w_.height() * kMinBigPanelShare) : w_.height() - stripHeight;
  QList<int> heights{bigHeight};
  for (int i = 1; i < column.size(); ++i)
    heights << (w_.height() - bigHeight - stripHeight) / int(column.size() - 1);
  if (strip) {
    column << strip;
    heights << stripHeight;
  }
  if (column.size() > 1) w_.resizeDocks(column, heights, Qt::Vertical);
  w_.layout()->invalidate();
  layOutNow(w_);
  sizeBigDock();
  askReadable();
}

void PresenterMode::askReadableSettled() {
  if (!active_ || fullPanel_ || !big_ || askedSettled_ || asksReadableMinimum(*big_->widget()))
    return;
  askedSettled_ = true;
  bool readable = false;
  resizeView([this, &readable] { readable = askReadable(); });
  // Given up again: the window was laid out at the readable size for a moment, and a frame
  // may have been asked for at that size; the lesson's state starts again at this one.
  if (!readable) w_.lessons()->settleAgain();
}

bool PresenterMode::askReadable() {
  // At its share of the width (titles and captions wrap to it), widened step by step up to
  // kMaxPanelShare while that does not fit: where the big panel at its readable size makes
  // the window taller (or wider) than the screen even then, it takes what there is at its
  // first share, and the lesson says it is too small to read (LessonController::reportFit).
  if (!big_) return false;
  setReadableMinimums(*big_, true);
  layOutNow(w_);
  const QScreen* screen = w_.screen() ? w_.screen() : QGuiApplication::primaryScreen();
  const QSize screenSize = screen ? screen->geometry().size() : QSize();
  const auto fits = [&] {
    const QSize least = w_.minimumSizeHint();
    return least.height() <= screenSize.height() && least.width() <= screenSize.width();
  };
  if (screenSize.isEmpty() || fits()) return true;
  if (!fullPanel_)
    while (panelShare_ + kPanelShareStep <= kMaxPanelShare + 1e-9) {
      panelShare_ += kPanelShareStep;
      sizeBigDock();
      layOutNow(w_);  // the panel laid out again at its new width (its rows, its columns)
      layOutNow(w_);
      if (fits()) return true;
    }
  panelShare_ = kPanelShare;
  setReadableMinimums(*big_, false);
  layOutNow(w_);
  sizeBigDock();
  if (w_.height() > screenSize.height() || w_.width() > screenSize.width()) fitScreen();
  return false;
}

void PresenterMode::keepOnScreen() {
  if (!active_ || fullPanel_) return;
  layOutNow(w_);  // the panels' new content measured: what the checks below read
  if (big_ && fedSinceArranged_ < kFeedsResized) {
    ++fedSinceArranged_;
    if (big_->width() > int(w_.width() * panelShare_) + 1) resizeView([this] { sizeBigDock(); });
  }
  const QScreen* screen = w_.screen() ? w_.screen() : QGuiApplication::primaryScreen();
  if (!screen) return;
  const int screenHeight = screen->geometry().height();
  if (w_.frameGeometry().height() <= screenHeight && w_.minimumSizeHint().height() <= screenHeight)
    return;
  // A few times per arrangement at most: a window that cannot fit does not loop.
  const int tries = keptOnScreen_;
  if (tries >= kMaxKeepOnScreen) return;
  resizeView([this] {
    arrangeDocks();
    fitScreen();
  });
  keptOnScreen_ = tries + 1;  // arrangeDocks counted from 0 again
}

void PresenterMode::resizeView(const std::function<void()>& change) {
  const QSize view = w_.viewport()->size();
  change();
  w_.layout()->activate();
  if (w_.viewport()->size() != view)
    w_.lessons()->settleAgain();  // a lesson's rotation settles again at the view's new size
}

void PresenterMode::fitScreen() {
  // A window manager-less X server (Xvfb) ignores the full-screen request: the geometry too.
  const QScreen* screen = w_.screen() ? w_.screen() : QGuiApplication::primaryScreen();
  if (screen) w_.setGeometry(screen->geometry());
  w_.showFullScreen();
  sizeBigDock();
}

void PresenterMode::sizeBigDock() {
  if (!big_) return;
  const double share = fullPanel_ ? 1.0 : panelShare_;
  w_.resizeDocks({big_}, {int(w_.width() * share)}, Qt::Horizontal);
}

}  // namespace sl::ui
