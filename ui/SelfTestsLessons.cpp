// The lesson-claims self-test (see SelfTests.h): every lesson opened fresh through the Lessons
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
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QJsonObject>
#include <QRegularExpression>

#include <glm/glm.hpp>

#include "LessonController.h"
#include "MainWindow.h"
#include "PublicationDocks.h"
#include "SelfTests.h"
#include "ViewportWidget.h"
#include "panels/common/PanelKit.h"
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

sl::Renderer::ErrorResult SelfTests::measureView() {
  w_.viewport_->makeCurrent();
  sl::Renderer::ErrorResult e = w_.viewport_->renderer()->computeError();
  w_.viewport_->doneCurrent();
  return e;
}

bool SelfTests::lessonClaims(const QString& dir) {
  // The lesson the app was started with (--lesson), as a student opens it: a fresh process,
  // the window's own start-up, the lesson settled before this runs.
  const int index = w_.lessons_->index();
  check(index >= 0, tr("started with --lesson"));
  if (index < 0) return false;
  const Lesson& lesson = w_.lessons_->lessons()[static_cast<std::size_t>(index)];
  const QString name = QFileInfo(lesson.path).completeBaseName();
  const sl::Preset& p = lesson.preset;
  const QString text = QString::fromStdString(p.explanation);
  std::printf("---- lesson %d: %s\n", index + 1, qPrintable(name));
  std::fflush(stdout);
  check(w_.viewport_->techniqueId() == p.technique && !w_.lessons_->settling(),
        tr("opens with %1 on %2, its temporal state settled or none (%3 settling frames)")
            .arg(QString::fromStdString(w_.viewport_->techniqueId()), w_.sceneSpec_)
            .arg(w_.lessons_->settleFrames()));
  std::printf("     window %dx%d, view %dx%d\n", w_.width(), w_.height(), w_.viewport_->width(),
              w_.viewport_->height());
  if (!dir.isEmpty() && QDir().mkpath(dir))
    w_.grab().toImage().save(QDir(dir).filePath(name + QStringLiteral(".png")));
  if (p.layout) lessonLayout(*p.layout);
  if (name.endsWith(QLatin1String("perspective-aliasing")))
    claimPerspective(text);
  else if (name.endsWith(QLatin1String("projective-aliasing")))
    claimProjective(text);
  else if (name.endsWith(QLatin1String("tessellation")))
    claimTessellation(text);
  else if (name.endsWith(QLatin1String("rtw-warping")))
    claimRtw();
  else if (name.endsWith(QLatin1String("diagonal-pca")))
    claimPca(text);
  else if (name.endsWith(QLatin1String("vibration-threshold")))
    claimVibration(text);
  else if (name.endsWith(QLatin1String("asm-vs-rmsm")))
    claimAsm(text);
  return true;
}

void SelfTests::lessonLayout(const sl::PresetLayout& layout) {
  QCoreApplication::processEvents();
  for (QDockWidget* dock : w_.findChildren<QDockWidget*>()) {
    const bool listed = std::find(layout.docks.begin(), layout.docks.end(),
                                  dock->objectName().toStdString()) != layout.docks.end();
    if (!listed && dock->isVisible()) check(false, tr("dock %1 is hidden").arg(dock->objectName()));
  }
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

void SelfTests::claimPerspective(const QString& text) {
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

void SelfTests::claimProjective(const QString& text) {
  const double ratio = stated(text, QStringLiteral("at least (\\d+(?:\\.\\d+)?) times"));
  const double high = stated(text, QStringLiteral("raise the sun to (\\d+)°"));
  check(std::isfinite(ratio) && std::isfinite(high), tr("the text states the ratio and the sun"));
  // The floor 5-30 m from the camera: its median m at the lesson's low sun, then with only
  // the sun's elevation changed.
  const glm::vec3 eye = w_.viewport_->camera().position;
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
  const sl::Light low = w_.viewport_->light();
  const auto [lowM, lowN] = floorMedian();
  sl::Light raised = low;
  raised.elevationDeg = float(high);
  w_.viewport_->setLight(raised);
  w_.waitForFrames(2);
  const auto [highM, highN] = floorMedian();
  w_.viewport_->setLight(low);
  w_.waitForFrames(1);
  check(lowN > 1000 && highN > 1000 && lowM >= ratio * highM,
        tr("the floor 5-30 m away: median m %1 with the sun at %2°, %3 at %4°: %5x (at least %6x)")
            .arg(lowM, 0, 'f', 2)
            .arg(double(low.elevationDeg))
            .arg(highM, 0, 'f', 2)
            .arg(high)
            .arg(lowM / highM, 0, 'f', 2)
            .arg(ratio));
}

void SelfTests::claimTessellation(const QString& text) {
  const double ratio =
      stated(text, QStringLiteral("without tessellation is at least (\\d+) times"));
  check(std::isfinite(ratio), tr("the text states the ratio"));
  sl::Renderer* r = w_.viewport_->renderer();
  const auto off = w_.viewport_->computeErrorNow();
  if (auto e = r->params().setFromString("tessellation", "on"))
    check(false, QString::fromStdString(*e));
  w_.waitForFrames(2);
  const auto on = w_.viewport_->computeErrorNow();
  check(off && on && *off >= ratio * *on,
        tr("error %1 % without tessellation, %2 % with it: %3x (at least %4x)")
            .arg(off.value_or(-1), 0, 'f', 2)
            .arg(on.value_or(-1), 0, 'f', 2)
            .arg(off && on && *on > 0 ? *off / *on : 0.0, 0, 'f', 1)
            .arg(ratio));
}

void SelfTests::claimRtw() {
  w_.waitForFrames(2);
  const auto main = w_.viewport_->computeErrorNow();
  w_.waitForFrames(1);
  const auto split = w_.viewport_->splitErrorPct();
  sl::Renderer* r = w_.viewport_->renderer();
  check(w_.viewport_->splitTechnique() == "uniform" && main && split && *main < *split,
        tr("%1 at %2 x %2 texels: %3 % error; %4 at %5 x %5: %6 %")
            .arg(QString::fromStdString(w_.viewport_->techniqueId()))
            .arg(r->params().getInt("resolution"))
            .arg(main.value_or(-1), 0, 'f', 3)
            .arg(QString::fromStdString(w_.viewport_->splitTechnique()))
            .arg(QString::fromStdString(w_.viewport_->splitParams().count("resolution")
                                            ? w_.viewport_->splitParams().at("resolution")
                                            : "default"))
            .arg(split.value_or(-1), 0, 'f', 3));
}

void SelfTests::claimPca(const QString& text) {
  const double angle = stated(text, QStringLiteral("settles at ([\\x{2212}-]?\\d+(?:\\.\\d+)?)°"));
  check(std::isfinite(angle), tr("the text states the settled angle"));
  PublicationPanel* covariance = nullptr;
  for (const PublicationDocks::Dock& d : w_.docks_.docks())
    if (d.entry.id == QLatin1String("covariance")) covariance = d.panel;
  // Once per process: tests/gui/lesson_claims.sh starts the app twice for this lesson.
  const double got =
      rtwsettle::angleDeg(w_.viewport_->renderer()->publication()).value_or(std::nan(""));
  check(w_.lessons_->settled() && std::abs(got - angle) <= 2.0,
        tr("R settles at %1° within %2 frames (stated %3° ± 2°)")
            .arg(got, 0, 'f', 2)
            .arg(w_.lessons_->settleFrames())
            .arg(angle));
  std::printf("metric rotation_deg=%.3f\n", got);
  // Complete when it opens: the panel already shows the settled state (axis along x).
  const QJsonObject drawn = covariance ? covariance->drawnValues() : QJsonObject();
  const double ex = drawn.value(QLatin1String(rtwsettle::kExKey)).toDouble(0.0);
  check(ex > 0.999, tr("Covariance shows e_x = %1 when the lesson opens").arg(ex));
}

void SelfTests::claimVibration(const QString& text) {
  const double pixels = stated(text, QStringLiteral("at least (\\d+) pixels change"));
  const double threshold = stated(text, QStringLiteral("the threshold is (\\d\\.\\d+)"));
  check(std::isfinite(pixels) && std::isfinite(threshold),
        tr("the text states the changed pixels and the threshold"));
  sl::Renderer* r = w_.viewport_->renderer();
  check(std::abs(r->params().get(rtwsettle::kThresholdKey) - threshold) < 1e-9,
        tr("%1 is %2")
            .arg(QLatin1String(rtwsettle::kThresholdKey))
            .arg(r->params().get(rtwsettle::kThresholdKey)));
  PublicationPanel* covariance = nullptr;
  for (const PublicationDocks::Dock& d : w_.docks_.docks())
    if (d.entry.id == QLatin1String("covariance")) covariance = d.panel;
  const QString shown =
      covariance ? covariance->drawnValues().value(QStringLiteral("threshold_shown")).toString()
                 : QString();
  check(shown.toDouble() == threshold,
        tr("the gauge shows the threshold %1 (text: %2)").arg(shown).arg(threshold));
  // Changed pixels of the hard mask from one frame to the next, the view and camera still.
  auto changedPerFrame = [&](int frames) {
    w_.viewport_->makeCurrent();
    std::vector<std::uint8_t> last = r->readback().hardMask;
    w_.viewport_->doneCurrent();
    std::vector<std::size_t> counts;
    for (int k = 0; k < frames; ++k) {
      w_.waitForFrames(1);
      w_.viewport_->makeCurrent();
      std::vector<std::uint8_t> now = r->readback().hardMask;
      w_.viewport_->doneCurrent();
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
  w_.waitForFrames(3);
  const std::vector<std::size_t> held = changedPerFrame(3);
  check(std::all_of(held.begin(), held.end(), [](std::size_t c) { return c == 0; }),
        tr("threshold 0.9999: %1 pixels change per frame").arg(list(held)));
}

// Lesson 13: asm misses the thin pole's shadow (its error as stated), rmsm on the other side
// draws it; the Pages panel shows why (only the coarse map held, nothing requested); at about
// the same memory uniform 2048² and rtw-backward 1024² on the other side give the stated errors.
void SelfTests::claimAsm(const QString& text) {
  const double asmPct = stated(text, QStringLiteral("no shadow at all \\(([0-9.]+) %"));
  const double rmsmPct = stated(text, QStringLiteral("draws it \\(([0-9.]+) %\\)"));
  const double coarse = stated(text, QStringLiteral("holds only the (\\d+) pages of its coarse"));
  const double asked = stated(text, QStringLiteral("requests (\\d+) pages"));
  const double uniformPct = stated(text, QStringLiteral("uniform at 2048 \\(([0-9.]+) %\\)"));
  const double rtwPct = stated(text, QStringLiteral("rtw-backward at 1024 \\(([0-9.]+) %\\)"));
  check(std::isfinite(asmPct) && std::isfinite(rmsmPct) && std::isfinite(coarse) &&
            std::isfinite(asked) && std::isfinite(uniformPct) && std::isfinite(rtwPct),
        tr("the text states asm's, rmsm's, uniform's and rtw's errors and asm's pages"));
  // The text's numbers have two decimals: within 0.01 of the measured ones.
  auto near = [](std::optional<double> got, double want) {
    return got && std::abs(*got - want) <= 0.01;
  };
  auto pct = [](std::optional<double> v) { return v ? QString::number(*v, 'f', 3) : tr("none"); };
  w_.waitForFrames(2);
  auto main = w_.viewport_->computeErrorNow();
  w_.waitForFrames(1);
  auto split = w_.viewport_->splitErrorPct();
  check(w_.viewport_->splitTechnique() == "rmsm" && near(main, asmPct) && near(split, rmsmPct) &&
            split && main && *split < *main / 3.0,
        tr("asm %1 % error (text: %2), rmsm %3 % (text: %4)")
            .arg(pct(main))
            .arg(asmPct)
            .arg(pct(split))
            .arg(rmsmPct));
  PublicationPanel* pagesPanel = nullptr;
  for (const PublicationDocks::Dock& d : w_.docks_.docks())
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
  for (const auto& [id, resolution, want] :
       {std::tuple{"uniform", "2048", uniformPct}, {"rtw-backward", "1024", rtwPct}}) {
    if (auto e = w_.viewport_->setSplitTechnique(id, {{"resolution", resolution}}))
      check(false, QString::fromStdString(*e));
    w_.waitForFrames(3);
    main = w_.viewport_->computeErrorNow();
    w_.waitForFrames(1);
    split = w_.viewport_->splitErrorPct();
    check(near(split, want) && split && main && *split < *main,
          tr("%1 at %2²: %3 % (text: %4), asm %5 %")
              .arg(QLatin1String(id), QLatin1String(resolution), pct(split))
              .arg(want)
              .arg(pct(main)));
  }
}

}  // namespace sl::ui
