// The GUI tests (`shadowlab-gui-tests --test NAME`, driven by tests/gui/*.sh under Xvfb). They
// act as a user would — typing into the generated parameter editors, going through
// File > Open with Qt's own file dialog, reading the message box — and check what the
// renderer and the window did. Each check prints "ok   ..." or "FAIL ..."; exit 0 = pass.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDragEnterEvent>
#include <QDir>
#include <QFile>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QFileInfo>
#include <QImage>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMouseEvent>
#include <QMessageBox>
#include <QMimeData>
#include <QRegularExpression>
#include <QSlider>
#include <QSpinBox>
#include <QStatusBar>
#include <QTimer>
#include <QUrl>

#include "GuiTests.h"

#include "teaching/LessonController.h"
#include "window/MainWindow.h"
#include "window/MessageText.h"
#include "teaching/PassStepper.h"
#include "window/SessionFiles.h"
#include "teaching/TeachingBar.h"
#include "view/ViewportWidget.h"
#include "algo/omni/OmniMapping.h"
#include "panels/common/ChartsPanel.h"
#include "panels/common/ParamPanel.h"

namespace sl::ui {

namespace {
constexpr qint64 kStartTimeoutMs = 120000;

/// Types `text` into a spin box like a user (select all, keys, Return).
void typeInto(QAbstractSpinBox* spin, const QString& text) {
  spin->setFocus(Qt::OtherFocusReason);
  if (auto* edit = spin->findChild<QLineEdit*>()) edit->selectAll();
  for (const QChar ch : text) {
    QKeyEvent press(QEvent::KeyPress, ch.unicode(), Qt::NoModifier, QString(ch));
    QApplication::sendEvent(spin, &press);
    QKeyEvent release(QEvent::KeyRelease, ch.unicode(), Qt::NoModifier, QString(ch));
    QApplication::sendEvent(spin, &release);
  }
  QKeyEvent enter(QEvent::KeyPress, Qt::Key_Return, Qt::NoModifier);
  QApplication::sendEvent(spin, &enter);
}

double meanLuminance(const QImage& image) {
  const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
  double sum = 0;
  for (int y = 0; y < rgb.height(); ++y) {
    const auto* line = reinterpret_cast<const QRgb*>(rgb.constScanLine(y));
    for (int x = 0; x < rgb.width(); ++x) sum += qGray(line[x]);
  }
  return rgb.isNull() ? 0.0 : sum / (double(rgb.width()) * rgb.height());
}

QString number(double v) {
  return QString::number(v, 'g', 10);
}
}  // namespace

const std::vector<GuiTests::Test>& GuiTests::all() {
  static const std::vector<Test> tests = {
      {"params", "", [](GuiTests& t, const QString&) { return t.params(); }},
      {"bad-gltf", "=FILE[,FILE...]", [](GuiTests& t, const QString& a) { return t.badGltf(a); }},
      {"bad-session", "=FILE[,FILE...]",
       [](GuiTests& t, const QString& a) { return t.badSession(a); }},
      {"teaching", "[=DIR]", [](GuiTests& t, const QString& a) { return t.teaching(a); }},
      {"charts", "[=DIR]", [](GuiTests& t, const QString& a) { return t.charts(a); }},
      {"split-resize", "[=TECHNIQUE]",
       [](GuiTests& t, const QString& a) { return t.splitResize(a); }},
      {"omni-probe", "[=DIR]", [](GuiTests& t, const QString& a) { return t.omniProbe(a); }},
      {"session-save", "=FILE", [](GuiTests& t, const QString& a) { return t.sessionSave(a); }},
      {"session-check", "", [](GuiTests& t, const QString&) { return t.sessionCheck(); }},
      {"output-policy", "=DIR", [](GuiTests& t, const QString& a) { return t.outputPolicy(a); }},
      {"presenter", "[=DIR]", [](GuiTests& t, const QString& a) { return t.presenter(a); }},
      {"split-params", "[=DIR]", [](GuiTests& t, const QString& a) { return t.splitParams(a); }},
      {"lesson-claims", "[=DIR]", [](GuiTests& t, const QString& a) { return t.lessonClaims(a); }},
      {"live-error", "[=DIR]", [](GuiTests& t, const QString& a) { return t.liveError(a); }},
      {"adaptive-resolution", "[=DIR]",
       [](GuiTests& t, const QString& a) { return t.adaptiveResolution(a); }},
      {"no-freeze", "[=DIR]", [](GuiTests& t, const QString& a) { return t.noFreeze(a); }},
      {"heartbeat", "[=DIR]", [](GuiTests& t, const QString& a) { return t.heartbeat(a); }},
      {"storage-click", "[=DIR]", [](GuiTests& t, const QString& a) { return t.storageClick(a); }},
      {"panels", "", [](GuiTests& t, const QString&) { return t.panelsFollowTechnique(); }},
      {"course", "[=DIR]", [](GuiTests& t, const QString& a) { return t.course(a); }},
      {"course-claims", "[=DIR]", [](GuiTests& t, const QString& a) { return t.courseClaims(a); }},
      {"course-grabs", "=DIR", [](GuiTests& t, const QString& a) { return t.courseGrabs(a); }},
      {"shortcuts", "", [](GuiTests& t, const QString&) { return t.shortcuts(); }},
      {"turn-prediction", "[=DIR]",
       [](GuiTests& t, const QString& a) { return t.turnPrediction(a); }},
  };
  return tests;
}

const GuiTests::Test* GuiTests::find(const QString& name) {
  for (const Test& t : all())
    if (name == QLatin1String(t.name)) return &t;
  return nullptr;
}

QString GuiTests::usage() {
  QStringList forms;
  for (const Test& t : all())
    forms << QString::fromLatin1(t.name) + QString::fromLatin1(t.argument);
  return forms.join(QStringLiteral(", "));
}

GuiTests::GuiTests(MainWindow& window)
    : QObject(&window), w_(window), auto_(*new Automation(window)) {}

void GuiTests::start(const Test& test, const QString& argument) {
  argument_ = argument;
  failures_ = 0;
  auto_.whenReady([this, &test] { run(test); },
                  [this](const QString& why) {
                    w_.report(tr("GUI test: %1").arg(why));
                    QCoreApplication::exit(1);
                  },
                  kStartTimeoutMs);
}

void GuiTests::run(const Test& test) {
  std::printf("GUI test %s: technique %s, scene %s\n", test.name,
              w_.viewport()->techniqueId().c_str(), qPrintable(auto_.sceneShown()));
  const bool ran = test.run(*this, argument_);
  const bool pass = ran && failures_ == 0;
  std::printf("%s\n", pass ? "PASS" : "FAIL");
  std::fflush(stdout);
  QCoreApplication::exit(pass ? 0 : 1);
}

bool GuiTests::splitResize(const QString& splitTechnique) {
  // Both halves measured, the window shrunk until the view is a few pixels, then restored:
  // the same view must measure the same errors (the renderers' size-dependent state
  // follows the restored size).
  const QString other = splitTechnique.isEmpty() ? QStringLiteral("rtw-backward") : splitTechnique;
  if (auto e = w_.viewport()->frames()->setSplitTechnique(other.toStdString())) {
    check(false, QString::fromStdString(*e));
    return false;
  }
  // The view pinned to its current size, so that "before" and "after" are the same frame.
  const QSize viewBefore = w_.viewport()->size();
  w_.viewport()->setFixedSize(viewBefore);
  QCoreApplication::processEvents();
  waitForFrames(3);
  const auto mainBefore = w_.viewport()->measure()->computeErrorNow();
  const auto splitBefore = w_.viewport()->measure()->splitErrorPct();
  // Every size a window dragged to its smallest can leave the view (each half 0-2 pixels).
  const QString tech = QString::fromStdString(w_.viewport()->techniqueId());
  for (const int side : {3, 2, 1, 0}) {
    QStringList problems;
    const auto connection = connect(w_.viewport(), &ViewportWidget::renderProblem, this,
                                    [&problems](const QString& p) { problems << p; });
    w_.viewport()->setFixedSize(side, side);
    QCoreApplication::processEvents();
    waitForFrames(8);  // long enough for temporal state (DA-RTW's moments) to settle there
    const QSize shrunk = w_.viewport()->size();
    w_.viewport()->setFixedSize(viewBefore);
    QCoreApplication::processEvents();
    waitForFrames(3);
    const auto mainAfter = w_.viewport()->measure()->computeErrorNow();
    const auto splitAfter = w_.viewport()->measure()->splitErrorPct();
    check(shrunk == QSize(side, side) && w_.viewport()->size() == viewBefore,
          tr("the view went to %1x%2 and back to %3x%4")
              .arg(shrunk.width())
              .arg(shrunk.height())
              .arg(w_.viewport()->width())
              .arg(w_.viewport()->height()));
    // The same frame in the same state: identical (both halves are deterministic once the
    // temporal state restarts), so 0.01 percentage points.
    const auto same = [](std::optional<double> a, std::optional<double> b) {
      return a && b && std::abs(*a - *b) <= 0.01;
    };
    check(same(mainBefore, mainAfter), tr("%1x%1, left half (%2): %3 % before, %4 % after")
                                           .arg(side)
                                           .arg(tech)
                                           .arg(mainBefore.value_or(-1), 0, 'f', 3)
                                           .arg(mainAfter.value_or(-1), 0, 'f', 3));
    check(same(splitBefore, splitAfter), tr("%1x%1, right half (%2): %3 % before, %4 % after")
                                             .arg(side)
                                             .arg(other)
                                             .arg(splitBefore.value_or(-1), 0, 'f', 3)
                                             .arg(splitAfter.value_or(-1), 0, 'f', 3));
    disconnect(connection);
    // A view too small to draw is a window state, not a rendering problem.
    check(
        problems.isEmpty(),
        tr("%1x%1 reports no rendering problem%2")
            .arg(side)
            .arg(problems.isEmpty() ? QString()
                                    : QStringLiteral(": ") + problems.join(QStringLiteral("; "))));
  }
  // File > Export figure with the split view on: two labelled cells (each half above its
  // error image), as wide as the two halves, twice as high plus the text.
  const QString figure = QDir::temp().filePath(QStringLiteral("shadowlab-gui-test-figure.png"));
  QFile::remove(figure);
  const auto exportError = auto_.exportFigure(figure);
  const QImage fig(figure);
  const int halfW = w_.viewport()->width() / 2, viewH = w_.viewport()->height();
  check(!exportError && !fig.isNull() && fig.width() >= 2 * halfW &&
            fig.width() <= 2 * halfW + 200 && fig.height() >= 2 * viewH,
        tr("File > Export figure: %1 (%2x%3 for halves of %4x%5)")
            .arg(exportError.value_or(figure))
            .arg(fig.width())
            .arg(fig.height())
            .arg(halfW)
            .arg(viewH));
  QFile::remove(figure);
  w_.viewport()->setMinimumSize(0, 0);
  w_.viewport()->setMaximumSize(QWIDGETSIZE_MAX, QWIDGETSIZE_MAX);
  return true;
}

bool GuiTests::omniProbe(const QString& dir) {
  const QString omniId = QStringLiteral("omni");
  PublicationPanel* panel = nullptr;
  for (const PublicationDocks::Dock& d : w_.docks().docks())
    if (d.entry.id == omniId) panel = d.panel;
  QDockWidget* dock = w_.docks().dock(omniId.toStdString());
  check(panel && dock, tr("the Omni map dock exists"));
  if (!panel || !dock) return false;
  dock->show();
  dock->raise();
  QCoreApplication::processEvents();
  waitForFrames(3);
  ViewportWidget* view = w_.viewport();
  sl::ViewSide* renderer = view->mainSide();
  const bool cube = view->techniqueId() == "cube";
  const glm::dvec3 light(view->camera()->light().positionM);
  // dp.axis: 0 y, 1 x, 2 z (DualParaboloidShadowMap's declaration).
  const glm::dvec3 axes[] = {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}};
  const omni::ParaboloidFrame frame = omni::paraboloidFrame(
      cube ? axes[0] : axes[std::clamp(renderer->params().getInt("dp.axis"), 0, 2)]);
  const QSize size = view->size();
  int probed = 0;
  for (const QPointF f :
       {QPointF(0.5, 0.5), QPointF(0.2, 0.3), QPointF(0.8, 0.75), QPointF(0.3, 0.85)}) {
    const QPointF at(f.x() * size.width(), f.y() * size.height());
    QMouseEvent move(QEvent::MouseMove, at, view->mapToGlobal(at), Qt::NoButton, Qt::NoButton,
                     Qt::NoModifier);
    QCoreApplication::sendEvent(view, &move);
    auto_.waitForProbe();
    const QJsonObject drawn = panel->drawnValues();
    const qreal dpr = view->devicePixelRatioF();
    const std::optional<sl::PixelProbe> p =
        auto_.probePixel(int(std::floor(at.x() * dpr)), int(std::floor(at.y() * dpr)));
    if (!p || !p->covered) continue;
    ++probed;
    const glm::dvec3 d = glm::dvec3(p->worldM) - light;
    int map = 0;
    glm::dvec2 uv;
    if (cube) {
      const omni::CubeCoord c = omni::cubeFaceUv(d);
      map = c.face;
      uv = c.uv;
    } else {
      const omni::ParaboloidCoord c = omni::paraboloidUv(frame, d);
      map = c.half;
      uv = c.uv;
    }
    // Without the normal offset (the script sets bias.normal=0) the lookup's uv is the
    // mapping's own: float32 (1e-3 of the map).
    const bool same = drawn.value(QStringLiteral("probe_map")).toInt(-1) == map &&
                      std::abs(drawn.value(QStringLiteral("probe_u")).toDouble(-9) - uv.x) < 1e-3 &&
                      std::abs(drawn.value(QStringLiteral("probe_v")).toDouble(-9) - uv.y) < 1e-3;
    check(same, tr("pixel (%1, %2): the marker is on map %3 at uv (%4, %5); algo/omni: map %6 at "
                   "(%7, %8)")
                    .arg(p->x)
                    .arg(p->y)
                    .arg(drawn.value(QStringLiteral("probe_map")).toInt(-1))
                    .arg(drawn.value(QStringLiteral("probe_u")).toDouble(-9), 0, 'f', 4)
                    .arg(drawn.value(QStringLiteral("probe_v")).toDouble(-9), 0, 'f', 4)
                    .arg(map)
                    .arg(uv.x, 0, 'f', 4)
                    .arg(uv.y, 0, 'f', 4));
    if (!dir.isEmpty() && QDir().mkpath(dir) && probed == 1)
      w_.grab().toImage().save(QDir(dir).filePath(QStringLiteral("omni-probe.png")));
  }
  check(probed >= 3, tr("%1 of 4 hover points over a surface").arg(probed));
  omniMapReadout(panel, cube);
  QEvent leave(QEvent::Leave);
  QCoreApplication::sendEvent(view, &leave);
  QCoreApplication::processEvents();
  check(!panel->drawnValues().contains(QStringLiteral("probe_map")),
        tr("leaving the view removes the marker"));
  // The probe is read back only while a panel that shows it is visible (issue 15 item 6).
  check(view->measure()->probeWanted(), tr("with the Omni map shown the view reads the probe"));
  auto hoverFrames = [&] {  // the mouse over the view, moved, and two frames under it
    const std::uint64_t before = auto_.viewReadouts().probesRead;
    for (const QPointF at : {QPointF(40, 40), QPointF(60, 50)}) {
      QMouseEvent move(QEvent::MouseMove, at, view->mapToGlobal(at), Qt::NoButton, Qt::NoButton,
                       Qt::NoModifier);
      QCoreApplication::sendEvent(view, &move);
      auto_.waitForProbe();
    }
    waitForFrames(2);
    return auto_.viewReadouts().probesRead - before;
  };
  const std::uint64_t shownReads = hoverFrames();
  check(shownReads >= 4,
        tr("Omni map shown: %1 probe reads for 2 moves and 2 frames").arg(qulonglong(shownReads)));
  dock->hide();
  QCoreApplication::processEvents();
  check(!view->measure()->probeWanted(), tr("with the Omni map hidden no panel wants the probe"));
  const std::uint64_t hiddenReads = hoverFrames();
  check(
      hiddenReads == 0,
      tr("Omni map hidden: %1 probe reads for 2 moves and 2 frames").arg(qulonglong(hiddenReads)));
  QCoreApplication::sendEvent(view, &leave);
  return true;
}

void GuiTests::omniMapReadout(PublicationPanel* panel, bool cube) {
  auto* density = panel->findChild<QCheckBox*>();
  auto* image = panel->findChild<ImageView*>();
  check(density && image && image->hasImage(), tr("the Omni map shows an image and a density box"));
  if (!density || !image || !image->hasImage()) return;
  density->setChecked(true);
  QCoreApplication::processEvents();
  const QJsonObject drawn = panel->drawnValues();
  // One scale for both mappings (OmniMapPanel's kDensityLog2Min/Max), whatever the data.
  check(drawn.value(QStringLiteral("density_shown")).toBool() &&
            drawn.value(QStringLiteral("scale_min")).toDouble() == 12.0 &&
            drawn.value(QStringLiteral("scale_max")).toDouble() == 24.0,
        tr("density shown on the fixed scale 12..24 log2 texels/sr (got %1..%2)")
            .arg(drawn.value(QStringLiteral("scale_min")).toDouble())
            .arg(drawn.value(QStringLiteral("scale_max")).toDouble()));
  // The cells of the layout: the cube's +x face is the cross's middle row, first column; the
  // paraboloid's first disc the left cell. Texel (x, y up) of the layout -> widget point.
  const int resolution = drawn.value(QStringLiteral("resolution")).toInt();
  const QSize texels = image->texelSize();
  const int cell = texels.height() / (cube ? 3 : 1);
  const int row0 = cube ? cell : 0;
  const QRectF r = image->shownImageRect();
  // The readout names the texel it reads ("texel (x, y)  uv (u, v)  distance = D m (stored
  // S), N texels/sr"): the widget's pixel covers a few texels, so the value is checked at the
  // texel it names.
  struct Readout {
    QString text;
    int tx = -1, ty = -1;
    double value = 0.0;
  };
  auto readAt = [&](int tx, int ty) {
    // Twice: the readout's text may wrap onto another line and move the image under the
    // pointer; the second move aims at where the image is then.
    for (int pass = 0; pass < 2; ++pass) {
      const QRectF shown = pass == 0 ? r : image->shownImageRect();
      const QPointF at(shown.left() + (tx + 0.5) / texels.width() * shown.width(),
                       shown.bottom() - (ty + 0.5) / texels.height() * shown.height());
      QMouseEvent move(QEvent::MouseMove, at, image->mapToGlobal(at), Qt::NoButton, Qt::NoButton,
                       Qt::NoModifier);
      QCoreApplication::sendEvent(image, &move);
      QCoreApplication::processEvents();
    }
    Readout out;
    out.text = image->hoverText();
    const QRegularExpressionMatch m =
        QRegularExpression(QStringLiteral("^texel \\((\\d+), (\\d+)\\).*, (\\S+) texels/sr$"))
            .match(out.text);
    if (m.hasMatch()) {
      out.tx = m.captured(1).toInt();
      out.ty = m.captured(2).toInt();
      out.value = m.captured(3).toDouble();
    }
    return out;
  };
  const omni::ParaboloidFrame frame = omni::paraboloidFrame({0, 1, 0});
  auto expected = [&](int tx, int ty) {  // texel of the cell: the mapping's density there
    const glm::dvec2 uv((tx + 0.5) / cell, (ty - row0 + 0.5) / cell);
    return cube ? omni::cubeTexelsPerSteradian(omni::cubeDirection(0, uv), resolution)
                : omni::paraboloidTexelsPerSteradian(frame, omni::paraboloidDirection(frame, 0, uv),
                                                     resolution);
  };
  // Centre, and near a corner (cube) or the rim (paraboloid); the density is symmetric about
  // the centre, so a cell drawn rotated reads the same.
  const std::pair<int, int> centre{cell / 2, row0 + cell / 2};
  const std::pair<int, int> edge = cube ? std::pair{2, row0 + 2} : std::pair{cell / 2, row0 + 3};
  double values[2] = {0.0, 0.0};
  int k = 0;
  for (const auto& [aimX, aimY] : {centre, edge}) {
    const Readout read = readAt(aimX, aimY);
    const double want = read.tx >= 0 ? expected(read.tx, read.ty) : 0.0;
    values[k++] = read.value;
    // A widget pixel spans several texels where the image is drawn small: the texel read is
    // within a pixel and a half of the one aimed at (at least 3 texels).
    const int slack =
        std::max(3, int(std::ceil(1.5 * texels.height() / std::max(1.0, r.height()))));
    check(read.tx >= 0 && std::abs(read.tx - aimX) <= slack && std::abs(read.ty - aimY) <= slack &&
              std::abs(read.value / want - 1.0) < 1e-3,
          tr("the value under the cursor near texel (%1, %2): \"%3\"; algo/omni there: %4 "
             "texels/sr")
              .arg(aimX)
              .arg(aimY)
              .arg(read.text)
              .arg(want, 0, 'g', 6));
  }
  const double ratio = values[1] / values[0], analytic = cube ? 3.0 * std::sqrt(3.0) : 4.0;
  check(ratio > 0.9 * analytic && ratio < analytic,
        tr("read under the cursor, near the %1 / centre = %2 (analytic at the very %1: %3)")
            .arg(cube ? tr("corner") : tr("rim"))
            .arg(ratio, 0, 'f', 4)
            .arg(analytic, 0, 'f', 4));
  density->setChecked(false);
  QCoreApplication::processEvents();
  check(!panel->drawnValues().value(QStringLiteral("density_shown")).toBool(),
        tr("unchecked: the depth is shown again"));
  QEvent leave(QEvent::Leave);
  QCoreApplication::sendEvent(image, &leave);
}

bool GuiTests::charts(const QString& dir) {
  w_.chartsDock()->show();
  w_.chartsDock()->raise();
  QCoreApplication::processEvents();
  // 3 configurations x 2 frames: uniform at two resolutions that differ from the view's, and
  // a small RTW map (slower than uniform, but little memory: the fronts against time and
  // against memory can differ).
  sl::ViewSide* r = w_.viewport()->mainSide();
  const int shownResolution = r->paramsOf("uniform").getInt("resolution");
  const int wanted = shownResolution == 256 ? 512 : 256;
  w_.chartsPanel()->setSweepText(
      QStringLiteral("uniform:resolution=%1,2048 rtw-backward:resolution=256").arg(wanted));
  w_.chartsPanel()->setFramesPerConfig(2);
  bool finished = false, completed = false;
  const auto connection = connect(w_.chartsPanel(), &ChartsPanel::sweepFinished, this,
                                  [&](bool c) { finished = true, completed = c; });
  // Cancel: a sweep stopped after its first frame reports itself not completed.
  bool cancelled = w_.chartsPanel()->startSweep();
  QCoreApplication::processEvents();
  w_.chartsPanel()->cancelSweep();
  cancelled = cancelled && finished && !completed && !w_.chartsPanel()->running();
  check(cancelled, QStringLiteral("Cancel stops a running sweep"));
  finished = completed = false;
  const bool started = w_.chartsPanel()->startSweep();
  check(started, QStringLiteral("the sweep starts"));
  if (!started) return false;
  // The view goes on drawing while the sweep runs: the sweep is one render job per frame, and
  // the view's frame runs between two of them (one job for the whole sweep held the view's
  // frame until the sweep had ended). Two frames: the first may have been under way already.
  const bool viewDrew = auto_.waitForFrames(2, 40000);
  check(viewDrew && !finished,
        QStringLiteral("the view draws a frame while the sweep runs (drawn: %1, sweep ended "
                       "before it: %2)")
            .arg(viewDrew)
            .arg(finished));
  QElapsedTimer clock;
  clock.start();
  while (!finished && clock.elapsed() < 40000)
    QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
  disconnect(connection);
  check(finished && completed, QStringLiteral("the sweep completes"));
  const auto& configs = w_.chartsPanel()->configs();
  bool measured = configs.size() == 3;
  for (const auto& c : configs) {
    measured = measured && c.done && c.ms.size() == 2 && c.medianMs > 0.0 &&
               std::isfinite(c.medianErrorPct) && c.medianErrorPct >= 0.0;
    std::printf("     %s: %.3g ms, %.3g %% error\n", qPrintable(c.label), c.medianMs,
                c.medianErrorPct);
  }
  check(measured, QStringLiteral("3 configurations x 2 frames measured"));
  if (!measured) return false;
  // The default sweep compares with a baseline that renders the view's light: uniform
  // refuses a point light, so there the other omni map (cube <-> dual-paraboloid).
  const sl::Light sun = w_.viewport()->camera()->light();
  for (const auto& [shown, light, expected] :
       {std::tuple{"cube", sl::Light::point({0, 2, 0}),
                   "cube:resolution=512,1024,2048 "
                   "dual-paraboloid:resolution=512,1024,2048"},
        {"dual-paraboloid", sl::Light::point({0, 2, 0}),
         "dual-paraboloid:resolution=512,1024,2048 cube:resolution=512,1024,2048"},
        {"uniform", sl::Light::point({0, 2, 0}), "cube:resolution=512,1024,2048"},
        {"cube", sl::Light::spot({0, 2, 0}, {0, -1, 0}, 40.0f),
         "cube:resolution=512,1024,2048 uniform:resolution=512,1024,2048"}}) {
    w_.viewport()->camera()->setLight(light);
    const QString previous = QString::fromStdString(w_.viewport()->techniqueId());
    w_.viewport()->setTechnique(shown);
    const QString sweep = w_.chartsPanel()->defaultSweepText();
    check(sweep == QLatin1String(expected),
          tr("default sweep with %1 and a %2 light: \"%3\"")
              .arg(QLatin1String(shown),
                   light.type == sl::LightType::Point ? QStringLiteral("point")
                                                      : QStringLiteral("spot"),
                   sweep));
    w_.viewport()->setTechnique(previous.toStdString());
  }
  w_.viewport()->camera()->setLight(sun);
  QCoreApplication::processEvents();
  if (!dir.isEmpty()) {
    QDir().mkpath(dir);
    const QString png = QDir(dir).filePath(QStringLiteral("panel-charts.png"));
    check(w_.chartsDock()->grab().toImage().save(png), QStringLiteral("saved ") + png);
  }
  if (!chartsAxis(dir)) return false;
  // A click on the first point (the slot the scatter series' clicked signal calls), from
  // another technique.
  if (auto e = auto_.setTechnique(QStringLiteral("rtw-backward"))) check(false, *e);
  w_.chartsPanel()->choose(0);
  waitForFrames(1);
  r = w_.viewport()->mainSide();
  check(r && r->techniqueId() == "uniform",
        QStringLiteral("clicking a point switches the technique to uniform"));
  check(r && r->params().getInt("resolution") == wanted,
        QStringLiteral("clicking a point sets resolution=%1").arg(wanted));
  const int index =
      w_.techniqueCombo()->findData(QString::fromStdString(r ? r->techniqueId() : std::string()));
  check(index >= 0 && w_.techniqueCombo()->currentIndex() == index,
        QStringLiteral("the technique combo follows"));
  return chartsUnmeasured();
}

bool GuiTests::chartsUnmeasured() {
  // A view of sky only (a scene without a camera path, the camera above it looking up)
  // measures no error: the configuration's is n/a (NaN), never 0; the chart draws no point for
  // it and the status line says so.
  check(auto_.openScene(QStringLiteral("dueling")), QStringLiteral("scene dueling"));
  const sl::Scene& scene = *w_.viewport()->scene();
  check(scene.paths.empty(),
        QStringLiteral("dueling has no camera path (the sweep uses the view)"));
  sl::Camera sky = w_.viewport()->camera()->camera();
  sky.position = scene.bounds.max + glm::vec3(0.0f, 10.0f, 0.0f);
  sky.target = sky.position + glm::vec3(0.0f, 10.0f, -1.0f);
  w_.viewport()->camera()->setCamera(sky);
  waitForFrames(1);
  w_.chartsPanel()->setSweepText(QStringLiteral("uniform:resolution=256"));
  w_.chartsPanel()->setFramesPerConfig(1);
  bool finished = false, completed = false;
  const auto connection = connect(w_.chartsPanel(), &ChartsPanel::sweepFinished, this,
                                  [&](bool c) { finished = true, completed = c; });
  check(w_.chartsPanel()->startSweep(), QStringLiteral("the sky-only sweep starts"));
  QElapsedTimer clock;
  clock.start();
  while (!finished && clock.elapsed() < 40000)
    QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
  disconnect(connection);
  const auto& configs = w_.chartsPanel()->configs();
  const bool unmeasured = finished && completed && configs.size() == 1 && configs[0].done &&
                          configs[0].errorPct.size() == 1 &&
                          !std::isfinite(configs[0].errorPct[0]) &&
                          !std::isfinite(configs[0].medianErrorPct);
  check(unmeasured, tr("sky only: the error is n/a, not a number (%1)")
                        .arg(configs.empty() ? 0.0 : configs[0].medianErrorPct));
  check(w_.chartsPanel()->drawnFront().empty(), QStringLiteral("sky only: no point drawn"));
  QString said;
  for (const QLabel* label : w_.chartsPanel()->findChildren<QLabel*>())
    if (label->text().contains(QStringLiteral("n/a"))) said = label->text();
  check(said.contains(QStringLiteral("Error n/a for 1 of them (no covered pixel")),
        tr("the status line says so: \"%1\"").arg(said));
  return unmeasured;
}

bool GuiTests::chartsAxis(const QString& dir) {
  // x: memory through the combo box, as a user would: axis and front change, no new sweep.
  const auto& configs = w_.chartsPanel()->configs();
  auto* xCombo = w_.chartsPanel()->findChild<QComboBox*>(QStringLiteral("chartsX"));
  check(xCombo && xCombo->count() == 2, QStringLiteral("the x combo box is there"));
  if (!xCombo) return false;
  // The front the panel should draw against each x, from the measured medians.
  auto expectedFront = [&](bool bytes) {
    std::vector<sl::CostPoint> costs;
    for (const auto& c : configs)
      costs.push_back({bytes ? c.medianBytes : c.medianMs, c.medianErrorPct});
    return sl::paretoFront(costs);
  };
  xCombo->setCurrentIndex(xCombo->findData(QStringLiteral("bytes")));
  QCoreApplication::processEvents();
  // uniform's memory is its one map: it grows with resolution² ("resolution=N" sweeps).
  auto resolutionOf = [](const ChartsPanel::Config& c) {
    return c.assignments.front().section(QLatin1Char('='), 1).toDouble();
  };
  const double ratio =
      configs[0].medianBytes > 0.0 ? configs[1].medianBytes / configs[0].medianBytes : 0.0;
  const double wantedRatio = std::pow(resolutionOf(configs[1]) / resolutionOf(configs[0]), 2.0);
  std::printf("     memory: %.0f and %.0f bytes (ratio %g, expected %g)\n", configs[0].medianBytes,
              configs[1].medianBytes, ratio, wantedRatio);
  check(ratio == wantedRatio,
        QStringLiteral("shadow memory measured per configuration (resolution²)"));
  check(w_.chartsPanel()->chartX() == sl::ChartX::Bytes &&
            w_.chartsPanel()->xAxisTitle().contains(QStringLiteral("memory")) &&
            w_.chartsPanel()->xAxisTitle().contains(QStringLiteral("iB")),
        QStringLiteral("x: memory switches the axis (\"%1\")").arg(w_.chartsPanel()->xAxisTitle()));
  auto frontText = [](const std::vector<std::size_t>& front) {
    QStringList s;
    for (std::size_t i : front) s << QString::number(i);
    return s.join(QLatin1Char(','));
  };
  check(w_.chartsPanel()->drawnFront() == expectedFront(true),
        QStringLiteral("the Pareto front is against memory (%1; against time: %2)")
            .arg(frontText(w_.chartsPanel()->drawnFront()), frontText(expectedFront(false))));
  check(!w_.chartsPanel()->running() && configs[0].ms.size() == 2,
        QStringLiteral("switching x measures nothing again"));
  if (!dir.isEmpty()) {
    const QString png = QDir(dir).filePath(QStringLiteral("panel-charts-bytes.png"));
    check(w_.chartsDock()->grab().toImage().save(png), QStringLiteral("saved ") + png);
  }
  xCombo->setCurrentIndex(xCombo->findData(QStringLiteral("ms")));
  QCoreApplication::processEvents();
  check(w_.chartsPanel()->chartX() == sl::ChartX::TimeMs &&
            w_.chartsPanel()->xAxisTitle().contains(QStringLiteral("ms")) &&
            w_.chartsPanel()->drawnFront() == expectedFront(false),
        QStringLiteral("x: time switches back (axis and front)"));
  return true;
}

void GuiTests::check(bool ok, const QString& what) {
  std::printf("%s %s\n", ok ? "ok  " : "FAIL", qPrintable(what));
  std::fflush(stdout);
  if (!ok) ++failures_;
}

bool GuiTests::waitForFrames(int frames, int timeoutMs) {
  if (auto_.waitForFrames(frames, timeoutMs)) return true;
  check(false, tr("%1 frame(s) rendered within %2 s").arg(frames).arg(timeoutMs / 1000.0));
  return false;
}

bool GuiTests::params() {
  sl::ViewSide* r = w_.viewport()->mainSide();
  w_.paramDock()->show();
  w_.paramDock()->raise();
  QCoreApplication::processEvents();

  // 1. A shared parameter, typed into its spin box: the renderer's value and the next frame.
  const std::string ambientKey = "shading.ambient";
  auto* ambient =
      w_.paramPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("param:shading.ambient"));
  check(ambient != nullptr, tr("the Parameters panel has an editor for shading.ambient"));
  if (!ambient) return false;
  const sl::ParamDecl& ambientDecl = *r->rendererParams().find(ambientKey);
  const double before = r->rendererParams().get(ambientKey);
  const double target = before < 0.5 ? 0.9 : 0.1;
  waitForFrames(1);
  const double lumBefore = meanLuminance(auto_.renderedFrame());
  const std::uint64_t frameBefore = r->stats().frameIndex;
  typeInto(ambient, number(target));
  check(std::abs(r->rendererParams().get(ambientKey) - target) < 1e-9,
        tr("typing %1 into Ambient sets the renderer's shading.ambient (was %2, now %3)")
            .arg(number(target), number(before), number(r->rendererParams().get(ambientKey))));
  const bool rendered = auto_.waitForFrames(1);
  check(rendered && r->stats().frameIndex > frameBefore,
        tr("a new frame was rendered after the change (frame %1 -> %2)")
            .arg(frameBefore)
            .arg(r->stats().frameIndex));
  const double lumAfter = meanLuminance(auto_.renderedFrame());
  check((target > before) ? lumAfter > lumBefore + 1.0 : lumAfter < lumBefore - 1.0,
        tr("the new frame shows it: mean luminance %1 -> %2")
            .arg(lumBefore, 0, 'f', 2)
            .arg(lumAfter, 0, 'f', 2));

  // 2. Out of range: refused with the declaration's message, nothing changes.
  auto_.clearStatusMessage();
  const std::uint64_t revision = r->rendererParams().revision();
  typeInto(ambient, QStringLiteral("5"));
  const QString message = auto_.statusMessage();
  const QString range = QString::fromStdString(sl::describeRange(ambientDecl));
  check(std::abs(r->rendererParams().get(ambientKey) - target) < 1e-9 &&
            r->rendererParams().revision() == revision,
        tr("typing 5 (out of range) leaves shading.ambient at %1")
            .arg(number(r->rendererParams().get(ambientKey))));
  check(message.contains(QStringLiteral("shading.ambient")) && message.contains(range),
        tr("the refusal is reported with the key and range %1: \"%2\"").arg(range, message));
  check(std::abs(ambient->value() - target) < 1e-9,
        tr("the editor shows the kept value again (%1)").arg(number(ambient->value())));

  // 3. The slider of the same row: to its left end = the declared minimum.
  if (auto* slider =
          w_.paramPanel()->findChild<QSlider*>(QStringLiteral("param:shading.ambient:slider"))) {
    slider->setValue(slider->minimum());
    check(std::abs(r->rendererParams().get(ambientKey) - ambientDecl.minValue) < 1e-9,
          tr("dragging the Ambient slider to its left end sets %1")
              .arg(number(ambientDecl.minValue)));
  } else {
    check(false, tr("the Ambient row has a slider"));
  }

  // 4. A technique parameter: the shadow-map resolution (an integer), if declared.
  const std::string resKey = "resolution";
  if (const sl::ParamDecl* res = r->params().find(resKey)) {
    auto* spin = w_.paramPanel()->findChild<QSpinBox*>(QStringLiteral("param:resolution"));
    check(spin != nullptr, tr("the Parameters panel has an editor for resolution"));
    if (!spin) return false;
    const int old = r->params().getInt(resKey);
    const int wanted = old / 2 >= res->minValue ? old / 2 : old * 2;
    typeInto(spin, QString::number(wanted));
    check(r->params().getInt(resKey) == wanted,
          tr("typing %1 into Resolution sets the technique's resolution (now %2)")
              .arg(wanted)
              .arg(r->params().getInt(resKey)));
    waitForFrames(1);
    bool resized = false;
    for (const sl::ResourceInfo& info : r->stats().memory.resources)
      resized = resized || info.width == wanted;
    check(resized, tr("the next frame's shadow resources include a %1-texel-wide map").arg(wanted));
    auto_.clearStatusMessage();
    const QString tooBig = QString::number(static_cast<long long>(res->maxValue) * 2);
    typeInto(spin, tooBig);
    const QString refusal = auto_.statusMessage();
    check(r->params().getInt(resKey) == wanted &&
              refusal.contains(QString::fromStdString(sl::describeRange(*res))),
          tr("typing %1 into Resolution is refused: \"%2\"").arg(tooBig, refusal));
  } else {
    std::printf("skip the technique has no 'resolution' parameter\n");
  }
  return true;
}

bool GuiTests::teaching(const QString& dir) {
  const bool save = !dir.isEmpty() && QDir().mkpath(dir);
  auto saveImage = [&](const QImage& image, const QString& name) {
    if (save) image.save(QDir(dir).filePath(name));
  };
  // 1. Step through the passes of one frame: each raises the panel showing its output.
  PassStepper& passes = *w_.passes();
  passes.step(+1);
  for (int i = 0; i < 50 && passes.index() < 0; ++i) waitForFrames(1, 2000);
  check(passes.index() == 0 && w_.viewport()->frames()->paused(),
        tr("] starts stepping at the first pass, paused (%1 passes)").arg(passes.steps().size()));
  QStringList seen;
  for (int i = 0; i < static_cast<int>(passes.steps().size()); ++i) {
    if (i > 0) passes.step(+1);
    QCoreApplication::processEvents();
    const PassStepper::Step& step = passes.steps()[static_cast<std::size_t>(passes.index())];
    seen << step.id;
    const bool raised =
        !step.dock || (step.dock->isVisible() && !step.dock->visibleRegion().isEmpty() &&
                       step.dock->windowTitle().startsWith(QStringLiteral("\u25b6")));
    check(passes.index() == i && raised,
          tr("pass %1 %2: %3")
              .arg(i + 1)
              .arg(step.id,
                   step.dock
                       ? tr("its panel (%1) is in front and marked").arg(step.dock->objectName())
                       : tr("the view")));
    QString file = step.id;
    file.replace(QLatin1Char(' '), QLatin1Char('-')).remove(QLatin1Char('+'));
    saveImage(w_.grab().toImage(), QStringLiteral("pass-%1-%2.png").arg(i + 1).arg(file));
  }
  // The steps are the declared passes of the technique, in the order they were timed.
  sl::ViewSide* r = w_.viewport()->mainSide();
  QStringList declared, timed;
  for (const sl::PassDecl& p :
       sl::framePassDecls(*sl::Renderer::findTechnique(r->techniqueId()), r->params()))
    declared << QString::fromStdString(p.id);
  for (const sl::PassTiming& p : r->stats().passes) timed << QString::fromStdString(p.name);
  check(seen == declared && (r->stats().timingFramesLate > 0 || timed == declared),
        tr("the passes come as declared and in frame order: %1 (timed: %2)")
            .arg(seen.join(QStringLiteral(" -> ")), timed.join(QStringLiteral(" -> "))));
  const std::uint64_t frame = r->stats().frameIndex;
  passes.step(+1);  // past the last pass: the next frame, from its first pass
  for (int i = 0; i < 50 && (passes.waitingForFrame() || passes.index() != 0); ++i)
    waitForFrames(1, 2000);
  check(passes.index() == 0 && w_.viewport()->mainSide()->stats().frameIndex == frame + 1,
        tr("] after the last pass renders exactly one more frame (%1 -> %2)")
            .arg(frame)
            .arg(w_.viewport()->mainSide()->stats().frameIndex));
  passes.stop();
  check(passes.index() < 0 && !w_.viewport()->frames()->paused(),
        tr("Esc stops stepping and resumes"));

  // 2. Overlays: O cycles through every value the declaration lists.
  sl::ParamSet& shared = w_.viewport()->mainSide()->rendererParams();
  const sl::ParamDecl* overlay = shared.find("view.overlay");
  QStringList values;
  for (std::size_t i = 0; overlay && i < overlay->enumNames.size(); ++i) {
    auto_.cycleOverlay();
    waitForFrames(1);
    values << QString::fromStdString(shared.format("view.overlay"));
    saveImage(w_.viewport()->grabView(), QStringLiteral("overlay-%1.png").arg(values.back()));
  }
  check(overlay && values.size() == static_cast<int>(overlay->enumNames.size()) &&
            values.back() == QString::fromStdString(overlay->enumNames.front()),
        tr("O cycles the overlays: %1").arg(values.join(QStringLiteral(", "))));

  // 3. Split view: the other technique on the right half, both errors measured.
  auto_.toggleSplit();
  waitForFrames(2);
  const auto error = w_.viewport()->measure()->computeErrorNow();
  waitForFrames(1);
  check(!w_.viewport()->frames()->splitTechnique().empty() && error &&
            w_.viewport()->measure()->splitErrorPct(),
        tr("F7 splits the view: %1 %2 % | %3 %4 %")
            .arg(QString::fromStdString(w_.viewport()->techniqueId()))
            .arg(error.value_or(-1), 0, 'f', 3)
            .arg(QString::fromStdString(w_.viewport()->frames()->splitTechnique()))
            .arg(w_.viewport()->measure()->splitErrorPct().value_or(-1), 0, 'f', 3));
  saveImage(w_.viewport()->grabView(), QStringLiteral("split.png"));
  auto_.toggleSplit();
  check(w_.viewport()->frames()->splitTechnique().empty(), tr("F7 again ends the split view"));

  // 3b. Outside view: V shows the third camera (the renderer reports it); a left drag orbits
  // it and leaves the main camera (which the metrics measure) where it was; V again ends it.
  auto* outside = w_.findChild<QAction*>(QStringLiteral("outsideViewAction"));
  check(outside != nullptr, tr("View > Outside view exists"));
  if (outside) {
    outside->trigger();
    waitForFrames(2);
    const sl::ViewSide* view = w_.viewport()->mainSide();
    check(w_.viewport()->camera()->outsideView() && view->stats().outsideCamera.has_value() &&
              !view->stats().outlines.frusta.empty(),
          tr("V turns the outside view on (%1 frusta drawn)")
              .arg(view->stats().outlines.frusta.size()));
    saveImage(w_.viewport()->grabView(), QStringLiteral("outside.png"));
    const sl::Camera before = w_.viewport()->camera()->camera();
    const double azimuth = shared.get("view.outside.azimuth_deg");
    const QPointF from(w_.viewport()->width() / 2.0, w_.viewport()->height() / 2.0),
        to = from + QPointF(60, 0);
    QMouseEvent press(QEvent::MouseButtonPress, from, w_.viewport()->mapToGlobal(from),
                      Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
    QMouseEvent move(QEvent::MouseMove, to, w_.viewport()->mapToGlobal(to), Qt::NoButton,
                     Qt::LeftButton, Qt::NoModifier);
    QMouseEvent release(QEvent::MouseButtonRelease, to, w_.viewport()->mapToGlobal(to),
                        Qt::LeftButton, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(w_.viewport(), &press);
    QApplication::sendEvent(w_.viewport(), &move);
    QApplication::sendEvent(w_.viewport(), &release);
    waitForFrames(1);
    const sl::Camera after = w_.viewport()->camera()->camera();
    check(after.position == before.position && after.target == before.target &&
              shared.get("view.outside.azimuth_deg") != azimuth,
          tr("a drag in the outside view orbits the third camera (azimuth %1 -> %2), not the main "
             "one")
              .arg(azimuth)
              .arg(shared.get("view.outside.azimuth_deg")));
    outside->trigger();
    waitForFrames(1);
    check(!w_.viewport()->camera()->outsideView() && !view->stats().outsideCamera.has_value(),
          tr("V again ends the outside view"));
  }

  // 4. Lessons: each applies its scene and technique.
  const std::vector<Lesson>& lessons = w_.lessons()->lessons();
  for (std::size_t i = 0; i < lessons.size(); ++i) {
    w_.lessons()->apply(static_cast<int>(i));
    waitForFrames(2);
    const sl::Preset& p = lessons[i].preset;
    check(auto_.sceneShown() == QString::fromStdString(p.scene) &&
              (p.technique.empty() || w_.viewport()->techniqueId() == p.technique),
          tr("lesson %1 (%2): scene %3, technique %4")
              .arg(i + 1)
              .arg(QString::fromStdString(p.title), auto_.sceneShown(),
                   QString::fromStdString(w_.viewport()->techniqueId())));
    saveImage(w_.grab().toImage(), QStringLiteral("lesson-%1.png").arg(i + 1));
  }
  return true;
}

bool GuiTests::badGltf(const QString& paths) {
  return badFiles(paths, w_.openAction(), tr("File > Open"));
}

bool GuiTests::badSession(const QString& paths) {
  return badFiles(paths, w_.sessions()->openAction(), tr("File > Open session"));
}

bool GuiTests::badFiles(const QString& paths, QAction* open, const QString& menuName) {
  const QStringList files = paths.split(QLatin1Char(','), Qt::SkipEmptyParts);
  check(!files.isEmpty(), tr("%1 names at least one file").arg(menuName));
  for (const QString& path : files) {
    check(QFileInfo::exists(path), tr("the broken file %1 exists").arg(path));
    if (!QFileInfo::exists(path)) return false;
    badFileOpen(path, open, menuName, false);
    badFileOpen(path, open, menuName, true);
  }
  return true;
}

GuiTests::ViewState GuiTests::viewState() const {
  return ViewState{w_.viewport()->scene(),
                   auto_.sceneShown(),
                   w_.viewport()->techniqueId(),
                   w_.viewport()->frames()->splitTechnique(),
                   w_.viewport()->mainSide()->params(),
                   w_.viewport()->mainSide()->rendererParams(),
                   w_.viewport()->frames()->splitParams()};
}

void GuiTests::badFileOpen(const QString& path, QAction* open, const QString& menuName, bool drop) {
  const ViewState before = viewState();
  const QString comboBefore = w_.sceneCombo()->currentText();
  const QString titleBefore = w_.windowTitle();
  const QString fileName = QFileInfo(path).fileName();
  const QString absolute = QFileInfo(path).absoluteFilePath();
  const QString how = drop ? tr("dropped") : menuName;
  std::printf("---- %s, %s\n", qPrintable(fileName), qPrintable(how));
  auto_.clearStatusMessage();

  // Drive the modal dialogs the way a user would: pick the file, read the error, close it.
  bool sawFileDialog = false, sawMessage = false;
  QString messageText, detailsText;
  QTimer driver;
  driver.setInterval(50);
  int ticks = 0;
  connect(&driver, &QTimer::timeout, this, [&] {
    QWidget* modal = QApplication::activeModalWidget();
    if (modal && ++ticks > 200) {  // 10 s: a dialog that will not close; give up, no hang
      QMetaObject::invokeMethod(modal, "reject", Qt::QueuedConnection);
      return;
    }
    if (auto* dialog = qobject_cast<QFileDialog*>(modal)) {
      sawFileDialog = true;
      // Type the path into the dialog's file name field and press Return.
      if (auto* edit = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"))) {
        edit->setText(absolute);
        QKeyEvent enter(QEvent::KeyPress, Qt::Key_Return, Qt::NoModifier);
        QApplication::sendEvent(edit, &enter);
      }
    } else if (auto* box = qobject_cast<QMessageBox*>(modal)) {
      sawMessage = true;
      messageText = box->text();
      detailsText = box->detailedText();
      box->accept();
    }
  });
  QElapsedTimer clock;
  clock.start();
  driver.start();
  if (drop) {
    // A file dragged from a file manager onto the window: enter, then drop, with its URL.
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(absolute)});
    const QPoint at = w_.rect().center();
    QDragEnterEvent enter(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(&w_, &enter);
    check(enter.isAccepted(), tr("dragging %1 over the window is accepted").arg(fileName));
    QDropEvent dropEvent(QPointF(at), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(&w_, &dropEvent);  // returns once the error dialog is closed
  } else {
    open->trigger();  // the menu item: returns once both dialogs are closed
    check(sawFileDialog, tr("%1 showed the file dialog").arg(menuName));
  }
  driver.stop();
  const qint64 ms = clock.elapsed();

  const QString status = auto_.statusMessage();
  auto quoted = [](const QString& text) {  // what this log prints of a shown text
    return text.size() > 120 ? text.left(120) + QStringLiteral("…") : text;
  };
  check(sawMessage && messageText.contains(fileName),
        tr("an error dialog naming the file appeared: \"%1\"").arg(quoted(messageText)));
  check(status.contains(fileName), tr("the status bar names the file: \"%1\"").arg(quoted(status)));
  // Elided (MessageText.h): a hostile file's text cannot freeze the window.
  const int limit = kShownMessageChars + 1;
  check(messageText.size() <= limit && status.size() <= limit &&
            detailsText.size() <= kMessageDetailsChars + 200,
        tr("the dialog and the status bar show at most %1 characters (%2, %3; details %4)")
            .arg(limit)
            .arg(messageText.size())
            .arg(status.size())
            .arg(detailsText.size()));
  check(ms < 20000, tr("%1 the file, read the error and closed it in %2 ms").arg(how).arg(ms));
  const ViewState after = viewState();
  check(after.scene == before.scene && after.sceneSpec == before.sceneSpec,
        tr("the previous scene (%1) is still shown").arg(before.sceneSpec));
  check(after == before, tr("technique, parameters and split view are unchanged"));
  check(w_.sceneCombo()->currentText() == comboBefore && w_.windowTitle() == titleBefore,
        tr("the scene selector and the title still name it (%1)").arg(comboBefore));
  const std::uint64_t frame = w_.viewport()->mainSide()->stats().frameIndex;
  const bool rendered = auto_.waitForFrames(2);
  check(rendered && w_.viewport()->mainSide()->stats().frameIndex > frame,
        tr("the view keeps rendering (frame %1 -> %2)")
            .arg(frame)
            .arg(w_.viewport()->mainSide()->stats().frameIndex));
}

}  // namespace sl::ui
