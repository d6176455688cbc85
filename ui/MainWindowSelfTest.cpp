// GUI self-tests (`shadowlab --self-test NAME`, driven by tests/gui/*.sh under Xvfb). They
// act as a user would — typing into the generated parameter editors, going through
// File > Open with Qt's own file dialog, reading the message box — and check what the
// renderer and the window did. Each check prints "ok   ..." or "FAIL ..."; exit 0 = pass.
#include <cmath>
#include <cstdio>

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QDragEnterEvent>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QFileInfo>
#include <QKeyEvent>
#include <QLineEdit>
#include <QMessageBox>
#include <QMimeData>
#include <QSlider>
#include <QSpinBox>
#include <QStatusBar>
#include <QTimer>
#include <QUrl>

#include "ChartsPanel.h"
#include "LessonPanel.h"
#include "MainWindow.h"
#include "MessageText.h"
#include "ParamPanel.h"
#include "ViewportWidget.h"

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

void MainWindow::startSelfTest(const QString& name, const QString& argument) {
  selfTest_ = name;
  selfTestArgument_ = argument;
  selfTestFailures_ = 0;
  dialogs_ = true;  // the tests check the message boxes a user would see
  auto* timer = new QTimer(this);
  auto* clock = new QElapsedTimer;
  clock->start();
  connect(timer, &QTimer::timeout, this, [this, timer, clock] {
    if (failed_) {
      timer->stop();
      return;
    }
    if (!rendererBound_ || viewport_->framesRendered() < 2) {
      if (clock->elapsed() > kStartTimeoutMs) {
        timer->stop();
        report(
            tr("--self-test: the renderer did not start within %1 s").arg(kStartTimeoutMs / 1000));
        QCoreApplication::exit(1);
      }
      viewport_->update();
      return;
    }
    timer->stop();
    timer->deleteLater();
    delete clock;
    runSelfTest();
  });
  timer->start(30);
}

void MainWindow::runSelfTest() {
  std::printf("self-test %s: technique %s, scene %s\n", qPrintable(selfTest_),
              viewport_->techniqueId().c_str(), qPrintable(sceneSpec_));
  bool ran = false;
  if (selfTest_ == QLatin1String("params"))
    ran = selfTestParams();
  else if (selfTest_ == QLatin1String("teaching"))
    ran = selfTestTeaching(selfTestArgument_);
  else if (selfTest_ == QLatin1String("charts"))
    ran = selfTestCharts(selfTestArgument_);
  else
    ran = selfTestBadGltf(selfTestArgument_);
  const bool pass = ran && selfTestFailures_ == 0;
  std::printf("%s\n", pass ? "PASS" : "FAIL");
  std::fflush(stdout);
  QCoreApplication::exit(pass ? 0 : 1);
}

bool MainWindow::selfTestCharts(const QString& dir) {
  chartsDock_->show();
  chartsDock_->raise();
  QCoreApplication::processEvents();
  // 3 configurations x 2 frames: uniform at two resolutions that differ from the view's, and
  // a small RTW map (slower than uniform, but little memory: the fronts against time and
  // against memory can differ).
  sl::Renderer* r = viewport_->renderer();
  const int shownResolution = r->paramsOf("uniform").getInt("resolution");
  const int wanted = shownResolution == 256 ? 512 : 256;
  chartsPanel_->setSweepText(
      QStringLiteral("uniform:resolution=%1,2048 rtw-backward:resolution=256").arg(wanted));
  chartsPanel_->setFramesPerConfig(2);
  bool finished = false, completed = false;
  const auto connection = connect(chartsPanel_, &ChartsPanel::sweepFinished, this,
                                  [&](bool c) { finished = true, completed = c; });
  // Cancel: a sweep stopped after its first frame reports itself not completed.
  bool cancelled = chartsPanel_->startSweep();
  QCoreApplication::processEvents();
  chartsPanel_->cancelSweep();
  cancelled = cancelled && finished && !completed && !chartsPanel_->running();
  selfTestCheck(cancelled, QStringLiteral("Cancel stops a running sweep"));
  finished = completed = false;
  const bool started = chartsPanel_->startSweep();
  selfTestCheck(started, QStringLiteral("the sweep starts"));
  if (!started) return false;
  QElapsedTimer clock;
  clock.start();
  while (!finished && clock.elapsed() < 40000)
    QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
  disconnect(connection);
  selfTestCheck(finished && completed, QStringLiteral("the sweep completes"));
  const auto& configs = chartsPanel_->configs();
  bool measured = configs.size() == 3;
  for (const auto& c : configs) {
    measured = measured && c.done && c.ms.size() == 2 && c.medianMs > 0.0 &&
               std::isfinite(c.medianErrorPct) && c.medianErrorPct >= 0.0;
    std::printf("     %s: %.3g ms, %.3g %% error\n", qPrintable(c.label), c.medianMs,
                c.medianErrorPct);
  }
  selfTestCheck(measured, QStringLiteral("3 configurations x 2 frames measured"));
  if (!measured) return false;
  QCoreApplication::processEvents();
  if (!dir.isEmpty()) {
    QDir().mkpath(dir);
    const QString png = QDir(dir).filePath(QStringLiteral("panel-charts.png"));
    selfTestCheck(chartsDock_->grab().toImage().save(png), QStringLiteral("saved ") + png);
  }
  if (!selfTestChartsAxis(dir)) return false;
  // A click on the first point (the slot the scatter series' clicked signal calls), from
  // another technique.
  setTechnique(QStringLiteral("rtw-backward"));
  chartsPanel_->choose(0);
  waitForFrames(1);
  r = viewport_->renderer();
  selfTestCheck(r && r->techniqueId() == "uniform",
                QStringLiteral("clicking a point switches the technique to uniform"));
  selfTestCheck(r && r->params().getInt("resolution") == wanted,
                QStringLiteral("clicking a point sets resolution=%1").arg(wanted));
  const int index =
      techniqueCombo_->findData(QString::fromStdString(r ? r->techniqueId() : std::string()));
  selfTestCheck(index >= 0 && techniqueCombo_->currentIndex() == index,
                QStringLiteral("the technique combo follows"));
  return true;
}

bool MainWindow::selfTestChartsAxis(const QString& dir) {
  // x: memory through the combo box, as a user would: axis and front change, no new sweep.
  const auto& configs = chartsPanel_->configs();
  auto* xCombo = chartsPanel_->findChild<QComboBox*>(QStringLiteral("chartsX"));
  selfTestCheck(xCombo && xCombo->count() == 2, QStringLiteral("the x combo box is there"));
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
  selfTestCheck(ratio == wantedRatio,
                QStringLiteral("shadow memory measured per configuration (resolution²)"));
  selfTestCheck(
      chartsPanel_->chartX() == sl::ChartX::Bytes &&
          chartsPanel_->xAxisTitle().contains(QStringLiteral("memory")) &&
          chartsPanel_->xAxisTitle().contains(QStringLiteral("iB")),
      QStringLiteral("x: memory switches the axis (\"%1\")").arg(chartsPanel_->xAxisTitle()));
  auto frontText = [](const std::vector<std::size_t>& front) {
    QStringList s;
    for (std::size_t i : front) s << QString::number(i);
    return s.join(QLatin1Char(','));
  };
  selfTestCheck(chartsPanel_->drawnFront() == expectedFront(true),
                QStringLiteral("the Pareto front is against memory (%1; against time: %2)")
                    .arg(frontText(chartsPanel_->drawnFront()), frontText(expectedFront(false))));
  selfTestCheck(!chartsPanel_->running() && configs[0].ms.size() == 2,
                QStringLiteral("switching x measures nothing again"));
  if (!dir.isEmpty()) {
    const QString png = QDir(dir).filePath(QStringLiteral("panel-charts-bytes.png"));
    selfTestCheck(chartsDock_->grab().toImage().save(png), QStringLiteral("saved ") + png);
  }
  xCombo->setCurrentIndex(xCombo->findData(QStringLiteral("ms")));
  QCoreApplication::processEvents();
  selfTestCheck(chartsPanel_->chartX() == sl::ChartX::TimeMs &&
                    chartsPanel_->xAxisTitle().contains(QStringLiteral("ms")) &&
                    chartsPanel_->drawnFront() == expectedFront(false),
                QStringLiteral("x: time switches back (axis and front)"));
  return true;
}

void MainWindow::selfTestCheck(bool ok, const QString& what) {
  std::printf("%s %s\n", ok ? "ok  " : "FAIL", qPrintable(what));
  std::fflush(stdout);
  if (!ok) ++selfTestFailures_;
}

bool MainWindow::waitForFrames(int frames, int timeoutMs) {
  const std::uint64_t target = viewport_->framesRendered() + static_cast<std::uint64_t>(frames);
  QElapsedTimer clock;
  clock.start();
  while (viewport_->framesRendered() < target) {
    viewport_->update();
    QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    if (clock.elapsed() > timeoutMs) return false;
  }
  return true;
}

bool MainWindow::selfTestParams() {
  sl::Renderer* r = viewport_->renderer();
  paramDock_->show();
  paramDock_->raise();
  QCoreApplication::processEvents();

  // 1. A shared parameter, typed into its spin box: the renderer's value and the next frame.
  const std::string ambientKey = "shading.ambient";
  auto* ambient = paramPanel_->findChild<QDoubleSpinBox*>(QStringLiteral("param:shading.ambient"));
  selfTestCheck(ambient != nullptr, tr("the Parameters panel has an editor for shading.ambient"));
  if (!ambient) return false;
  const sl::ParamDecl& ambientDecl = *r->rendererParams().find(ambientKey);
  const double before = r->rendererParams().get(ambientKey);
  const double target = before < 0.5 ? 0.9 : 0.1;
  waitForFrames(1);
  const double lumBefore = meanLuminance(viewport_->grabFramebuffer());
  const std::uint64_t frameBefore = r->stats().frameIndex;
  typeInto(ambient, number(target));
  selfTestCheck(
      std::abs(r->rendererParams().get(ambientKey) - target) < 1e-9,
      tr("typing %1 into Ambient sets the renderer's shading.ambient (was %2, now %3)")
          .arg(number(target), number(before), number(r->rendererParams().get(ambientKey))));
  const bool rendered = waitForFrames(1);
  selfTestCheck(rendered && r->stats().frameIndex > frameBefore,
                tr("a new frame was rendered after the change (frame %1 -> %2)")
                    .arg(frameBefore)
                    .arg(r->stats().frameIndex));
  const double lumAfter = meanLuminance(viewport_->grabFramebuffer());
  selfTestCheck((target > before) ? lumAfter > lumBefore + 1.0 : lumAfter < lumBefore - 1.0,
                tr("the new frame shows it: mean luminance %1 -> %2")
                    .arg(lumBefore, 0, 'f', 2)
                    .arg(lumAfter, 0, 'f', 2));

  // 2. Out of range: refused with the declaration's message, nothing changes.
  statusBar()->clearMessage();
  const std::uint64_t revision = r->rendererParams().revision();
  typeInto(ambient, QStringLiteral("5"));
  const QString message = statusBar()->currentMessage();
  const QString range = QString::fromStdString(sl::describeRange(ambientDecl));
  selfTestCheck(std::abs(r->rendererParams().get(ambientKey) - target) < 1e-9 &&
                    r->rendererParams().revision() == revision,
                tr("typing 5 (out of range) leaves shading.ambient at %1")
                    .arg(number(r->rendererParams().get(ambientKey))));
  selfTestCheck(
      message.contains(QStringLiteral("shading.ambient")) && message.contains(range),
      tr("the refusal is reported with the key and range %1: \"%2\"").arg(range, message));
  selfTestCheck(std::abs(ambient->value() - target) < 1e-9,
                tr("the editor shows the kept value again (%1)").arg(number(ambient->value())));

  // 3. The slider of the same row: to its left end = the declared minimum.
  if (auto* slider =
          paramPanel_->findChild<QSlider*>(QStringLiteral("param:shading.ambient:slider"))) {
    slider->setValue(slider->minimum());
    selfTestCheck(std::abs(r->rendererParams().get(ambientKey) - ambientDecl.minValue) < 1e-9,
                  tr("dragging the Ambient slider to its left end sets %1")
                      .arg(number(ambientDecl.minValue)));
  } else {
    selfTestCheck(false, tr("the Ambient row has a slider"));
  }

  // 4. A technique parameter: the shadow-map resolution (an integer), if declared.
  const std::string resKey = "resolution";
  if (const sl::ParamDecl* res = r->params().find(resKey)) {
    auto* spin = paramPanel_->findChild<QSpinBox*>(QStringLiteral("param:resolution"));
    selfTestCheck(spin != nullptr, tr("the Parameters panel has an editor for resolution"));
    if (!spin) return false;
    const int old = r->params().getInt(resKey);
    const int wanted = old / 2 >= res->minValue ? old / 2 : old * 2;
    typeInto(spin, QString::number(wanted));
    selfTestCheck(r->params().getInt(resKey) == wanted,
                  tr("typing %1 into Resolution sets the technique's resolution (now %2)")
                      .arg(wanted)
                      .arg(r->params().getInt(resKey)));
    waitForFrames(1);
    bool resized = false;
    for (const sl::ResourceInfo& info : r->stats().memory.resources)
      resized = resized || info.width == wanted;
    selfTestCheck(resized,
                  tr("the next frame's shadow resources include a %1-texel-wide map").arg(wanted));
    statusBar()->clearMessage();
    const QString tooBig = QString::number(static_cast<long long>(res->maxValue) * 2);
    typeInto(spin, tooBig);
    const QString refusal = statusBar()->currentMessage();
    selfTestCheck(r->params().getInt(resKey) == wanted &&
                      refusal.contains(QString::fromStdString(sl::describeRange(*res))),
                  tr("typing %1 into Resolution is refused: \"%2\"").arg(tooBig, refusal));
  } else {
    std::printf("skip the technique has no 'resolution' parameter\n");
  }
  return true;
}

bool MainWindow::selfTestTeaching(const QString& dir) {
  const bool save = !dir.isEmpty() && QDir().mkpath(dir);
  auto saveImage = [&](const QImage& image, const QString& name) {
    if (save) image.save(QDir(dir).filePath(name));
  };
  // 1. Step through the passes of one frame: each raises the panel showing its output.
  stepPass(+1);
  for (int i = 0; i < 50 && passIndex_ < 0; ++i) waitForFrames(1, 2000);
  selfTestCheck(
      passIndex_ == 0 && viewport_->paused(),
      tr("] starts stepping at the first pass, paused (%1 passes)").arg(passSteps_.size()));
  QStringList seen;
  for (int i = 0; i < static_cast<int>(passSteps_.size()); ++i) {
    if (i > 0) stepPass(+1);
    QCoreApplication::processEvents();
    const PassStep& step = passSteps_[static_cast<std::size_t>(passIndex_)];
    seen << step.id;
    const bool raised =
        !step.dock || (step.dock->isVisible() && !step.dock->visibleRegion().isEmpty() &&
                       step.dock->windowTitle().startsWith(QStringLiteral("\u25b6")));
    selfTestCheck(
        passIndex_ == i && raised,
        tr("pass %1 %2: %3")
            .arg(i + 1)
            .arg(step.id,
                 step.dock
                     ? tr("its panel (%1) is in front and marked").arg(step.dock->objectName())
                     : tr("the view")));
    saveImage(grab().toImage(), QStringLiteral("pass-%1-%2.png").arg(i + 1).arg(step.id));
  }
  selfTestCheck(
      seen.join(QLatin1Char(' ')).contains(QStringLiteral("im collapse blur scan warped lookup")) ||
          seen.join(QLatin1Char(' '))
              .contains(QStringLiteral("im moments pca collapse blur scan warped lookup")),
      tr("the passes come in frame order: %1").arg(seen.join(QStringLiteral(" -> "))));
  const std::uint64_t frame = viewport_->renderer()->stats().frameIndex;
  stepPass(+1);  // past the last pass: the next frame, from its first pass
  for (int i = 0; i < 50 && (passWaitingForFrame_ || passIndex_ != 0); ++i) waitForFrames(1, 2000);
  selfTestCheck(passIndex_ == 0 && viewport_->renderer()->stats().frameIndex == frame + 1,
                tr("] after the last pass renders exactly one more frame (%1 -> %2)")
                    .arg(frame)
                    .arg(viewport_->renderer()->stats().frameIndex));
  stopPassStepping();
  selfTestCheck(passIndex_ < 0 && !viewport_->paused(), tr("Esc stops stepping and resumes"));

  // 2. Overlays: O cycles through every value the declaration lists.
  sl::ParamSet& shared = viewport_->renderer()->rendererParams();
  const sl::ParamDecl* overlay = shared.find("view.overlay");
  QStringList values;
  for (std::size_t i = 0; overlay && i < overlay->enumNames.size(); ++i) {
    cycleOverlay();
    waitForFrames(1);
    values << QString::fromStdString(shared.format("view.overlay"));
    saveImage(viewport_->grabView(), QStringLiteral("overlay-%1.png").arg(values.back()));
  }
  selfTestCheck(overlay && values.size() == static_cast<int>(overlay->enumNames.size()) &&
                    values.back() == QString::fromStdString(overlay->enumNames.front()),
                tr("O cycles the overlays: %1").arg(values.join(QStringLiteral(", "))));

  // 3. Split view: the other technique on the right half, both errors measured.
  toggleSplit();
  waitForFrames(2);
  const auto error = viewport_->computeErrorNow();
  waitForFrames(1);
  selfTestCheck(!viewport_->splitTechnique().empty() && error && viewport_->splitErrorPct(),
                tr("F7 splits the view: %1 %2 % | %3 %4 %")
                    .arg(QString::fromStdString(viewport_->techniqueId()))
                    .arg(error.value_or(-1), 0, 'f', 3)
                    .arg(QString::fromStdString(viewport_->splitTechnique()))
                    .arg(viewport_->splitErrorPct().value_or(-1), 0, 'f', 3));
  saveImage(viewport_->grabView(), QStringLiteral("split.png"));
  toggleSplit();
  selfTestCheck(viewport_->splitTechnique().empty(), tr("F7 again ends the split view"));

  // 4. Lessons: each applies its scene and technique.
  for (std::size_t i = 0; i < lessons_.size(); ++i) {
    applyLesson(static_cast<int>(i));
    waitForFrames(2);
    const sl::Preset& p = lessons_[i].preset;
    selfTestCheck(sceneSpec_ == QString::fromStdString(p.scene) &&
                      (p.technique.empty() || viewport_->techniqueId() == p.technique),
                  tr("lesson %1 (%2): scene %3, technique %4")
                      .arg(i + 1)
                      .arg(QString::fromStdString(p.title), sceneSpec_,
                           QString::fromStdString(viewport_->techniqueId())));
    saveImage(grab().toImage(), QStringLiteral("lesson-%1.png").arg(i + 1));
  }
  return true;
}

bool MainWindow::selfTestBadGltf(const QString& paths) {
  const QStringList files = paths.split(QLatin1Char(','), Qt::SkipEmptyParts);
  selfTestCheck(!files.isEmpty(), tr("bad-gltf names at least one file"));
  for (const QString& path : files) {
    selfTestCheck(QFileInfo::exists(path), tr("the broken glTF %1 exists").arg(path));
    if (!QFileInfo::exists(path)) return false;
    selfTestBadGltfOpen(path, false);
    selfTestBadGltfOpen(path, true);
  }
  return true;
}

void MainWindow::selfTestBadGltfOpen(const QString& path, bool drop) {
  const std::shared_ptr<const sl::Scene> sceneBefore = viewport_->scene();
  const QString specBefore = sceneSpec_;
  const QString comboBefore = sceneCombo_->currentText();
  const QString titleBefore = windowTitle();
  const QString fileName = QFileInfo(path).fileName();
  const QString absolute = QFileInfo(path).absoluteFilePath();
  const QString how = drop ? tr("dropped") : tr("File > Open");
  std::printf("---- %s, %s\n", qPrintable(fileName), qPrintable(how));
  statusBar()->clearMessage();

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
    const QPoint at = rect().center();
    QDragEnterEvent enter(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(this, &enter);
    selfTestCheck(enter.isAccepted(), tr("dragging %1 over the window is accepted").arg(fileName));
    QDropEvent dropEvent(QPointF(at), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(this, &dropEvent);  // returns once the error dialog is closed
  } else {
    openAction_->trigger();  // File > Open glTF…: returns once both dialogs are closed
    selfTestCheck(sawFileDialog, tr("File > Open glTF… showed the file dialog"));
  }
  driver.stop();
  const qint64 ms = clock.elapsed();

  const QString status = statusBar()->currentMessage();
  auto quoted = [](const QString& text) {  // what this log prints of a shown text
    return text.size() > 120 ? text.left(120) + QStringLiteral("…") : text;
  };
  selfTestCheck(sawMessage && messageText.contains(fileName),
                tr("an error dialog naming the file appeared: \"%1\"").arg(quoted(messageText)));
  selfTestCheck(status.contains(fileName),
                tr("the status bar names the file: \"%1\"").arg(quoted(status)));
  // Elided (MessageText.h): a hostile file's text cannot freeze the window.
  const int limit = kShownMessageChars + 1;
  selfTestCheck(messageText.size() <= limit && status.size() <= limit &&
                    detailsText.size() <= kMessageDetailsChars + 200,
                tr("the dialog and the status bar show at most %1 characters (%2, %3; details %4)")
                    .arg(limit)
                    .arg(messageText.size())
                    .arg(status.size())
                    .arg(detailsText.size()));
  selfTestCheck(ms < 20000,
                tr("%1 the file, read the error and closed it in %2 ms").arg(how).arg(ms));
  selfTestCheck(viewport_->scene() == sceneBefore && sceneSpec_ == specBefore,
                tr("the previous scene (%1) is still shown").arg(specBefore));
  selfTestCheck(sceneCombo_->currentText() == comboBefore && windowTitle() == titleBefore,
                tr("the scene selector and the title still name it (%1)").arg(comboBefore));
  const std::uint64_t frame = viewport_->renderer()->stats().frameIndex;
  const bool rendered = waitForFrames(2);
  selfTestCheck(rendered && viewport_->renderer()->stats().frameIndex > frame,
                tr("the view keeps rendering (frame %1 -> %2)")
                    .arg(frame)
                    .arg(viewport_->renderer()->stats().frameIndex));
}

}  // namespace sl::ui
