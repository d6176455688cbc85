// The lesson-claims self-test (see GuiTests.h): every lesson opened fresh through the Lessons
// menu's path (LessonController::apply), its layout checked, and the lessons that state a claim
// in numbers measured: the numbers are read from the lesson's own text, so that the text says
// exactly what this test checks.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <tuple>
#include <vector>

#include <QCoreApplication>
#include <QJsonArray>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QHeaderView>
#include <QTableView>
#include <QTreeView>
#include <QScreen>
#include <QTextDocument>
#include <QLabel>
#include <QJsonArray>
#include <QJsonObject>
#include <QRegularExpression>

#include <glm/glm.hpp>

#include "teaching/LessonController.h"
#include "window/MainWindow.h"
#include "teaching/PresenterMode.h"
#include "window/PublicationDocks.h"
#include "GuiTests.h"
#include "view/ViewportWidget.h"
#include "panels/common/LessonPanel.h"
#include "panels/common/PanelKit.h"
#include "panels/common/ParamPanel.h"
#include "algo/rtw/TurnPrediction.h"
#include "panels/rtw/CovariancePanel.h"
#include "panels/rtw/RtwSettle.h"

namespace sl::ui {

namespace {
/// The first capture of `pattern` in `text` as a number (the lesson's stated claim); NaN
/// when the text does not state it. U+2212 (minus sign) reads as '-'.
double stated(const QString& text, const QString& pattern) {
  const QRegularExpressionMatch m = QRegularExpression(pattern).match(text);
  if (!m.hasMatch()) return std::nan("");
  QString n = m.captured(1);
  n.replace(QChar(0x2212), QLatin1Char('-'));
  return n.toDouble();
}

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

bool covered(const sl::FrameReadback& f, std::size_t i) {
  return f.positions[i].w > 0.5f;
}
}  // namespace

sl::Renderer::ErrorResult GuiTests::measureView() {
  return auto_.computeError();
}

bool GuiTests::lessonClaims(const QString& dir) {
  // The lesson the app was started with (--lesson), as a student opens it: a fresh process,
  // the window's own start-up, the lesson settled before this runs.
  const int index = w_.lessons()->index();
  check(index >= 0, tr("started with --lesson"));
  if (index < 0) return false;
  checkOpenLesson(index, dir);
  return true;
}

void GuiTests::checkOpenLesson(int index, const QString& dir) {
  // Settled: a resize once the panels are filled (presenter mode) may start it again.
  waitForFrames(1);
  auto_.waitForSettled();
  const Lesson& lesson = w_.lessons()->lessons()[static_cast<std::size_t>(index)];
  const QString name = QFileInfo(lesson.path).completeBaseName();
  const sl::Preset& p = lesson.preset;
  const QString text = QString::fromStdString(p.explanation);
  std::printf("---- lesson %d: %s\n", index + 1, qPrintable(name));
  std::fflush(stdout);
  check(w_.viewport()->techniqueId() == p.technique && !w_.lessons()->settling(),
        tr("opens with %1 on %2, its temporal state settled or none (%3 settling frames)")
            .arg(QString::fromStdString(w_.viewport()->techniqueId()), auto_.sceneShown())
            .arg(w_.lessons()->settleFrames()));
  std::printf("     window %dx%d, view %dx%d\n", w_.width(), w_.height(), w_.viewport()->width(),
              w_.viewport()->height());
  {  // what a lesson opened after others could inherit: the camera and the light
    const sl::Camera c = w_.viewport()->camera()->camera();
    const sl::Light l = w_.viewport()->camera()->light();
    std::printf(
        "     camera (%.2f %.2f %.2f) -> (%.2f %.2f %.2f), near %.3g, far %.3g; light "
        "azimuth %.1f°, elevation %.1f°\n",
        c.position.x, c.position.y, c.position.z, c.target.x, c.target.y, c.target.z, c.nearM,
        c.farM, l.azimuthDeg, l.elevationDeg);
  }
  if (p.layout) lessonLayout(*p.layout);
  lessonOnScreen(name);
  // The window before the claims change it, its numbers filled (lessonOnScreen measured them).
  if (!dir.isEmpty() && QDir().mkpath(dir))
    w_.grab().toImage().save(QDir(dir).filePath(name + QStringLiteral(".png")));
  if (name.endsWith(QLatin1String("perspective-aliasing")))
    claimPerspective(text);
  else if (name.endsWith(QLatin1String("projective-aliasing")))
    claimProjective(text);
  else if (name.endsWith(QLatin1String("tessellation")))
    claimTessellation(text);
  else if (name.endsWith(QLatin1String("rtw-warping")))
    claimRtw();
  else if (name.endsWith(QLatin1String("diagonal-pca")))
    claimPca(index);
  else if (name.endsWith(QLatin1String("vibration-threshold")))
    claimVibration(text);
  else if (name.endsWith(QLatin1String("forward-vs-backward")))
    claimForwardBackward(text);
  else if (name.endsWith(QLatin1String("perspective-warping")))
    claimPerspectiveWarp(text);
  else if (name.endsWith(QLatin1String("dueling-frusta")))
    claimDuelingFrusta(text);
  else if (name.endsWith(QLatin1String("cascades")))
    claimCascades(text);
  else if (name.endsWith(QLatin1String("omni")))
    claimOmni(text);
  else if (name.endsWith(QLatin1String("fvsm")))
    claimFvsm(text);
  else if (name.endsWith(QLatin1String("asm-vs-rmsm")))
    claimAsm(text);
}

void GuiTests::lessonOnScreen(const QString& name) {
  // The window fits the screen it is on (1280x800 to 3840x2160: the test runs at two sizes).
  QCoreApplication::processEvents();
  const QRect screen = w_.screen() ? w_.screen()->geometry() : QRect();
  const QRect frame = w_.frameGeometry();
  check(!screen.isEmpty() && frame.width() <= screen.width() && frame.height() <= screen.height(),
        tr("%1: the window (%2 x %3) fits the %4 x %5 screen")
            .arg(name)
            .arg(frame.width())
            .arg(frame.height())
            .arg(screen.width())
            .arg(screen.height()));
  if (!screen.isEmpty() && (frame.width() > screen.width() || frame.height() > screen.height()))
    for (const QDockWidget* dock : w_.findChildren<QDockWidget*>())  // which panel asks for it
      if (dock->isVisible())
        std::printf("     dock %s: %d x %d px, at least %d x %d\n", qPrintable(dock->objectName()),
                    dock->width(), dock->height(), dock->minimumSizeHint().width(),
                    dock->minimumSizeHint().height());
  // Every live number the text quotes is filled once the view's error is measured (a lesson
  // with a split view: its right half's too).
  // The window handles events while the error is traced: a re-layout in the meantime (the
  // presenter's second arrangement once the lesson has settled) changes the view, whose
  // error is then measured again (at most three times).
  for (int attempt = 0; attempt < 3; ++attempt) {
    waitForFrames(2);
    if (w_.viewport()->measure()->computeErrorNow()) break;
  }
  QCoreApplication::processEvents();
  const QString shown = w_.lessonPanel()->shownText();
  const qsizetype missing = shown.indexOf(QStringLiteral("n/a"));
  check(missing < 0, tr("%1: every number of the text is filled (%2)")
                         .arg(name)
                         .arg(missing < 0 ? tr("none n/a")
                                          : shown.mid(std::max<qsizetype>(0, missing - 60), 80)));
  // No label on screen cuts its text: a number is never elided (text wraps or the panel grows).
  QStringList cut;
  for (const QLabel* label : w_.findChildren<QLabel*>()) {
    if (!label->isVisible() || label->visibleRegion().isEmpty() || label->wordWrap() ||
        label->textFormat() == Qt::RichText || Qt::mightBeRichText(label->text()) ||
        label->text().isEmpty() || !label->pixmap().isNull())
      continue;
    const QFontMetrics fm = label->fontMetrics();
    int widest = 0;
    for (const QString& line : label->text().split(QLatin1Char('\n')))
      widest = std::max(widest, fm.horizontalAdvance(line));
    if (widest > label->contentsRect().width() + 1 || label->text().contains(QChar(0x2026)))
      cut << tr("'%1' (%2 px in %3)")
                 .arg(label->text().left(60))
                 .arg(widest)
                 .arg(label->contentsRect().width());
  }
  check(cut.isEmpty(), tr("%1: no label cut: %2")
                           .arg(name)
                           .arg(cut.isEmpty() ? tr("none") : cut.join(QStringLiteral("; "))));
  // No table cell or header in view elided: each visible column as wide as its content.
  QStringList elided;
  for (const QAbstractItemView* view : w_.findChildren<QAbstractItemView*>()) {
    if (!view->isVisible() || view->visibleRegion().isEmpty() || !view->model()) continue;
    const auto* tree = qobject_cast<const QTreeView*>(view);
    const auto* table = qobject_cast<const QTableView*>(view);
    const QHeaderView* header = tree ? tree->header() : table ? table->horizontalHeader() : nullptr;
    if (!header) continue;
    for (int c = 0; c < view->model()->columnCount(view->rootIndex()); ++c) {
      if (header->isSectionHidden(c)) continue;
      const int width = header->sectionSize(c);
      const int cells = view->sizeHintForColumn(c);  // the widest cell in view, as delegated
      const int title = header->isVisible() ? header->sectionSizeHint(c) : 0;
      if (std::max(cells, title) > width + 1)
        elided << tr("'%1' column %2 (%3 px of %4 needed)")
                      .arg(view->model()->headerData(c, Qt::Horizontal).toString().left(30))
                      .arg(c)
                      .arg(width)
                      .arg(std::max(cells, title));
    }
  }
  check(elided.isEmpty(),
        tr("%1: no table cell or header elided: %2")
            .arg(name)
            .arg(elided.isEmpty() ? tr("none") : elided.join(QStringLiteral("; "))));
}

void GuiTests::lessonStrip(const sl::PresetLayout& layout) {
  QDockWidget* dock = w_.lessons()->stripDock();
  if (layout.strip.empty()) {
    check(!dock || !dock->isVisible(), tr("a lesson without a strip shows none"));
    return;
  }
  // The strip in view, whole: an editor per key, as tall as its rows (never scrolled).
  QStringList keys, missing;
  for (const std::string& key : layout.strip) {
    keys << QString::fromStdString(key);
    const QWidget* editor =
        dock ? dock->findChild<QWidget*>(QStringLiteral("param:") + keys.back()) : nullptr;
    if (!editor || !editor->isVisible() || editor->visibleRegion().isEmpty())
      missing << keys.back();
  }
  const QWidget* rows = dock ? w_.lessons()->strip() : nullptr;
  const int needed = rows ? rows->minimumSizeHint().height() : 0;
  check(dock && dock->isVisible() && !dock->visibleRegion().isEmpty() && missing.isEmpty() &&
            rows->height() >= needed,
        tr("the lesson's strip (%1) is in view, whole: %2 px of the %3 its rows need%4")
            .arg(keys.join(QStringLiteral(", ")))
            .arg(rows ? rows->height() : 0)
            .arg(needed)
            .arg(missing.isEmpty()
                     ? QString()
                     : tr("; not in view: %1").arg(missing.join(QStringLiteral(", ")))));
}

namespace {
/// The lessons whose big panel does not read in presenter mode on a projector's screen
/// (docs/user-guide/presenter.md, "Which lessons read at which size"): there the lesson says
/// so, naming the panel; every other lesson must read on these screens.
bool doesNotFit(const QString& lesson, const QSize& screen) {
  struct Known {
    const char* lesson;
    bool at1920x1080, at1280x800;
  };
  static const Known known[] = {
      {"05-forward-vs-backward", true, false},  // opened alone: Warp under Importance, both small
      {"09-dueling-frusta", false, true},  // Partitions: five maps in one row from 48 % of 1920
      {"12-fvsm", true, true},             // FVSM: five images and a plot, 87 px short at 60 %
  };
  for (const Known& k : known)
    if (lesson.startsWith(QLatin1String(k.lesson)))
      return screen == QSize(1920, 1080)  ? k.at1920x1080
             : screen == QSize(1280, 800) ? k.at1280x800
                                          : true;
  return screen != QSize(1920, 1080) && screen != QSize(1280, 800);
}
}  // namespace

void GuiTests::lessonReadable(const sl::PresetLayout& layout) {
  // Is every plot and image of the panels the lesson names, where it is on screen, at a
  // readable size (unreadableParts: PlotWidget::kReadableHeight, kReadableCurves,
  // ImageView::kReadableSide), every plot's legend beside its curves? Where one is not, the
  // lesson said so on the status line when it settled, naming the panel.
  QStringList small, unnamed;
  const QString& note = w_.lessons()->fitNote();
  for (const std::string& id : layout.docks) {
    const QDockWidget* dock = w_.findChild<QDockWidget*>(QString::fromStdString(id));
    if (!dock || !dock->isVisible() || dock->visibleRegion().isEmpty()) continue;
    const QStringList parts = unreadableParts(*dock);
    if (parts.isEmpty()) continue;
    small << tr("%1: %2").arg(QString::fromStdString(id), parts.join(QStringLiteral(", ")));
    if (!note.contains(dock->windowTitle())) unnamed << dock->windowTitle();
  }
  std::printf(
      "     readable (plots %d px tall with %d px of curves, images %d px, legends beside "
      "the curves): %s\n",
      PlotWidget::kReadableHeight, PlotWidget::kReadableCurves, ImageView::kReadableSide,
      small.isEmpty() ? "all" : qPrintable(small.join(QStringLiteral("; "))));
  // On a projector's screen in presenter mode, a lesson that fits must read (a regression
  // fails); one that does not fit says so.
  const int index = w_.lessons()->index();
  const QString lesson =
      index < 0 ? QString()
                : QFileInfo(w_.lessons()->lessons()[static_cast<std::size_t>(index)].path)
                      .completeBaseName();
  const QSize screen = w_.screen() ? w_.screen()->geometry().size() : QSize();
  if (w_.presenter()->active() && !doesNotFit(lesson, screen))
    check(small.isEmpty(),
          tr("%1 fits a %2 x %3 screen: every panel it names reads (%4)")
              .arg(lesson)
              .arg(screen.width())
              .arg(screen.height())
              .arg(small.isEmpty() ? tr("all") : small.join(QStringLiteral("; "))));
  check(unnamed.isEmpty(),
        small.isEmpty() ? tr("every panel the lesson names reads at this size")
        : unnamed.isEmpty()
            ? tr("the lesson says which panels are too small to read: \"%1\"").arg(note)
            : tr("the lesson names every panel too small to read (missing: %1; it said: \"%2\")")
                  .arg(unnamed.join(QStringLiteral(", ")), note));
}

void GuiTests::lessonLayout(const sl::PresetLayout& layout) {
  QCoreApplication::processEvents();
  QDockWidget* big = layout.large.empty()
                         ? nullptr
                         : w_.findChild<QDockWidget*>(QString::fromStdString(layout.large));
  const QList<QDockWidget*> behind = big ? w_.tabifiedDockWidgets(big) : QList<QDockWidget*>();
  for (QDockWidget* dock : w_.findChildren<QDockWidget*>()) {
    const bool listed = std::find(layout.docks.begin(), layout.docks.end(),
                                  dock->objectName().toStdString()) != layout.docks.end();
    // Presenter mode tabs Lesson and Parameters behind the big panel
    // (docs/user-guide/presenter.md): there only as a tab, not on screen.
    const bool tabBehind =
        w_.presenter()->active() && behind.contains(dock) && dock->visibleRegion().isEmpty();
    const bool strip = !layout.strip.empty() && dock == w_.lessons()->stripDock();
    if (!listed && dock->isVisible() && !tabBehind && !strip)
      check(false, tr("dock %1 is hidden").arg(dock->objectName()));
  }
  lessonStrip(layout);
  lessonReadable(layout);
  if (layout.large.empty()) return;
  QDockWidget* large = w_.findChild<QDockWidget*>(QString::fromStdString(layout.large));
  const Qt::DockWidgetArea area = large ? w_.dockWidgetArea(large) : Qt::NoDockWidgetArea;
  const bool vertical = area == Qt::BottomDockWidgetArea || area == Qt::TopDockWidgetArea;
  const double share = !large     ? 0.0
                       : vertical ? double(large->height()) / w_.height()
                                  : double(large->width()) / w_.width();
  check(large && large->isVisible() && !large->visibleRegion().isEmpty() && share >= 0.3,
        tr("the %1 panel is shown large: %2 % of the window's %3")
            .arg(QString::fromStdString(layout.large))
            .arg(100.0 * share, 0, 'f', 0)
            .arg(vertical ? tr("height") : tr("width")));
}

void GuiTests::claimPerspective(const QString& text) {
  const double bandPct =
      stated(text, QStringLiteral("at least (\\d+) % of the floor and pillar pixels fall in each"));
  const double hi = stated(text, QStringLiteral("three bands m > (\\d+),"));
  const double lo =
      stated(text, QStringLiteral("three bands m > \\d+, \\d+ to \\d+ and m < (\\d+)"));
  const double edgePct = stated(text, QStringLiteral("at least (\\d+) % of them lie within"));
  const double edgePx = stated(text, QStringLiteral("lie within (\\d+) pixels of an edge"));
  check(std::isfinite(bandPct) && std::isfinite(hi) && std::isfinite(lo) &&
            std::isfinite(edgePct) && std::isfinite(edgePx),
        tr("the text states the bands (m > %1, %2 to %1, m < %2), their share, the edge share and "
           "the distance")
            .arg(hi)
            .arg(lo));
  const sl::Renderer::ErrorResult e = measureView();
  const sl::FrameReadback& f = e.frame;
  // m in three bands: undersampled (> 2), matched (1/2..2), oversampled (< 1/2).
  std::size_t n = 0, bands[3] = {0, 0, 0};
  for (std::size_t i = 0; i < f.aliasing.size(); ++i) {
    if (!covered(f, i)) continue;
    ++n;
    const float m = f.aliasing[i];
    ++bands[double(m) > hi ? 0 : (double(m) >= lo ? 1 : 2)];
  }
  const auto pct = [n](std::size_t k) { return n ? 100.0 * double(k) / double(n) : 0.0; };
  {
    std::vector<float> ms;
    for (std::size_t i = 0; i < f.aliasing.size(); ++i)
      if (covered(f, i)) ms.push_back(f.aliasing[i]);
    std::sort(ms.begin(), ms.end());
    if (!ms.empty())
      std::printf("     m percentiles: p10 %.2f p25 %.2f p50 %.2f p75 %.2f p90 %.2f (view %dx%d)\n",
                  double(ms[ms.size() / 10]), double(ms[ms.size() / 4]), double(ms[ms.size() / 2]),
                  double(ms[ms.size() * 3 / 4]), double(ms[ms.size() * 9 / 10]), f.width, f.height);
  }
  check(n > 0 && pct(bands[0]) >= bandPct && pct(bands[1]) >= bandPct && pct(bands[2]) >= bandPct,
        tr("m spans a gradient: %1 % of %2 pixels at m > %3, %4 % at %5 to %3, %6 % below %5 "
           "(each at least %7 %)")
            .arg(pct(bands[0]), 0, 'f', 1)
            .arg(n)
            .arg(hi)
            .arg(pct(bands[1]), 0, 'f', 1)
            .arg(lo)
            .arg(pct(bands[2]), 0, 'f', 1)
            .arg(bandPct));
  // Wrong pixels near an edge of the exact shadow: thin lines along the edges, not blocks.
  const int w = f.width, h = f.height, r = int(edgePx);
  const auto at = [w](int x, int y) { return std::size_t(y) * std::size_t(w) + std::size_t(x); };
  std::vector<std::uint8_t> edge(f.hardMask.size(), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::uint8_t ref = e.referenceMask[at(x, y)];
      if (ref > 1) continue;
      for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
        if (x + dx >= w || y + dy >= h) continue;
        const std::uint8_t other = e.referenceMask[at(x + dx, y + dy)];
        if (other <= 1 && other != ref) edge[at(x, y)] = edge[at(x + dx, y + dy)] = 1;
      }
    }
  std::size_t wrong = 0, nearEdge = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = at(x, y);
      if (!covered(f, i) || e.referenceMask[i] > 1 || f.hardMask[i] == e.referenceMask[i]) continue;
      ++wrong;
      bool near = false;
      for (int yy = std::max(0, y - r); yy <= std::min(h - 1, y + r) && !near; ++yy)
        for (int xx = std::max(0, x - r); xx <= std::min(w - 1, x + r) && !near; ++xx)
          near = edge[at(xx, yy)] != 0;
      nearEdge += near ? 1 : 0;
    }
  const double nearPct = wrong ? 100.0 * double(nearEdge) / double(wrong) : 0.0;
  check(wrong > 0 && nearPct >= edgePct,
        tr("error %1 %: %2 wrong pixels, %3 % of them within %4 px of an exact shadow edge "
           "(at least %5 %)")
            .arg(e.stats.errorPct, 0, 'f', 2)
            .arg(wrong)
            .arg(nearPct, 0, 'f', 1)
            .arg(r)
            .arg(edgePct));
}

void GuiTests::claimProjective(const QString& text) {
  const double ratio = stated(text, QStringLiteral("at least (\\d+(?:\\.\\d+)?) times"));
  const double high = stated(text, QStringLiteral("raise the sun to (\\d+)°"));
  check(std::isfinite(ratio) && std::isfinite(high), tr("the text states the ratio and the sun"));
  // The floor 5-30 m from the camera: its median m at the lesson's low sun, then with only
  // the sun's elevation changed.
  const glm::vec3 eye = w_.viewport()->camera()->camera().position;
  auto floorMedian = [&]() {
    const sl::Renderer::ErrorResult e = measureView();
    const sl::FrameReadback& f = e.frame;
    std::vector<double> m;
    for (std::size_t i = 0; i < f.aliasing.size(); ++i) {
      if (!covered(f, i) || f.normals[i].y < 0.99f || !(f.aliasing[i] > 0.0f)) continue;
      const float d = glm::length(glm::vec3(f.positions[i]) - eye);
      if (d >= 5.0f && d <= 30.0f) m.push_back(f.aliasing[i]);
    }
    return std::pair{median(m), m.size()};
  };
  const sl::Light low = w_.viewport()->camera()->light();
  const auto [lowM, lowN] = floorMedian();
  sl::Light raised = low;
  raised.elevationDeg = float(high);
  w_.viewport()->camera()->setLight(raised);
  waitForFrames(2);
  const auto [highM, highN] = floorMedian();
  w_.viewport()->camera()->setLight(low);
  waitForFrames(1);
  check(lowN > 1000 && highN > 1000 && lowM >= ratio * highM,
        tr("the floor 5-30 m away: median m %1 with the sun at %2°, %3 at %4°: %5x (at least %6x)")
            .arg(lowM, 0, 'f', 2)
            .arg(double(low.elevationDeg))
            .arg(highM, 0, 'f', 2)
            .arg(high)
            .arg(lowM / highM, 0, 'f', 2)
            .arg(ratio));
}

void GuiTests::claimTessellation(const QString& text) {
  const double ratio =
      stated(text, QStringLiteral("without tessellation is at least (\\d+) times"));
  check(std::isfinite(ratio), tr("the text states the ratio"));
  sl::ViewSide* r = w_.viewport()->mainSide();
  const auto off = w_.viewport()->measure()->computeErrorNow();
  if (auto e = r->params().setFromString("tessellation", "on"))
    check(false, QString::fromStdString(*e));
  waitForFrames(2);
  const auto on = w_.viewport()->measure()->computeErrorNow();
  check(off && on && *off >= ratio * *on,
        tr("error %1 % without tessellation, %2 % with it: %3x (at least %4x)")
            .arg(off.value_or(-1), 0, 'f', 2)
            .arg(on.value_or(-1), 0, 'f', 2)
            .arg(off && on && *on > 0 ? *off / *on : 0.0, 0, 'f', 1)
            .arg(ratio));
}

void GuiTests::claimRtw() {
  waitForFrames(2);
  const auto main = w_.viewport()->measure()->computeErrorNow();
  waitForFrames(1);
  const auto split = w_.viewport()->measure()->splitErrorPct();
  sl::ViewSide* r = w_.viewport()->mainSide();
  check(
      w_.viewport()->frames()->splitTechnique() == "uniform" && main && split && *main < *split,
      tr("%1 at %2 x %2 texels: %3 % error; %4 at %5 x %5: %6 %")
          .arg(QString::fromStdString(w_.viewport()->techniqueId()))
          .arg(r->params().getInt("resolution"))
          .arg(main.value_or(-1), 0, 'f', 3)
          .arg(QString::fromStdString(w_.viewport()->frames()->splitTechnique()))
          .arg(QString::fromStdString(w_.viewport()->frames()->splitParams().count("resolution")
                                          ? w_.viewport()->frames()->splitParams().at("resolution")
                                          : "default"))
          .arg(split.value_or(-1), 0, 'f', 3));
}

void GuiTests::claimPca(int lessonIndex) {
  const sl::Preset& lesson = w_.lessons()->lessons()[static_cast<std::size_t>(lessonIndex)].preset;
  check(lesson.cases.size() == 2,
        tr("the lesson is told in two cases (rotation wins; it does not): %1")
            .arg(lesson.cases.size()));
  for (std::size_t k = 0; k < lesson.cases.size(); ++k) {
    // The first case is the one the lesson opens with; the next as Ctrl+Shift+N applies it.
    if (k > 0) {
      w_.lessons()->nextCase();
      auto_.waitForSettled();  // settling runs frame by frame from the event loop
    }
    check(w_.lessons()->caseIndex() == int(k) && !w_.lessons()->settling(),
          tr("case %1 applied and settled").arg(k + 1));
    claimPcaCase(lesson.cases[k], int(k) + 1);
  }
}

void GuiTests::checkCovarianceReadouts(const QString& where) {
  PublicationPanel* covariance = nullptr;
  for (const PublicationDocks::Dock& d : w_.docks().docks())
    if (d.entry.id == QLatin1String("covariance")) covariance = d.panel;
  sl::ViewSide* r = w_.viewport()->mainSide();
  auto drawn = [covariance] { return covariance ? covariance->drawnValues() : QJsonObject(); };
  if (drawn().value(QStringLiteral("frame")).toDouble(-1) != double(r->publication().frameIndex))
    waitForFrames(1);  // the panel shows the frame the window drew last
  const QStringList problems = CovariancePanel::readoutProblems(drawn(), r->publication());
  check(covariance && problems.isEmpty(),
        tr("%1: every Covariance readout agrees with the renderer's publication%2")
            .arg(where, problems.isEmpty()
                            ? QString()
                            : QStringLiteral(": ") + problems.join(QStringLiteral("; "))));
}

void GuiTests::claimPcaCase(const sl::Preset& c, int caseNumber) {
  const QString text = QString::fromStdString(c.explanation);
  std::printf("     case %d: %s\n", caseNumber, c.title.c_str());
  // The left half: "R settles at 45°, ± 2°" (folded by the quarter-turn symmetry). The right
  // half, when it turns too: "turns by at least 10°" (the view's shape moves its angle).
  const double angle =
      stated(text, QStringLiteral("R settles at ([\\x{2212}-]?\\d+(?:\\.\\d+)?)°"));
  const double about = stated(text, QStringLiteral("turns by at least (\\d+(?:\\.\\d+)?)°"));
  check(std::isfinite(angle), tr("case %1: the text states the settled angle").arg(caseNumber));
  sl::ViewSide* r = w_.viewport()->mainSide();
  const sl::Publication& pub = r->publication();
  const double got = rtwsettle::angleDeg(pub).value_or(std::nan(""));
  check(w_.lessons()->settled() && std::abs(sl::rtw::foldQuarterTurn(got - angle)) <= 2.0,
        tr("case %1: R settles at %2° within %3 frames (stated %4° ± 2°)")
            .arg(caseNumber)
            .arg(got, 0, 'f', 2)
            .arg(w_.lessons()->settleFrames())
            .arg(angle));
  std::printf("metric rotation_deg=%.3f\n", got);
  if (std::isfinite(about)) {
    const sl::ViewSide* split = w_.viewport()->splitSide();
    const double turned =
        split ? rtwsettle::angleDeg(split->publication()).value_or(std::nan("")) : std::nan("");
    check(std::abs(sl::rtw::foldQuarterTurn(turned)) >= about,
          tr("case %1: the right half turns by %2° (stated at least %3°)")
              .arg(caseNumber)
              .arg(turned, 0, 'f', 2)
              .arg(about));
  }
  PublicationPanel* covariance = nullptr;
  for (const PublicationDocks::Dock& d : w_.docks().docks())
    if (d.entry.id == QLatin1String("covariance")) covariance = d.panel;
  checkCovarianceReadouts(tr("case %1").arg(caseNumber));
  // The Turn prediction the text describes, drawn from the frame shown: its lowest points
  // where the text says ("lowest points at ±45°"), or no turn better by the margin.
  const QJsonObject drawn = covariance ? covariance->drawnValues() : QJsonObject();
  const QJsonArray ratios = drawn.value(QStringLiteral("prediction.ratios")).toArray();
  check(ratios.size() == 37 && drawn.value(QStringLiteral("prediction.markers")).toInt() >= 2,
        tr("case %1: the Turn prediction shows its curve (%2 points, frame %3, valid %4, state "
           "%5) and its markers (%6)")
            .arg(caseNumber)
            .arg(ratios.size())
            .arg(drawn.value(QStringLiteral("prediction.frame")).toDouble())
            .arg(drawn.value(QStringLiteral("prediction.valid")).toBool())
            .arg(drawn.value(QStringLiteral("state")).toString())
            .arg(drawn.value(QStringLiteral("prediction.markers")).toInt()));
  const double lowest = stated(text, QStringLiteral("lowest points at ±(\\d+)°"));
  if (std::isfinite(lowest) && ratios.size() == 37) {
    int k = 0;
    for (int i = 1; i < ratios.size(); ++i)
      if (ratios[i].toDouble(1e9) < ratios[k].toDouble(1e9)) k = i;
    const double at = -90.0 + 5.0 * k;
    check(std::abs(std::abs(at) - lowest) <= 5.0,
          tr("case %1: the predicted curve is lowest at %2° (%3 of now; stated ±%4°)")
              .arg(caseNumber)
              .arg(at)
              .arg(ratios[k].toDouble(), 0, 'f', 2)
              .arg(lowest));
    const double unturned = stated(text, QStringLiteral("at least (\\d+) times the score now"));
    if (std::isfinite(unturned))
      check(ratios[18].toDouble(0.0) >= unturned,
            tr("case %1: at 0° the prediction is %2 times the score now (stated at least %3)")
                .arg(caseNumber)
                .arg(ratios[18].toDouble(0.0), 0, 'f', 2)
                .arg(unturned));
  }
  if (text.contains(QStringLiteral("no turn is predicted better by more than the margin"))) {
    const double gain = pub.number("prediction.gain", std::nan(""));
    const double margin = pub.number("prediction.margin", std::nan(""));
    check(gain <= margin, tr("case %1: the best turn is predicted %2 better, the margin is %3")
                              .arg(caseNumber)
                              .arg(gain, 0, 'f', 3)
                              .arg(margin, 0, 'f', 2));
  }

  // The split view at the same texels: the lesson's partner on the right.
  waitForFrames(2);
  const auto main = w_.viewport()->measure()->computeErrorNow();
  waitForFrames(1);
  const auto split = w_.viewport()->measure()->splitErrorPct();
  const auto splitParams = w_.viewport()->frames()->splitParams();
  const QString splitRes = QString::fromStdString(
      splitParams.count("resolution") ? splitParams.at("resolution") : std::string("default"));
  const int mainRes = r->params().getInt("resolution");
  const std::string partner = c.compare ? c.compare->technique : std::string();
  check(w_.viewport()->frames()->splitTechnique() == partner && splitRes.toInt() == mainRes,
        tr("case %1: the split view compares %2 at the same %3 x %3 texels (right: %4)")
            .arg(caseNumber)
            .arg(QString::fromStdString(partner))
            .arg(mainRes)
            .arg(splitRes));
  const QString halves = tr("left (%1) %2 %, right (%3) %4 %")
                             .arg(QString::fromStdString(w_.viewport()->techniqueId()))
                             .arg(main.value_or(-1), 0, 'f', 3)
                             .arg(QString::fromStdString(partner))
                             .arg(split.value_or(-1), 0, 'f', 3);
  const double atMost = stated(
      text, QStringLiteral("at most (\\d+(?:\\.\\d+)?) times the right half's wrong pixels"));
  check(std::isfinite(atMost),
        tr("case %1: the text states one comparison of the halves").arg(caseNumber));
  if (std::isfinite(atMost))
    check(main && split && *main <= atMost * *split,
          tr("case %1: %2 (at most %3 x the right)").arg(caseNumber).arg(halves).arg(atMost));
}

void GuiTests::claimVibration(const QString& text) {
  const double pixels = stated(text, QStringLiteral("at least (\\d+) pixels change"));
  // The threshold is the lesson's parameter; the text quotes it live ({pca.threshold}).
  const sl::Preset* lesson = w_.lessons()->activePreset();
  const auto set =
      lesson ? lesson->params.find(rtwsettle::kThresholdKey) : decltype(lesson->params.end()){};
  const double threshold = lesson && set != lesson->params.end()
                               ? QString::fromStdString(set->second).toDouble()
                               : std::nan("");
  const QString shownText = w_.lessonPanel()->shownText();
  check(
      std::isfinite(pixels) && std::isfinite(threshold) &&
          shownText.contains(tr("the threshold is %1").arg(threshold, 0, 'f', 4)),
      tr("the text states the changed pixels and shows the lesson's threshold %1").arg(threshold));
  sl::ViewSide* r = w_.viewport()->mainSide();
  check(std::abs(r->params().get(rtwsettle::kThresholdKey) - threshold) < 1e-9,
        tr("%1 is %2")
            .arg(QLatin1String(rtwsettle::kThresholdKey))
            .arg(r->params().get(rtwsettle::kThresholdKey)));
  PublicationPanel* covariance = nullptr;
  for (const PublicationDocks::Dock& d : w_.docks().docks())
    if (d.entry.id == QLatin1String("covariance")) covariance = d.panel;
  const QString shown =
      covariance ? covariance->drawnValues().value(QStringLiteral("threshold_shown")).toString()
                 : QString();
  check(shown.toDouble() == threshold,
        tr("the gauge shows the threshold %1 (text: %2)").arg(shown).arg(threshold));
  // Changed pixels of the hard mask from one frame to the next, the view and camera still.
  auto changedPerFrame = [&](int frames) {
    std::vector<std::uint8_t> last = auto_.readback().hardMask;
    std::vector<std::size_t> counts;
    for (int k = 0; k < frames; ++k) {
      waitForFrames(1);
      std::vector<std::uint8_t> now = auto_.readback().hardMask;
      std::size_t c = 0;
      for (std::size_t i = 0; i < std::min(now.size(), last.size()); ++i) c += now[i] != last[i];
      counts.push_back(c);
      last = std::move(now);
    }
    return counts;
  };
  auto list = [](const std::vector<std::size_t>& v) {
    QStringList s;
    for (std::size_t c : v) s << QString::number(c);
    return s.join(QStringLiteral(", "));
  };
  const std::vector<std::size_t> shimmer = changedPerFrame(8);
  checkCovarianceReadouts(tr("threshold %1").arg(threshold));
  // The vibration is visible in the angle plot: its history starts at the settled state, so
  // the plot's range is the vibration's (a tenth of a degree), not the settling turn's.
  const QJsonObject plotted = covariance ? covariance->drawnValues() : QJsonObject();
  const double span = plotted.value(QStringLiteral("history.angle_max_deg")).toDouble() -
                      plotted.value(QStringLiteral("history.angle_min_deg")).toDouble();
  check(span > 1e-4 && span < 2.0,
        tr("the angle plot spans %1° over %2 frames: the vibration fills it")
            .arg(span, 0, 'g', 3)
            .arg(plotted.value(QStringLiteral("history.frames")).toInt()));
  std::size_t total = 0;
  for (std::size_t c : shimmer) total += c;
  check(double(total) >= pixels, tr("threshold %1: %2 pixels change per frame, %3 in 8 frames (at "
                                    "least %4)")
                                     .arg(threshold)
                                     .arg(list(shimmer))
                                     .arg(total)
                                     .arg(pixels));
  // The fix the text suggests: 0.9999 holds R, and nothing changes.
  if (auto e = r->params().setFromString(rtwsettle::kThresholdKey, "0.9999"))
    check(false, QString::fromStdString(*e));
  waitForFrames(3);
  const std::vector<std::size_t> held = changedPerFrame(3);
  check(std::all_of(held.begin(), held.end(), [](std::size_t c) { return c == 0; }),
        tr("threshold 0.9999: %1 pixels change per frame").arg(list(held)));
}

// --- Lessons 5 and 8-12 ------------------------------------------------------------------

GuiTests::LessonNumbers GuiTests::measureLesson() {
  const sl::Renderer::ErrorResult e = measureView();
  std::vector<float> ms;
  for (std::size_t i = 0; i < e.frame.aliasing.size(); ++i)
    if (covered(e.frame, i) && std::isfinite(e.frame.aliasing[i]) && e.frame.aliasing[i] > 0.0f)
      ms.push_back(e.frame.aliasing[i]);
  LessonNumbers n;
  n.errorPct = e.stats.errorPct;
  if (!ms.empty()) {
    const auto k = std::ptrdiff_t(double(ms.size() - 1) * 0.95);
    std::nth_element(ms.begin(), ms.begin() + k, ms.end());
    n.mP95 = double(ms[std::size_t(k)]);
  }
  const sl::FrameStats& s = w_.viewport()->mainSide()->stats();
  n.bytes = s.memory.bytes();
  n.frameMs = s.totalMs;
  std::printf("     %s: error %.3f %%, m p95 %.2f, %.2f MiB, %.0f ms (view %dx%d)\n",
              w_.viewport()->techniqueId().c_str(), n.errorPct, n.mP95,
              double(n.bytes) / (1024.0 * 1024.0), n.frameMs, e.frame.width, e.frame.height);
  std::fflush(stdout);
  return n;
}

void GuiTests::lessonSet(const char* key, const QString& value, int frames) {
  if (auto e = w_.viewport()->mainSide()->params().setFromString(key, value.toStdString()))
    check(false, QString::fromStdString(*e));
  check(auto_.waitForFrames(frames), tr("%1 frames after %2 = %3").arg(frames).arg(key, value));
}

void GuiTests::lessonSwitch(const QString& technique,
                            const std::vector<std::pair<const char*, QString>>& params, int frames,
                            int timeoutMs) {
  if (auto e = auto_.setTechnique(technique)) check(false, *e);
  check(w_.viewport()->techniqueId() == technique.toStdString(),
        tr("the technique is now %1").arg(technique));
  for (const auto& [key, value] : params)
    if (auto e = w_.viewport()->mainSide()->params().setFromString(key, value.toStdString()))
      check(false, QString::fromStdString(*e));
  check(auto_.waitForFrames(frames, timeoutMs),
        tr("%1 renders %2 frames within %3 s").arg(technique).arg(frames).arg(timeoutMs / 1000));
}

void GuiTests::claimForwardBackward(const QString& text) {
  const double ratio = stated(
      text, QStringLiteral("importance to at least (\\d+(?:\\.\\d+)?) times as many of the light"));
  const double sameWithin =
      stated(text, QStringLiteral("the errors stay within (\\d+) % of each other"));
  check(std::isfinite(ratio) && std::isfinite(sameWithin),
        tr("the text states the ratio of the texels given importance and the errors' difference"));
  sl::ViewSide* r = w_.viewport()->mainSide();
  const QString resolution = QString::number(r->params().getInt("resolution"));
  const auto forwardIm = rtwsettle::importanceCoverage(r->publication());
  const LessonNumbers forward = measureLesson();
  // Backward analysis at the same texels, nothing else changed.
  lessonSwitch(QStringLiteral("rtw-backward"), {{"resolution", resolution}});
  const auto backwardIm = rtwsettle::importanceCoverage(r->publication());
  const LessonNumbers backward = measureLesson();
  check(forwardIm && backwardIm && forwardIm->first >= ratio * backwardIm->first,
        tr("the light's texels given importance: forward %1 %, backward %2 % of %3: %4x (at least "
           "%5x)")
            .arg(forwardIm ? 100.0 * forwardIm->first : -1.0, 0, 'f', 1)
            .arg(backwardIm ? 100.0 * backwardIm->first : -1.0, 0, 'f', 1)
            .arg(forwardIm ? forwardIm->second : 0)
            .arg(forwardIm && backwardIm && backwardIm->first > 0
                     ? forwardIm->first / backwardIm->first
                     : 0.0,
                 0, 'f', 2)
            .arg(ratio));
  check(std::abs(backward.errorPct - forward.errorPct) <= sameWithin / 100.0 * forward.errorPct,
        tr("at %1 x %1 texels: rtw-forward %2 % error, rtw-backward %3 % (within %4 % of each "
           "other)")
            .arg(resolution)
            .arg(forward.errorPct, 0, 'f', 3)
            .arg(backward.errorPct, 0, 'f', 3)
            .arg(sameWithin));
}

void GuiTests::claimPerspectiveWarp(const QString& text) {
  const double errRatio =
      stated(text, QStringLiteral("the error falls at least (\\d+(?:\\.\\d+)?) times"));
  const double mRatio =
      stated(text, QStringLiteral("95th percentile at least (\\d+(?:\\.\\d+)?) times"));
  check(std::isfinite(errRatio) && std::isfinite(mRatio),
        tr("the text states how far the error and m's 95th percentile fall"));
  // Only Warp eta changes: -1 (uniform), 0 (LiSPSM, the lesson's state), 1 (PSM).
  const LessonNumbers lispsm = measureLesson();
  lessonSet("warp.eta", QStringLiteral("-1"));
  const LessonNumbers uniform = measureLesson();
  lessonSet("warp.eta", QStringLiteral("1"));
  const LessonNumbers psm = measureLesson();
  lessonSet("warp.eta", QStringLiteral("0"));
  check(uniform.errorPct >= errRatio * lispsm.errorPct && uniform.mP95 >= mRatio * lispsm.mP95,
        tr("η = -1: error %1 %, m p95 %2; η = 0: %3 %, %4: the error falls %5x (at least %6x), "
           "m p95 %7x (at least %8x)")
            .arg(uniform.errorPct, 0, 'f', 2)
            .arg(uniform.mP95, 0, 'f', 1)
            .arg(lispsm.errorPct, 0, 'f', 2)
            .arg(lispsm.mP95, 0, 'f', 1)
            .arg(lispsm.errorPct > 0 ? uniform.errorPct / lispsm.errorPct : 0.0, 0, 'f', 1)
            .arg(errRatio)
            .arg(lispsm.mP95 > 0 ? uniform.mP95 / lispsm.mP95 : 0.0, 0, 'f', 1)
            .arg(mRatio));
  check(psm.errorPct > lispsm.errorPct && psm.mP95 > lispsm.mP95,
        tr("η = 1 (towards PSM): error %1 %, m p95 %2, both above η = 0's")
            .arg(psm.errorPct, 0, 'f', 2)
            .arg(psm.mP95, 0, 'f', 1));
}

void GuiTests::claimDuelingFrusta(const QString& text) {
  const double side = stated(text, QStringLiteral("against one of (\\d+)²"));
  const double factor =
      stated(text, QStringLiteral("error is at most (\\d+(?:\\.\\d+)?) times theirs"));
  check(std::isfinite(side) && std::isfinite(factor),
        tr("the text states the equal-texel map and the factor"));
  sl::ViewSide* r = w_.viewport()->mainSide();
  const int res = r->params().getInt("resolution");
  const LessonNumbers faces = measureLesson();
  const std::uint64_t faceTexels = faces.bytes / 4;
  lessonSwitch(QStringLiteral("lispsm"), {{"resolution", QString::number(side)}});
  const LessonNumbers lispsm = measureLesson();
  lessonSwitch(QStringLiteral("uniform"), {{"resolution", QString::number(side)}});
  const LessonNumbers uniform = measureLesson();
  const double single = side * side;
  check(std::abs(double(faceTexels) - single) <= 0.01 * single,
        tr("the same texels: face-partition %1 (%2 B, 5 maps of %3 x %3), one map of %4 x %4: %5")
            .arg(faceTexels)
            .arg(faces.bytes)
            .arg(res)
            .arg(side)
            .arg(single, 0, 'f', 0));
  check(faces.errorPct <= factor * lispsm.errorPct && faces.errorPct <= factor * uniform.errorPct,
        tr("error: face-partition %1 %, lispsm %2 %, uniform %3 % (face-partition at most %4x)")
            .arg(faces.errorPct, 0, 'f', 3)
            .arg(lispsm.errorPct, 0, 'f', 3)
            .arg(uniform.errorPct, 0, 'f', 3)
            .arg(factor));
  // lispsm falls back to the uniform map: the same shadows.
  check(std::abs(lispsm.errorPct - uniform.errorPct) <= 0.01,
        tr("lispsm falls back to the uniform map: %1 % and %2 %")
            .arg(lispsm.errorPct, 0, 'f', 3)
            .arg(uniform.errorPct, 0, 'f', 3));
}

void GuiTests::claimCascades(const QString& text) {
  const double last = stated(text, QStringLiteral("maps 0 to (\\d+) have m p95 within"));
  const double spread =
      stated(text, QStringLiteral("m p95 within a factor (\\d+(?:\\.\\d+)?) of each other"));
  const double drop =
      stated(text, QStringLiteral("map 0's m p95 falls at least (\\d+(?:\\.\\d+)?) times"));
  check(std::isfinite(last) && std::isfinite(spread) && std::isfinite(drop),
        tr("the text states the log split's spread and map 0's fall"));
  sl::ViewSide* r = w_.viewport()->mainSide();
  const int k = r->params().getInt("partitions");
  // Each map's m p95 over the pixels that selected it, as the Partitions panel shows it.
  auto perMap = [&]() {
    std::vector<double> p95;
    const auto& n = r->publication().numbers;
    for (int i = 0; i < k; ++i) {
      const std::string key = "partition." + std::to_string(i) + ".m.";
      const auto pixels = n.find(key + "pixels"), m = n.find(key + "p95");
      p95.push_back(pixels != n.end() && m != n.end() && pixels->second > 0 ? m->second
                                                                            : std::nan(""));
    }
    return p95;
  };
  auto list = [](const std::vector<double>& v) {
    QStringList s;
    for (double x : v) s << (std::isfinite(x) ? QString::number(x, 'f', 1) : QStringLiteral("-"));
    return s.join(QStringLiteral(", "));
  };
  waitForFrames(2);
  const std::vector<double> uniform = perMap();
  const LessonNumbers uniformN = measureLesson();
  lessonSet("split", QStringLiteral("log"), 3);
  const std::vector<double> log = perMap();
  const LessonNumbers logN = measureLesson();
  double lo = INFINITY, hi = 0.0;
  int used = 0;
  for (std::size_t i = 0; i < log.size() && double(i) <= last; ++i)
    if (std::isfinite(log[i])) lo = std::min(lo, log[i]), hi = std::max(hi, log[i]), ++used;
  check(used >= 2 && double(used) == last + 1 && hi <= spread * lo,
        tr("log split: the maps' m p95 %1; maps 0 to %2 within a factor %3 (at most %4)")
            .arg(list(log))
            .arg(last)
            .arg(used ? hi / lo : 0.0, 0, 'f', 1)
            .arg(spread));
  check(!uniform.empty() && !log.empty() && uniform[0] >= drop * log[0],
        tr("map 0's m p95: %1 with the uniform split, %2 with log: %3x (at least %4x); error %5 % "
           "and %6 %")
            .arg(uniform.empty() ? -1.0 : uniform[0], 0, 'f', 1)
            .arg(log.empty() ? -1.0 : log[0], 0, 'f', 1)
            .arg(!uniform.empty() && !log.empty() && log[0] > 0 ? uniform[0] / log[0] : 0.0, 0, 'f',
                 1)
            .arg(drop)
            .arg(uniformN.errorPct, 0, 'f', 2)
            .arg(logN.errorPct, 0, 'f', 2));
  check(logN.errorPct < uniformN.errorPct, tr("the error falls with log: %1 % to %2 %")
                                               .arg(uniformN.errorPct, 0, 'f', 2)
                                               .arg(logN.errorPct, 0, 'f', 2));
}

void GuiTests::claimOmni(const QString& text) {
  const double dpMiB = stated(text, QStringLiteral("2 × 2048² = (\\d+) MiB"));
  const double cubeMiB = stated(text, QStringLiteral("the cube's 6 × 1024² = (\\d+) MiB"));
  const double same =
      stated(text, QStringLiteral("the same error here, within a factor (\\d+(?:\\.\\d+)?)"));
  const double tessRatio =
      stated(text, QStringLiteral("at least (\\d+(?:\\.\\d+)?) times the error tessellated"));
  check(std::isfinite(dpMiB) && std::isfinite(cubeMiB) && std::isfinite(same) &&
            std::isfinite(tessRatio),
        tr("the text states both memories, the error factor and the tessellation ratio"));
  const LessonNumbers off = measureLesson();
  lessonSet("tessellation", QStringLiteral("on"), 3);
  const LessonNumbers dp = measureLesson();
  lessonSwitch(QStringLiteral("cube"), {});
  const LessonNumbers cube = measureLesson();
  const double MiB = 1024.0 * 1024.0;
  check(double(dp.bytes) == dpMiB * MiB && double(cube.bytes) == cubeMiB * MiB,
        tr("memory: dual paraboloid %1 MiB, cube %2 MiB (stated %3 and %4)")
            .arg(double(dp.bytes) / MiB, 0, 'f', 2)
            .arg(double(cube.bytes) / MiB, 0, 'f', 2)
            .arg(dpMiB)
            .arg(cubeMiB));
  check(off.errorPct >= tessRatio * dp.errorPct,
        tr("dual paraboloid: error %1 % without tessellation, %2 % with it: %3x (at least %4x)")
            .arg(off.errorPct, 0, 'f', 3)
            .arg(dp.errorPct, 0, 'f', 3)
            .arg(dp.errorPct > 0 ? off.errorPct / dp.errorPct : 0.0, 0, 'f', 1)
            .arg(tessRatio));
  check(dp.errorPct <= same * cube.errorPct && cube.errorPct <= same * dp.errorPct,
        tr("about the same error: dual paraboloid %1 %, cube %2 % (within %3x)")
            .arg(dp.errorPct, 0, 'f', 3)
            .arg(cube.errorPct, 0, 'f', 3)
            .arg(same));
}

void GuiTests::claimFvsm(const QString& text) {
  const double tiles = stated(text, QStringLiteral("Tiles per axis (\\d+) and Tile resolution"));
  const double tileRes = stated(text, QStringLiteral("and Tile resolution (\\d+)"));
  const double errFactor = stated(
      text, QStringLiteral("fvsm's error is at most (\\d+(?:\\.\\d+)?) times virtual-tiled's"));
  const double timeFactor =
      stated(text, QStringLiteral("in at most (\\d+(?:\\.\\d+)?) times its frame time"));
  check(std::isfinite(tiles) && std::isfinite(tileRes) && std::isfinite(errFactor) &&
            std::isfinite(timeFactor),
        tr("the text states the small brute-force budget, the error and the time factors"));
  // Frame times are wall clock on a shared machine (ctest runs two tests at once): each side's
  // time is its best of three frames, so a load spike in one frame does not decide the claim.
  const auto bestFrameMs = [this](double ms) {
    for (int i = 0; i < 2; ++i) {
      check(auto_.waitForFrames(1, 240000), tr("one more frame to time"));
      ms = std::min(ms, w_.viewport()->mainSide()->stats().totalMs);
    }
    return ms;
  };
  LessonNumbers fvsm = measureLesson();
  fvsm.frameMs = bestFrameMs(fvsm.frameMs);
  // The brute force at the small budget only (the full 16 x 16 tiles of 4096 x 4096 take tens
  // of seconds a frame here).
  lessonSwitch(QStringLiteral("virtual-tiled"),
               {{"tiles", QString::number(tiles)}, {"tile.resolution", QString::number(tileRes)}},
               2, 240000);
  LessonNumbers small = measureLesson();
  small.frameMs = bestFrameMs(small.frameMs);
  check(fvsm.errorPct <= errFactor * small.errorPct && fvsm.frameMs <= timeFactor * small.frameMs,
        tr("fvsm: %1 % error in %2 ms; virtual-tiled, %3 x %3 tiles of %4 x %4 texels: %5 % in "
           "%6 ms (fvsm at most %7x the error in at most %8x the time)")
            .arg(fvsm.errorPct, 0, 'f', 4)
            .arg(fvsm.frameMs, 0, 'f', 0)
            .arg(tiles)
            .arg(tileRes)
            .arg(small.errorPct, 0, 'f', 4)
            .arg(small.frameMs, 0, 'f', 0)
            .arg(errFactor)
            .arg(timeFactor));
}

// Lesson 13: asm misses the thin pole's shadow, rmsm on the other side draws it (at most a third
// of asm's wrong pixels); the Pages panel shows why (only the coarse map held, nothing requested);
// at about the same memory uniform 2048² and rtw-backward 1024² on the other side beat asm too.
// The text quotes the errors live; the counts of pages are facts of the lesson's settings.
void GuiTests::claimAsm(const QString& text) {
  const double coarse = stated(text, QStringLiteral("holds only the (\\d+) pages of its coarse"));
  const double asked = stated(text, QStringLiteral("requests (\\d+) pages"));
  check(std::isfinite(coarse) && std::isfinite(asked), tr("the text states asm's pages"));
  auto pct = [](std::optional<double> v) { return v ? QString::number(*v, 'f', 3) : tr("none"); };
  waitForFrames(2);
  auto main = w_.viewport()->measure()->computeErrorNow();
  waitForFrames(1);
  auto split = w_.viewport()->measure()->splitErrorPct();
  check(
      w_.viewport()->frames()->splitTechnique() == "rmsm" && split && main && *split < *main / 3.0,
      tr("asm %1 % error, rmsm %2 % (at most a third)").arg(pct(main)).arg(pct(split)));
  PublicationPanel* pagesPanel = nullptr;
  for (const PublicationDocks::Dock& d : w_.docks().docks())
    if (d.entry.id == QLatin1String("pages")) pagesPanel = d.panel;
  const QJsonObject drawn = pagesPanel ? pagesPanel->drawnValues() : QJsonObject();
  const QJsonObject cells = drawn.value(QStringLiteral("cells")).toObject();
  const int held = cells.value(QStringLiteral("new")).toInt() +
                   cells.value(QStringLiteral("cached_hit")).toInt() +
                   cells.value(QStringLiteral("cached_idle")).toInt();
  check(pagesPanel && drawn.value(QStringLiteral("cache")).toBool() && held == int(coarse) &&
            drawn.value(QStringLiteral("requested")).toDouble() == asked,
        tr("the Pages panel draws %1 pages held (text: %2), %3 requested (text: %4)")
            .arg(held)
            .arg(coarse)
            .arg(drawn.value(QStringLiteral("requested")).toDouble())
            .arg(asked));
  // The other side at about the same memory.
  for (const auto& [id, resolution] : {std::pair{"uniform", "2048"}, {"rtw-backward", "1024"}}) {
    if (auto e = w_.viewport()->frames()->setSplitTechnique(id, {{"resolution", resolution}}))
      check(false, QString::fromStdString(*e));
    waitForFrames(3);
    main = w_.viewport()->measure()->computeErrorNow();
    waitForFrames(1);
    split = w_.viewport()->measure()->splitErrorPct();
    check(split && main && *split < *main,
          tr("%1 at %2 x %2 texels: %3 %, asm %4 %")
              .arg(QLatin1String(id), QLatin1String(resolution), pct(split))
              .arg(pct(main)));
  }
}

}  // namespace sl::ui
