// The presenter-mode and split-parameter self-tests (see GuiTests.h). presenter[=DIR] turns
// presenter mode on
// through its action (F11) when --presenter did not, and checks what a lecturer relies on at
// the screen's size: the window fits, body text is large, one panel's image is large, the
// changed (flicker) overlay draws exactly the pixels the renderer counted, the pointer ring
// and the zoom inset are drawn; colour-bar ticks read as numbers. split-params[=DIR] edits the
// split view's own resolution in its panel and checks "equal memory". PNGs into DIR.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QDockWidget>
#include <QFontInfo>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMouseEvent>
#include <QScreen>
#include <QSpinBox>
#include <QtCharts/QAbstractAxis>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QLegend>

#include "teaching/LessonController.h"
#include "window/MainWindow.h"
#include "teaching/PresenterMode.h"
#include "GuiTests.h"
#include "window/SplitSideParams.h"
#include "teaching/TeachingBar.h"
#include "window/Theme.h"
#include "view/ViewOverlay.h"
#include "view/ViewportWidget.h"
#include "common/shared_constants.h"
#include "panels/common/PanelKit.h"
#include "panels/common/ParamPanel.h"
#include "panels/common/TimingPanel.h"

namespace sl::ui {

namespace {

bool isChangedColour(QRgb c) {
  const float k[3] = {SL_CHANGED_COLOUR};
  return qRed(c) == std::lround(k[0] * 255.0f) && qGreen(c) == std::lround(k[1] * 255.0f) &&
         qBlue(c) == std::lround(k[2] * 255.0f);
}

/// A mouse event sent straight to `target` (widget pixels).
void sendMouse(QWidget* target, QEvent::Type type, const QPoint& at, Qt::MouseButton button,
               Qt::MouseButtons buttons, Qt::KeyboardModifiers mods) {
  QMouseEvent e(type, QPointF(at), target->mapToGlobal(QPointF(at)), button, buttons, mods);
  QCoreApplication::sendEvent(target, &e);
}

/// The largest shown image of `dock`'s image views: its shorter side (widget pixels), and
/// how much of its view it fills in the dimension that limits it (0..1).
struct ShownImage {
  double side = 0.0, fill = 0.0;
};
ShownImage largestImage(QDockWidget* dock) {
  ShownImage out;
  if (!dock) return out;
  for (ImageView* iv : dock->findChildren<ImageView*>())
    if (iv->isVisible() && iv->hasImage()) {
      const QRectF r = iv->shownImageRect();
      out.side = std::max(out.side, std::min(r.width(), r.height()));
      out.fill = std::max(out.fill, std::max(r.width() / iv->width(), r.height() / iv->height()));
    }
  return out;
}

/// The docks shown and not covered (a tabbed dock behind another is not).
int docksInView(const QMainWindow& window) {
  int n = 0;
  for (QDockWidget* d : window.findChildren<QDockWidget*>())
    if (d->isVisible() && !d->visibleRegion().isEmpty()) ++n;
  return n;
}

}  // namespace

bool GuiTests::presenter(const QString& dir) {
  if (!dir.isEmpty()) QDir().mkpath(dir);
  ViewportWidget* v = w_.viewport();
  const bool fromCommandLine = w_.presenter()->active();
  if (!fromCommandLine) w_.presenter()->action()->trigger();  // what F11 does
  check(w_.presenter()->active(),
        tr("presenter mode is on (%1)")
            .arg(fromCommandLine ? QStringLiteral("--presenter")
                                 : QStringLiteral("View > Presenter mode")));
  for (int i = 0; i < 10; ++i) QCoreApplication::processEvents(QEventLoop::AllEvents, 30);
  waitForFrames(3);

  // 1. The window fits the screen.
  const QScreen* screen = w_.screen();
  if (!screen) {
    check(false, tr("the window has a screen"));
    return false;
  }
  const QRect sr = screen->geometry();
  const QRect frame = w_.frameGeometry();
  check(sr.contains(frame) && frame.width() <= sr.width() && frame.height() <= sr.height(),
        tr("the window (%1x%2 at %3,%4, minimum %7x%8) fits the %5x%6 screen")
            .arg(frame.width())
            .arg(frame.height())
            .arg(frame.x())
            .arg(frame.y())
            .arg(sr.width())
            .arg(sr.height())
            .arg(w_.minimumSizeHint().width())
            .arg(w_.minimumSizeHint().height()));
  check(frame.width() >= sr.width() * 9 / 10 && frame.height() >= sr.height() * 9 / 10,
        tr("the window fills the screen (%1x%2)").arg(frame.width()).arg(frame.height()));

  // 2. Body text: at least 22 px at 1920x1080, in proportion on smaller screens.
  const double scale = std::min(sr.width() / 1920.0, sr.height() / 1080.0);
  const int wantedPx = int(std::ceil(22.0 * scale));
  const int appPx = QFontInfo(QApplication::font()).pixelSize();
  const int statusPx = auto_.statusTextPixelSize();
  check(appPx >= wantedPx && statusPx >= wantedPx,
        tr("body text %1 px (status line %2 px) >= %3 px (22 px x %4)")
            .arg(appPx)
            .arg(statusPx)
            .arg(wantedPx)
            .arg(scale, 0, 'f', 3));
  check(QApplication::palette().color(QPalette::Window).lightness() < 30 &&
            QApplication::palette().color(QPalette::WindowText).lightness() > 240,
        tr("high contrast: text lightness %1 on %2")
            .arg(QApplication::palette().color(QPalette::WindowText).lightness())
            .arg(QApplication::palette().color(QPalette::Window).lightness()));

  // 3. One big panel beside the view, its image as large as the space allows (with a lesson
  // that has a strip, the strip under it, in view).
  QDockWidget* big = w_.presenter()->bigDock();
  const int visibleDocks = docksInView(w_);
  const QDockWidget* strip = w_.lessons()->stripDock();
  const bool stripInView = strip && strip->isVisible() && !strip->visibleRegion().isEmpty();
  const bool wantStrip = w_.lessons()->activePreset() && w_.lessons()->activePreset()->layout &&
                         !w_.lessons()->activePreset()->layout->strip.empty();
  check(big && big->isVisible() && visibleDocks == 1 + (stripInView ? 1 : 0) &&
            stripInView == wantStrip,
        tr("one panel shown: %1 (%2 dock(s) in view%3)")
            .arg(big ? big->windowTitle() : QStringLiteral("none"))
            .arg(visibleDocks)
            .arg(stripInView ? tr(": the lesson's strip under it") : QString()));
  // A lesson's telling panel is the big one, however presenter mode came on (--presenter,
  // or F11 after the lesson had laid out its docks).
  const int lessonIndex = w_.lessons()->index();
  const auto& lessonLayout =
      lessonIndex < 0
          ? std::optional<sl::PresetLayout>()
          : w_.lessons()->lessons()[static_cast<std::size_t>(lessonIndex)].preset.layout;
  const std::string lessonLarge = lessonLayout ? lessonLayout->large : std::string();
  if (!lessonLarge.empty())
    check(big && big->objectName().toStdString() == lessonLarge,
          tr("the big panel is the lesson's: %1 (the lesson's: %2)")
              .arg(big ? big->objectName() : QStringLiteral("none"),
                   QString::fromStdString(lessonLarge)));
  const double imageSide = largestImage(big).side;
  const double wantedSide = 0.35 * sr.height();
  check(imageSide >= wantedSide, tr("the big panel's image is %1 px square (>= 35 % of the "
                                    "screen's height, %2 px)")
                                     .arg(imageSide, 0, 'f', 0)
                                     .arg(wantedSide, 0, 'f', 0));

  // 4. The changed (flicker) overlay: the light turns a little, one frame is rendered;
  // the vivid pixels of the view are exactly the renderer's count.
  sl::ViewSide* r = v->mainSide();
  if (auto e = r->rendererParams().setFromString("view.overlay", "changed")) {
    check(false, QString::fromStdString(*e));
    return false;
  }
  w_.teaching()->syncOverlayCombo();
  auto_.setPaused(true);
  auto_.stepFrame();
  waitForFrames(1);
  sl::Light light = v->camera()->light();
  light.azimuthDeg += 0.5f;
  v->camera()->setLight(light);
  auto_.stepFrame();
  waitForFrames(1);
  const QImage rendered = v->frames()->renderedImage();
  const auto counted = r->stats().maskChange;
  std::uint64_t vivid = 0;
  for (int y = 0; y < rendered.height(); ++y)
    for (int x = 0; x < rendered.width(); ++x) vivid += isChangedColour(rendered.pixel(x, y));
  if (!dir.isEmpty())  // the view with the changed pixels, for a look
    v->grabView().save(QDir(dir).filePath(
        QStringLiteral("presenter-%1x%2-changed.png").arg(sr.width()).arg(sr.height())));
  check(counted && counted->changed > 0 && vivid == counted->changed,
        tr("changed overlay: %1 vivid pixels drawn, the renderer counted %2 (of %3)")
            .arg(vivid)
            .arg(counted ? qlonglong(counted->changed) : -1)
            .arg(counted ? qlonglong(counted->compared) : -1));

  // 5. The pointer ring follows the mouse over the view.
  const QPoint at(v->width() / 3, v->height() / 3);
  sendMouse(v, QEvent::MouseMove, at, Qt::NoButton, Qt::NoButton, Qt::NoModifier);
  QImage shown = v->grabView();
  const double dpr = shown.devicePixelRatio();
  int ringPixels = 0;
  const QColor ring(255, 40, 200);
  for (int y = 0; y < shown.height(); ++y)
    for (int x = 0; x < shown.width(); ++x) {
      const QColor c = shown.pixelColor(x, y);
      if (std::abs(c.red() - ring.red()) < 30 && std::abs(c.green() - ring.green()) < 30 &&
          std::abs(c.blue() - ring.blue()) < 30 &&
          std::hypot(x / dpr - at.x(), y / dpr - at.y()) < 80)
        ++ringPixels;
    }
  check(
      auto_.viewReadouts().pointerHighlight && ringPixels > 40,
      tr("pointer ring drawn around (%1, %2): %3 pixels").arg(at.x()).arg(at.y()).arg(ringPixels));

  // 6. The zoom inset: Ctrl+Shift+drag over an area, drawn magnified (nearest neighbour)
  // in the corner.
  const Qt::KeyboardModifiers zoomMods = Qt::ControlModifier | Qt::ShiftModifier;
  const QPoint a(v->width() / 5, v->height() / 4), b(a + QPoint(48, 30));
  sendMouse(v, QEvent::MouseButtonPress, a, Qt::LeftButton, Qt::LeftButton, zoomMods);
  sendMouse(v, QEvent::MouseMove, b, Qt::NoButton, Qt::LeftButton, zoomMods);
  sendMouse(v, QEvent::MouseButtonRelease, b, Qt::LeftButton, Qt::NoButton, zoomMods);
  auto_.stepFrame();
  waitForFrames(1);
  const QRect area = auto_.viewReadouts().zoomArea.value_or(QRect());
  const QRect inset = auto_.viewReadouts().zoomInset;
  const int factor = auto_.viewReadouts().zoomFactor;
  check(area == QRect(a, b).normalized() && factor >= 2 && !inset.isEmpty(),
        tr("zoom inset of %1x%2 at %3,%4: x%5 at %6,%7")
            .arg(area.width())
            .arg(area.height())
            .arg(area.x())
            .arg(area.y())
            .arg(factor)
            .arg(inset.x())
            .arg(inset.y()));
  if (factor >= 2 && !inset.isEmpty()) {
    const QImage source = v->frames()->renderedImage();
    shown = v->grabView();
    // Each source pixel's block centre in the inset has that pixel's colour (device pixels
    // equal widget pixels under Xvfb; the test samples where both agree).
    int sampled = 0, same = 0;
    for (int sy = 0; sy < area.height(); sy += 3)
      for (int sx = 0; sx < area.width(); sx += 3) {
        const QPoint src(area.x() + sx, area.y() + sy);
        const QPoint dst(inset.x() + sx * factor + factor / 2,
                         inset.y() + sy * factor + factor / 2);
        if (!source.rect().contains(src * dpr) || !shown.rect().contains(dst * dpr)) continue;
        ++sampled;
        same += source.pixel(src * dpr) == shown.pixel(dst * dpr);
      }
    check(sampled > 50 && same == sampled,
          tr("the inset repeats the area's pixels: %1 of %2 samples equal").arg(same).arg(sampled));
  }

  // 7. Colour-bar and axis ticks read as numbers: a true minus, no noise digits.
  const QChar minus(0x2212);
  check(formatTick(-0.0218, 1.0) == QString(minus) + QStringLiteral("0.02") &&
            formatTick(1e-7, 2.0) == QStringLiteral("0") &&
            formatTick(-2.5, 10.0) == QString(minus) + QStringLiteral("2.5") &&
            formatTick(0.5, 1.0) == QStringLiteral("0.5") &&
            !formatTick(-0.001, 0.0).contains(QLatin1Char('-')),
        tr("ticks: %1, %2, %3, %4, %5")
            .arg(formatTick(-0.0218, 1.0), formatTick(1e-7, 2.0), formatTick(-2.5, 10.0),
                 formatTick(0.5, 1.0), formatTick(-0.001, 0.0)));

  // 7b. The view's notes and badges never cover its text, at the presenter's font.
  checkOverlayBoxes(dir, v->size());

  if (!dir.isEmpty()) {
    const QString name = QStringLiteral("presenter-%1x%2").arg(sr.width()).arg(sr.height());
    const bool saved = w_.grab().save(QDir(dir).filePath(name + QStringLiteral(".png"))) &&
                       shown.save(QDir(dir).filePath(name + QStringLiteral("-view.png")));
    check(saved, tr("saved %1.png and %1-view.png into %2").arg(name, dir));
  }

  // 8. Every font in the docks follows the presenter's scale, the Timing panel big: its
  // pass names whole.
  checkPresenterFonts(dir, sr.size());
  // 9. The big panel full screen (F12) and back.
  checkFullPanel(dir, sr);

  // 10. Off again (from the full panel): the view, the normal font and theme come back.
  w_.presenter()->fullPanelAction()->trigger();
  QCoreApplication::processEvents();
  w_.presenter()->action()->trigger();
  QCoreApplication::processEvents();
  check(!w_.presenter()->active() && !w_.presenter()->fullPanel() && w_.viewport()->isVisible() &&
            QFontInfo(QApplication::font()).pixelSize() < appPx,
        tr("presenter mode off (from the full panel): view shown, body text back to %1 px")
            .arg(QFontInfo(QApplication::font()).pixelSize()));
  return true;
}

void GuiTests::checkOverlayBoxes(const QString& dir, const QSize& view) {
  // What the overlay shows together, with the longest texts a lesson and a slow frame give:
  // a lesson (banner, pause badge, legend, note), a comparison (split captions, badge,
  // legend, note, zoom inset), the outside view (banner, badge, its legend, note), each with
  // every overlay legend in turn, at the view's size and 80 % of it (docks grown); and
  // everything at once at the view's size. (A smaller view keeps the boxes apart, but the
  // last placed may leave it.)
  QWidget host;
  ViewOverlay o(&host);
  const QString bannerTitle =
      tr("Lesson 6 \u00b7 where the rotation wins: DA-RTW turns the light frame");
  const QString bannerText =
      tr("The importance map's covariance is stretched along the "
         "diagonal; PCA's principal axis points along it and the warp, "
         "turned, gives the diagonal its texels.");
  const QVector<QPair<QColor, QString>> outsideLegend = {
      {Qt::red, tr("camera frustum (to the scene's far end)")},
      {Qt::green, tr("light frustum, map 0")},
      {Qt::blue, tr("warped map's frustum, to its centre")}};
  QImage zoom(view, QImage::Format_RGB32);
  zoom.fill(QColor(90, 110, 140));
  enum Show { Banner = 1, Split = 2, Outside = 4, Inset = 8 };
  const int lesson = Banner, compare = Split | Inset, outsideView = Banner | Outside,
            everything = Banner | Split | Outside | Inset;
  auto show = [&](int what, const QSize& size) {
    o.bannerTitle = what & Banner ? bannerTitle : QString();
    o.bannerText = what & Banner ? bannerText : QString();
    o.outsideLegend = what & Outside ? outsideLegend : decltype(outsideLegend){};
    o.split = what & Split ? zoom.scaled(64, 64) : QImage();
    o.leftCaption = tr("da-rtw \u00b7 error 0.746 % (frame 1234) \u00b7 m p95 3.21 \u00b7 4.0 MiB");
    o.rightCaption = tr("rtw-backward \u00b7 error 2.067 % (frame 1234) \u00b7 m p95 5.19");
    o.zoomSource = what & Inset ? zoom : QImage();
    o.zoomArea = QRect(size.width() / 3, size.height() / 3, 40, 30);
    o.resize(size);
  };
  o.pausedText = tr("PAUSED at frame 1234  \u00b7  . step  \u00b7  Space resume");
  o.resolutionNote =
      tr("internal 960x540 (frames over 100 ms)  \u00b7  computing fvsm \u2026 "
         "4.2 s (the last complete frame is shown)");
  o.errorNote = tr("view changed: tracing its reference\u2026");
  o.changedCount = std::make_pair(std::uint64_t(123456), std::uint64_t(654321));
  const ViewOverlay::Legend legends[] = {ViewOverlay::Legend::Aliasing, ViewOverlay::Legend::Error,
                                         ViewOverlay::Legend::Changed,
                                         ViewOverlay::Legend::WarpGrid};
  struct Case {
    int what;
    QSize size;
  };
  QVector<Case> cases;
  for (const QSize size : {view, view * 0.8})
    for (const int what : {lesson, compare, outsideView}) cases.append({what, size});
  cases.append({everything, view});
  int layouts = 0, boxesSeen = 0, overlaps = 0, outside = 0;
  QString first;
  for (const Case& c : cases)
    for (const ViewOverlay::Legend legend : legends) {
      show(c.what, c.size);
      o.legend = legend;
      const QVector<ViewOverlay::Box> boxes = o.layout();
      ++layouts;
      boxesSeen += int(boxes.size());
      const QString where = QStringLiteral("%1x%2").arg(c.size.width()).arg(c.size.height());
      for (int i = 0; i < boxes.size(); ++i) {
        if (!QRectF(o.rect()).contains(boxes[i].rect)) {
          ++outside;
          if (first.isEmpty())
            first = tr("%1 leaves the %2 view").arg(ViewOverlay::roleName(boxes[i].role), where);
        }
        for (int j = i + 1; j < boxes.size(); ++j)
          if (boxes[i].rect.intersects(boxes[j].rect)) {
            ++overlaps;
            if (first.isEmpty())
              first = tr("%1 covers %2 in the %3 view")
                          .arg(ViewOverlay::roleName(boxes[j].role),
                               ViewOverlay::roleName(boxes[i].role), where);
          }
      }
    }
  // Every case draws the badge, the note and a legend; the comparison two captions and the
  // inset (two boxes); so at least 3 boxes a layout.
  check(overlaps == 0 && outside == 0 && boxesSeen >= 3 * layouts,
        tr("the view's boxes (banner, badge, legends, captions, note, inset) never cover each "
           "other and stay in the view: %1 layouts, %2 boxes, %3 overlaps, %4 outside%5")
            .arg(layouts)
            .arg(boxesSeen)
            .arg(overlaps)
            .arg(outside)
            .arg(first.isEmpty() ? QString() : QStringLiteral(" (first: %1)").arg(first)));
  if (!dir.isEmpty()) {  // everything at once, to look at
    show(everything, view);
    o.legend = ViewOverlay::Legend::Aliasing;
    o.grab().save(QDir(dir).filePath(QStringLiteral("overlay-boxes.png")));
  }
}

void GuiTests::checkPresenterFonts(const QString& dir, const QSize& screen) {
  w_.presenter()->choosePanel(w_.timingDock()->objectName());
  for (int i = 0; i < 10; ++i) QCoreApplication::processEvents(QEventLoop::AllEvents, 30);
  auto_.stepFrame();  // paused since the changed overlay's check: one frame for the Timing panel
  waitForFrames(1);
  for (int i = 0; i < 5; ++i) QCoreApplication::processEvents(QEventLoop::AllEvents, 30);
  // Every widget of every dock (shown or not: a dock shown later keeps its font), the docks'
  // own titles, and the Qt Charts items: at least kMinShare of the body size.
  constexpr double kMinShare = 0.8;
  const int body = bodyPixelSize();
  const int least = int(std::floor(body * kMinShare));
  int walked = 0, small = 0, smallest = body;
  QString smallestName;
  QStringList smallNames;
  auto visit = [&](const QFont& font, const QString& name) {
    const int px = QFontInfo(font).pixelSize();
    ++walked;
    if (px < smallest) smallest = px, smallestName = name;
    if (px < least) {
      ++small;
      if (smallNames.size() < 12) smallNames << QStringLiteral("%1 (%2 px)").arg(name).arg(px);
    }
  };
  for (QDockWidget* dock : w_.findChildren<QDockWidget*>()) {
    visit(dock->font(), dock->windowTitle());
    for (QWidget* widget : dock->findChildren<QWidget*>())
      visit(widget->font(),
            dock->windowTitle() + QStringLiteral(" / ") + widget->metaObject()->className());
    for (QChartView* view : dock->findChildren<QChartView*>()) {
      const QChart* chart = view->chart();
      if (!chart) continue;
      const QString at = dock->windowTitle() + QStringLiteral(" / chart ");
      visit(chart->titleFont(), at + QStringLiteral("title"));
      visit(chart->legend()->font(), at + QStringLiteral("legend"));
      for (const QAbstractAxis* axis : chart->axes()) {
        visit(axis->labelsFont(), at + QStringLiteral("axis labels"));
        visit(axis->titleFont(), at + QStringLiteral("axis title"));
      }
    }
  }
  check(walked > 100 && small == 0,
        tr("fonts in the docks: %1 walked, %2 below %3 px (%4 % of the %5 px body); smallest "
           "%6 px (%7)%8")
            .arg(walked)
            .arg(small)
            .arg(least)
            .arg(kMinShare * 100.0, 0, 'f', 0)
            .arg(body)
            .arg(smallest)
            .arg(smallestName)
            .arg(smallNames.isEmpty()
                     ? QString()
                     : QStringLiteral(": ") + smallNames.join(QStringLiteral(", "))));
  // The big dock's title bar (drawn by Qt in the dock's font) is as tall as a body line.
  const int titleH = w_.timingDock()->widget()->y();
  check(titleH >= body,
        tr("the big dock's title bar is %1 px tall (>= the %2 px body)").arg(titleH).arg(body));
  const TimingPanel* timing = w_.timingPanel();
  const QStringList names = timing->passNames(), shown = timing->shownPassNames();
  check(w_.presenter()->bigDock() == w_.timingDock() && !names.isEmpty() && shown == names,
        tr("the Timing panel big, %1 pass names drawn whole (%2 wide, boxes %3): %4")
            .arg(names.size())
            .arg(timing->width())
            .arg(timing->stacked() ? QStringLiteral("one above the other")
                                   : QStringLiteral("side by side"))
            .arg(shown.join(QStringLiteral(", "))));
  if (!dir.isEmpty())
    check(
        w_.grab().save(QDir(dir).filePath(
            QStringLiteral("presenter-%1x%2-timing.png").arg(screen.width()).arg(screen.height()))),
        tr("saved the Timing panel's grab"));
  w_.presenter()->choosePanel(QString());  // automatic again
  for (int i = 0; i < 5; ++i) QCoreApplication::processEvents(QEventLoop::AllEvents, 30);
}

void GuiTests::checkFullPanel(const QString& dir, const QRect& screen) {
  auto settle = [] {
    for (int i = 0; i < 10; ++i) QCoreApplication::processEvents(QEventLoop::AllEvents, 30);
  };
  const double besideSide = largestImage(w_.presenter()->bigDock()).side;
  w_.presenter()->fullPanelAction()->trigger();  // what F12 does
  settle();
  QDockWidget* big = w_.presenter()->bigDock();
  const QRect frame = w_.frameGeometry();
  const QRect dockRect = big ? QRect(big->mapTo(&w_, QPoint(0, 0)), big->size()) : QRect();
  const int below = w_.menuBar()->isVisible() ? w_.menuBar()->height() : 0;
  const int visibleDocks = docksInView(w_);
  check(w_.presenter()->fullPanel() && !w_.viewport()->isVisible() && big && visibleDocks == 1 &&
            screen.contains(frame) && dockRect.width() >= w_.width() * 97 / 100 &&
            dockRect.height() >= (w_.height() - below) * 97 / 100,
        tr("full panel: %1 is %2x%3 of the %4x%5 window (menu bar %6 px), the view hidden, "
           "%7 dock(s) in view")
            .arg(big ? big->windowTitle() : QStringLiteral("none"))
            .arg(dockRect.width())
            .arg(dockRect.height())
            .arg(w_.width())
            .arg(w_.height())
            .arg(below)
            .arg(visibleDocks));
  // Its image as large as the space allows: larger than beside the view, and filling the
  // image view in the dimension that limits it.
  const auto [side, fill] = largestImage(big);
  check(side >= 0.6 * screen.height() && side > besideSide && fill >= 0.85,
        tr("full panel's image %1 px square (beside the view %2 px; >= 60 % of the screen's "
           "height, %3 px), filling %4 % of its view's limiting side")
            .arg(side, 0, 'f', 0)
            .arg(besideSide, 0, 'f', 0)
            .arg(0.6 * screen.height(), 0, 'f', 0)
            .arg(fill * 100.0, 0, 'f', 0));
  if (!dir.isEmpty())
    check(w_.grab().save(QDir(dir).filePath(QStringLiteral("presenter-%1x%2-fullpanel.png")
                                                .arg(screen.width())
                                                .arg(screen.height()))),
          tr("saved the full panel's grab"));
  // F12 again: the view back beside the panel, rendering.
  w_.presenter()->fullPanelAction()->trigger();
  settle();
  auto_.stepFrame();  // paused: one frame
  const bool rendered = auto_.waitForFrames(1);
  check(!w_.presenter()->fullPanel() && w_.viewport()->isVisible() && rendered &&
            w_.presenter()->bigDock() && w_.presenter()->bigDock()->width() < w_.width() * 3 / 4,
        tr("full panel off: the view is back (%1x%2) and renders, the panel %3 px wide")
            .arg(w_.viewport()->width())
            .arg(w_.viewport()->height())
            .arg(w_.presenter()->bigDock() ? w_.presenter()->bigDock()->width() : 0));
}

bool GuiTests::splitParams(const QString& dir) {
  if (!dir.isEmpty()) QDir().mkpath(dir);
  ViewportWidget* v = w_.viewport();
  sl::ViewSide* main = v->mainSide();
  const std::string other = "rtw-backward";
  auto_.setSplit(QString::fromStdString(other));  // as "Compare with" does
  if (v->frames()->splitTechnique() != other) {
    check(false, tr("the split view shows %1").arg(QString::fromStdString(other)));
    return false;
  }
  w_.paramDock()->show();
  w_.paramDock()->raise();
  v->setFixedSize(640, 400);  // the same frame size for every measurement
  QCoreApplication::processEvents();
  waitForFrames(3);
  SplitSideParams& side = *w_.splitSide();
  auto* spin = side.panel()->findChild<QSpinBox*>(QStringLiteral("param:resolution"));
  check(side.panel()->isVisible() && spin,
        tr("the Parameters dock shows the right half's parameters (%1)")
            .arg(QString::fromStdString(other)));
  if (!spin) return false;
  sl::ViewSide* split = v->splitSide();
  if (!split) {
    check(false, tr("the split renderer exists"));
    return false;
  }

  // 1. The right half's resolution edited in its own panel: its memory and error change,
  // the left half's do not.
  const auto mainErrBefore = v->measure()->computeErrorNow();
  const auto splitErrBefore = v->measure()->splitErrorPct();
  const std::uint64_t mainBytesBefore = main->stats().memory.bytes();
  const std::uint64_t splitBytesBefore = split->stats().memory.bytes();
  const int before = spin->value();
  const int edited = before / 2;
  spin->setValue(edited);
  QCoreApplication::processEvents();
  waitForFrames(2);
  const auto mainErrAfter = v->measure()->computeErrorNow();
  const auto splitErrAfter = v->measure()->splitErrorPct();
  const std::uint64_t mainBytesAfter = main->stats().memory.bytes();
  const std::uint64_t splitBytesAfter = split->stats().memory.bytes();
  check(split->params().get("resolution") == edited && main->params().get("resolution") != edited,
        tr("right resolution %1 -> %2 (left stays %3)")
            .arg(before)
            .arg(split->params().get("resolution"))
            .arg(main->params().get("resolution")));
  check(splitBytesAfter < splitBytesBefore && mainBytesAfter == mainBytesBefore,
        tr("memory: right %1 -> %2 B, left %3 -> %4 B")
            .arg(splitBytesBefore)
            .arg(splitBytesAfter)
            .arg(mainBytesBefore)
            .arg(mainBytesAfter));
  check(mainErrBefore && mainErrAfter && std::abs(*mainErrBefore - *mainErrAfter) <= 1e-9 &&
            splitErrBefore && splitErrAfter && *splitErrBefore != *splitErrAfter,
        tr("error: right %1 % -> %2 %, left %3 % -> %4 %")
            .arg(splitErrBefore.value_or(-1), 0, 'f', 4)
            .arg(splitErrAfter.value_or(-1), 0, 'f', 4)
            .arg(mainErrBefore.value_or(-1), 0, 'f', 4)
            .arg(mainErrAfter.value_or(-1), 0, 'f', 4));
  check(v->frames()->splitParams().at("resolution") == std::to_string(edited),
        tr("the session's split parameters follow the panel (resolution=%1)")
            .arg(QString::fromStdString(v->frames()->splitParams().at("resolution"))));

  // 2. Equal memory: the largest right resolution within the left half's bytes; one step
  // more spends more.
  // The parameter matched is the right technique's declared memory knob (its resolution
  // here, rmsm's pool pages below), set through its spin box in the right half's panel.
  auto checkEqualMemory = [&](const QString& when) {
    waitForFrames(2);
    const std::uint64_t mainBytes = main->stats().memory.bytes();
    const std::uint64_t splitBytes = split->stats().memory.bytes();
    const sl::ParamDecl* decl = sl::memoryKnob(split->params().decls());
    check(decl != nullptr, tr("%1: the right technique declares a memory knob").arg(when));
    if (!decl) return;
    const QString key = QString::fromStdString(decl->key);
    const int value = int(split->params().get(decl->key));
    check(splitBytes <= mainBytes &&
              side.bytesText().contains(QLocale().toString(qulonglong(mainBytes))) &&
              side.bytesText().contains(QLocale().toString(qulonglong(splitBytes))),
          tr("%1: right %2 B at %3 = %4 <= left %5 B (%6 %), both shown")
              .arg(when)
              .arg(splitBytes)
              .arg(key)
              .arg(value)
              .arg(mainBytes)
              .arg(100.0 * double(splitBytes) / double(mainBytes), 0, 'f', 1));
    auto* knobSpin = side.panel()->findChild<QSpinBox*>(QStringLiteral("param:") + key);
    check(knobSpin != nullptr, tr("%1: the right half's panel edits %2").arg(when, key));
    const int step = std::max(1, int(decl->step));
    if (!knobSpin || value + step > decl->maxValue) return;
    // One step more (measured with a frame, then back): over the budget.
    knobSpin->setValue(value + step);
    QCoreApplication::processEvents();
    waitForFrames(1);
    const std::uint64_t over = split->stats().memory.bytes();
    check(over > mainBytes, tr("%1: one step more (%2 = %3) spends %4 B > %5 B")
                                .arg(when, key)
                                .arg(value + step)
                                .arg(over)
                                .arg(mainBytes));
  };
  side.equalMemoryBox()->setChecked(true);
  checkEqualMemory(tr("equal memory"));
  // The left side's memory changes: matched again (the toggle stays on).
  side.equalMemoryBox()->setChecked(false);
  if (auto e = main->params().set("resolution", main->params().get("resolution") / 2)) {
    check(false, QString::fromStdString(*e));
    return false;
  }
  w_.paramPanel()->refreshValues();
  waitForFrames(2);
  side.equalMemoryBox()->setChecked(true);
  if (auto e = main->params().set("resolution", main->params().get("resolution") * 2)) {
    check(false, QString::fromStdString(*e));
    return false;
  }
  for (int i = 0; i < 20; ++i) QCoreApplication::processEvents(QEventLoop::AllEvents, 30);
  waitForFrames(3);
  for (int i = 0; i < 20; ++i) QCoreApplication::processEvents(QEventLoop::AllEvents, 30);
  check(side.matchedMainBytes() && *side.matchedMainBytes() == main->stats().memory.bytes(),
        tr("after the left resolution changed to %1, matched again for %2 B")
            .arg(main->params().get("resolution"))
            .arg(main->stats().memory.bytes()));
  // The pending match is what the check measures (the one-step-more edit is undone by it).
  checkEqualMemory(tr("re-matched"));
  // A second pair: rmsm's memory is its physical pool, so equal memory sets pool.pages (its
  // virtual.resolution, a resolution in name, spends no byte).
  auto_.setSplit(QStringLiteral("rmsm"));
  for (int i = 0; i < 20; ++i) QCoreApplication::processEvents(QEventLoop::AllEvents, 30);
  split = v->splitSide();
  check(split && v->frames()->splitTechnique() == "rmsm", tr("the split view shows rmsm"));
  if (!split) return false;
  side.equalMemoryBox()->setChecked(false);
  side.equalMemoryBox()->setChecked(true);
  for (int i = 0; i < 20; ++i) QCoreApplication::processEvents(QEventLoop::AllEvents, 30);
  check(side.bytesText().contains(QStringLiteral("Equal memory: pool.pages = ")),
        tr("rmsm: equal memory sets pool.pages (%1)").arg(side.bytesText()));
  checkEqualMemory(tr("rmsm"));
  if (!dir.isEmpty())
    check(w_.grab().save(QDir(dir).filePath(QStringLiteral("split-params.png"))),
          tr("saved split-params.png into %1").arg(dir));
  return true;
}

}  // namespace sl::ui
