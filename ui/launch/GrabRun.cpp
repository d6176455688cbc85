// `--grab` runs and the window's image export (see GrabRun.h).
#include "launch/GrabRun.h"

#include <cstdio>

#include <QAction>
#include <QBuffer>
#include <QCoreApplication>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLabel>

#include "teaching/LessonController.h"
#include "window/MainWindow.h"
#include "window/StatusLine.h"
#include "view/ViewportWidget.h"
#include "core/Course.h"
#include "core/JsonNumber.h"
#include "panels/common/TimingPanel.h"
#include "scene/GltfLoader.h"
#include "window/MessageText.h"

namespace sl::ui {

namespace {
constexpr int kGrabTickMs = 30;
constexpr qint64 kGrabTimeoutMs = 120000;
constexpr qsizetype kMaxNotedProblems = 20;

QString panelFileName(const QDockWidget* dock) {
  return QStringLiteral("panel-%1.png").arg(dock->objectName());
}

/// A file the window names itself (only a regular file or none is replaced).
sl::OutputTarget windowTarget(const QString& name, const QString& path) {
  return {name.toStdString(), path.toStdString(), false};
}
}  // namespace

std::vector<sl::InputTarget> windowInputs(const MainWindow& window, bool forSession) {
  std::vector<sl::InputTarget> inputs;
  if (const auto& scene = window.viewport()->scene())
    for (const std::string& f : scene->inputFiles) inputs.push_back({"the scene's file " + f, f});
  const std::string course = sl::courseFile(sl::builtinSceneDir()).string();
  inputs.push_back({"the course file " + course, course});
  if (!forSession)
    for (const Lesson& l : window.lessons()->lessons())
      inputs.push_back({"the lesson or session " + l.path.toStdString(), l.path.toStdString()});
  return inputs;
}

QByteArray pngBytes(const QImage& image) {
  QByteArray png;
  QBuffer buffer(&png);
  buffer.open(QIODevice::WriteOnly);
  if (image.isNull() || !image.save(&buffer, "PNG")) return {};
  return png;
}

std::optional<QString> writeWindowOutput(const MainWindow& window, const QString& path,
                                         const QByteArray& bytes, bool forSession) {
  const sl::OutputTarget target = windowTarget(QFileInfo(path).fileName(), path);
  if (auto e = sl::checkOutputTargets({target}, windowInputs(window, forSession)))
    return QString::fromStdString(*e);
  if (bytes.isEmpty())
    return QCoreApplication::translate("GrabRun", "%1: nothing to write").arg(path);
  const std::string data = bytes.toStdString();
  if (auto e = sl::writeOutputAtomically(
          target, [&](const std::string& tmp) { return sl::writeFileBytes(tmp, data); }))
    return QString::fromStdString(*e);
  return std::nullopt;
}

std::optional<QString> GrabRun::checkGrabFiles(const QString& dirPath, bool published) const {
  const QDir dir(dirPath);
  std::vector<sl::OutputTarget> targets;
  QStringList names = {QStringLiteral("window.png"), QStringLiteral("viewport.png")};
  for (const QDockWidget* dock : w_.findChildren<QDockWidget*>()) names << panelFileName(dock);
  if (published) names << QStringLiteral("published.json");
  for (const QString& name : names) targets.push_back(windowTarget(name, dir.filePath(name)));
  if (auto e = sl::checkOutputTargets(targets, windowInputs(w_))) return QString::fromStdString(*e);
  return std::nullopt;
}

GrabRun::GrabRun(MainWindow& window) : QObject(&window), w_(window) {
  timer_.setInterval(kGrabTickMs);
  connect(&timer_, &QTimer::timeout, this, &GrabRun::tick);
}

void GrabRun::start(const QString& dir, int frames) {
  // Before any frame: DIR must take every file of the grab without replacing an input of the
  // run (a session, a scene's buffer named published.json) or writing into a FIFO or device.
  if (auto e = checkGrabFiles(dir, true)) {
    printErr(QStringLiteral("--grab: ") + *e);
    QTimer::singleShot(0, this, [] { QCoreApplication::exit(2); });
    return;
  }
  dir_ = dir;
  frames_ = frames;
  clock_.start();
  timer_.start();
  w_.updatePublishing();
}

void GrabRun::noteProblem(const QString& message) {
  // Kept from the window's start (problems before the grab count too), each once, bounded.
  if (problems_.size() < kMaxNotedProblems && !problems_.contains(message)) problems_ << message;
}

void GrabRun::tick() {
  if (w_.failed()) return timer_.stop();
  if (!w_.rendererBound()) {
    if (clock_.elapsed() > kGrabTimeoutMs) {
      timer_.stop();
      w_.report(tr("--grab: the renderer did not start within %1 s (no OpenGL context?)")
                    .arg(kGrabTimeoutMs / 1000));
      QCoreApplication::exit(1);
    }
    return;
  }
  if (framesRendered_ < frames_ || w_.lessons()->settling()) {
    w_.viewport()->frames()->requestFrame();
    return;
  }
  timer_.stop();
  finish();
}

void GrabRun::finish() {
  // The status line shows the error of the grabbed view. Then freeze the frame, so that
  // the window, the viewport, every panel and published.json show the same frame.
  ViewportWidget* viewport = w_.viewport();
  viewport->measure()->computeErrorNow();
  w_.waitForFrames(1);  // the error overlay, when on, needs a frame drawn with the reference
  viewport->frames()->setPaused(true, false);
  QCoreApplication::processEvents(QEventLoop::ExcludeUserInputEvents);
  if (const sl::ViewSide* r = viewport->mainSide()) w_.docks().feed(*r, true);

  QStringList failures;
  if (auto e = checkGrabFiles(dir_, true)) failures << *e;  // checked again: files may have come
  if (failures.isEmpty()) failures << writeImages(dir_, true);
  if (failures.isEmpty()) {
    const QString path = QDir(dir_).absoluteFilePath(QStringLiteral("published.json"));
    if (auto e = writeWindowOutput(w_, path, QJsonDocument(publicationJson()).toJson()))
      failures << *e;
    else
      std::printf("%s\n", path.toLocal8Bit().constData());
  }
  std::fflush(stdout);
  for (const QString& problem : problems_) failures << tr("grab failed: %1").arg(problem);
  for (const QString& f : failures) printErr(f);
  QCoreApplication::exit(failures.isEmpty() ? 0 : 1);
}

QStringList GrabRun::writeImages(const QString& dirPath, bool printPaths) {
  QStringList failures;
  if (auto e = checkGrabFiles(dirPath, false)) return {*e};  // nothing written
  const QDir dir(dirPath);
  auto save = [&](const QImage& image, const QString& name) {
    const QString path = dir.absoluteFilePath(name);
    if (auto e = writeWindowOutput(w_, path, pngBytes(image))) {
      failures << *e;
      return;
    }
    if (printPaths) std::printf("%s\n", path.toLocal8Bit().constData());
  };
  save(w_.grab().toImage(), QStringLiteral("window.png"));
  save(w_.viewport()->grabView(), QStringLiteral("viewport.png"));
  // Tabbed docks: bring each to the front so that it is laid out and painted.
  std::vector<QDockWidget*> front;
  for (QDockWidget* dock : w_.findChildren<QDockWidget*>())
    if (dock->isVisible()) front.push_back(dock);
  for (QDockWidget* dock : w_.findChildren<QDockWidget*>()) {
    if (dock->isHidden() && !dock->toggleViewAction()->isChecked()) continue;  // closed
    dock->raise();
    QCoreApplication::processEvents(QEventLoop::ExcludeUserInputEvents);
    save(dock->grab().toImage(), panelFileName(dock));
  }
  for (QDockWidget* dock : front) dock->raise();
  QCoreApplication::processEvents(QEventLoop::ExcludeUserInputEvents);
  return failures;
}

QJsonObject GrabRun::publicationJson() const {
  QJsonObject o;
  const ViewportWidget* viewport = w_.viewport();
  const sl::ViewSide* r = viewport->mainSide();
  if (!r) return o;
  const sl::Publication& pub = r->publication();
  o[QStringLiteral("frame")] = static_cast<qint64>(pub.frameIndex);
  o[QStringLiteral("technique")] = QString::fromStdString(r->techniqueId());
  o[QStringLiteral("published_technique")] = QString::fromStdString(pub.techniqueId);
  o[QStringLiteral("scene")] = w_.sceneSpec();
  QJsonObject numbers;
  for (const auto& [key, value] : pub.numbers)  // JSON has no inf or NaN: named (JsonNumber.h)
    numbers[QString::fromStdString(key)] =
        sl::nonFiniteName(value) ? QJsonValue(QString::fromLatin1(sl::nonFiniteName(value)))
                                 : QJsonValue(value);
  o[QStringLiteral("numbers")] = numbers;
  // The parameters this frame rendered with, as the Parameters dock shows them (the
  // technique's own and the shared ones): what a preset or lesson set can be checked here.
  QJsonObject params;
  sl::ViewSide* live = w_.viewport()->mainSide();  // the parameter sets are reached non-const
  for (const sl::ParamSet* set : {&live->params(), &live->rendererParams()})
    for (const sl::ParamDecl& d : set->decls())
      params[QString::fromStdString(d.key)] = QString::fromStdString(set->format(d.key));
  o[QStringLiteral("params")] = params;
  QJsonObject images;
  for (const auto& [key, image] : pub.images)
    images[QString::fromStdString(key)] = QJsonArray{image.width, image.height, image.channels};
  o[QStringLiteral("images")] = images;
  QJsonObject curves;
  for (const auto& [key, curve] : pub.curves)
    curves[QString::fromStdString(key)] = static_cast<qint64>(curve.size());
  o[QStringLiteral("curves")] = curves;
  QJsonArray requested;
  for (const std::string& key : pub.requested) requested.append(QString::fromStdString(key));
  o[QStringLiteral("requested")] = requested;
  o[QStringLiteral("publication_bytes")] = static_cast<qint64>(r->stats().publicationBytes);
  o[QStringLiteral("panels")] = w_.docks().drawnValues();
  o[QStringLiteral("placeholders")] = w_.docks().placeholders();
  // The docks a user sees: open, and not a tab behind another or off the window.
  QJsonArray inView;
  for (const QDockWidget* dock : w_.findChildren<QDockWidget*>())
    if (dock->isVisible() && !dock->visibleRegion().isEmpty()) inView.append(dock->objectName());
  o[QStringLiteral("docks_in_view")] = inView;
  // A failed frame has no time (null, frame_failure says why), as the status line's "frame n/a".
  o[QStringLiteral("frame_ms")] =
      viewport->frames()->frameFailure().isEmpty() ? QJsonValue(r->stats().totalMs) : QJsonValue();
  // What the status line showed for the error ("error 0.420 %", "error n/a (why)").
  o[QStringLiteral("error_readout")] = w_.statusLine()->errorLabel()->text();
  // The Timing panel's summary line (a failed frame: "total <b>n/a</b> (the frame failed: …)").
  o[QStringLiteral("timing_summary")] = w_.timingPanel()->summaryText();
  // Never 0 for a frame that measured nothing: null, and why.
  if (auto error = viewport->measure()->errorPct())
    o[QStringLiteral("error_pct")] = *error;
  else if (!viewport->measure()->errorNotMeasured().isEmpty()) {
    o[QStringLiteral("error_pct")] = QJsonValue::Null;
    o[QStringLiteral("error_unmeasured")] = viewport->measure()->errorNotMeasured();
  }
  if (!viewport->frames()->frameFailure().isEmpty())
    o[QStringLiteral("frame_failure")] = viewport->frames()->frameFailure();
  if (!viewport->frames()->splitTechnique().empty()) {
    o[QStringLiteral("split_technique")] =
        QString::fromStdString(viewport->frames()->splitTechnique());
    // The right half's error, or null when it measured nothing (its caption says why).
    const auto split = viewport->measure()->splitErrorPct();
    o[QStringLiteral("split_error_pct")] = split ? QJsonValue(*split) : QJsonValue();
    o[QStringLiteral("split_caption")] = viewport->readouts().rightCaption;
  }
  return o;
}

}  // namespace sl::ui
