// The 3D view (see ViewportWidget.h). Every renderer call that may touch GL runs with this
// widget's context current; the widget itself issues no GL calls.
#include "ViewportWidget.h"

#include <algorithm>
#include <cmath>

#include <QGuiApplication>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QWheelEvent>

#include "GlSupport.h"

namespace sl::ui {

namespace {
constexpr float kOrbitDegPerPixel = 0.35f;
constexpr float kLookDegPerPixel = 0.15f;
constexpr float kDollyPerWheelStep = 0.85f;  ///< distance factor per wheel notch (towards)
constexpr float kFlySceneFractionPerS = 0.35f;
constexpr float kFastFlyFactor = 4.0f;
constexpr int kFlyTickMs = 16;

bool isFlyKey(int key) {
  switch (key) {
    case Qt::Key_W:
    case Qt::Key_A:
    case Qt::Key_S:
    case Qt::Key_D:
    case Qt::Key_Q:
    case Qt::Key_E:
      return true;
    default:
      return false;
  }
}

double errorPercentOf(const sl::ShadowErrorStats& stats) {
  return stats.errorPct;
}
}  // namespace

ViewportWidget::ViewportWidget(QWidget* parent) : QOpenGLWidget(parent) {
  setFocusPolicy(Qt::StrongFocus);
  setMinimumSize(160, 120);
  errorTimer_.setSingleShot(true);
  connect(&errorTimer_, &QTimer::timeout, this, &ViewportWidget::computeErrorIfStill);
  flyTimer_.setInterval(kFlyTickMs);
  connect(&flyTimer_, &QTimer::timeout, this, &ViewportWidget::flyStep);
}

ViewportWidget::~ViewportWidget() {
  destroyRenderer();
}

void ViewportWidget::initializeGL() {
  // A new context (first show, or after re-parenting): free the renderer with it.
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &ViewportWidget::destroyRenderer,
          Qt::UniqueConnection);
  // Signals go out queued: their receivers may open dialogs, which must not happen while
  // Qt is inside initializeGL.
  auto fail = [this](const QString& message) {
    QMetaObject::invokeMethod(
        this, [this, message] { Q_EMIT initializationFailed(message); }, Qt::QueuedConnection);
  };
  if (auto problem = checkContext(*context())) return fail(*problem);
  try {
    renderer_ = std::make_unique<sl::Renderer>();
  } catch (const std::exception& e) {
    return fail(
        QStringLiteral("the renderer could not start: %1").arg(QString::fromStdString(e.what())));
  }
  applyStateToRenderer();
  QMetaObject::invokeMethod(
      this, [this] { Q_EMIT rendererReady(); }, Qt::QueuedConnection);
}

void ViewportWidget::applyStateToRenderer() {
  if (scene_) renderer_->setScene(scene_);
  if (!techniqueId_.empty()) {
    if (auto error = renderer_->setTechnique(techniqueId_))
      Q_EMIT renderProblem(QString::fromStdString(*error));
  }
  techniqueId_ = renderer_->techniqueId();
  renderer_->setCamera(camera_);
  renderer_->setLight(light_);
  lastTechniqueId_.clear();
}

void ViewportWidget::destroyRenderer() {
  if (!renderer_) return;
  Q_EMIT rendererAboutToBeDestroyed();
  makeCurrent();
  renderer_.reset();
  doneCurrent();
}

void ViewportWidget::paintGL() {
  if (!renderer_) return;
  // Parameters are edited by panels directly in the renderer's ParamSets: notice it here.
  if (renderer_->techniqueId() != lastTechniqueId_ ||
      renderer_->params().revision() != lastParamRevision_ ||
      renderer_->rendererParams().revision() != lastRendererParamRevision_) {
    lastTechniqueId_ = renderer_->techniqueId();
    lastParamRevision_ = renderer_->params().revision();
    lastRendererParamRevision_ = renderer_->rendererParams().revision();
    markViewChanged();
  }
  renderer_->setCamera(camera_);
  renderer_->setLight(light_);
  const qreal dpr = devicePixelRatioF();
  const int w = static_cast<int>(std::lround(width() * dpr));
  const int h = static_cast<int>(std::lround(height() * dpr));

  std::optional<std::string> error;
  try {
    error = renderer_->renderFrame(w, h, defaultFramebufferObject());
  } catch (const std::exception& e) {
    error = std::string("renderer: ") + e.what();
  }
  ++framesRendered_;
  std::string problem = error.value_or(std::string());
  for (const std::string& glError : renderer_->takeGlErrors())
    problem += (problem.empty() ? "" : "; ") + glError;
  if (!problem.empty() && problem != lastProblem_)
    Q_EMIT renderProblem(QString::fromStdString(problem));
  lastProblem_ = problem;

  Q_EMIT frameRendered();
  if (!errorIsCurrent()) errorTimer_.start(kErrorDelayMs);  // restarts: waits for stillness
  if (continuous_) update();
}

void ViewportWidget::resizeGL(int, int) {
  markViewChanged();
}

void ViewportWidget::setScene(std::shared_ptr<const sl::Scene> scene) {
  scene_ = std::move(scene);
  if (scene_ && scene_->sun) light_ = *scene_->sun;
  if (renderer_) {
    makeCurrent();
    renderer_->setScene(scene_);
    renderer_->setLight(light_);
    renderer_->resetTemporalState();
    doneCurrent();
  }
  resetView();
}

std::optional<std::string> ViewportWidget::setTechnique(const std::string& id) {
  if (!renderer_) {
    if (!sl::Renderer::findTechnique(id)) {
      std::string known;
      for (const sl::TechniqueInfo& t : sl::Renderer::techniques())
        known += (known.empty() ? "" : ", ") + t.id;
      return "unknown technique '" + id + "' (known: " + known + ")";
    }
    techniqueId_ = id;
    return std::nullopt;
  }
  makeCurrent();
  auto error = renderer_->setTechnique(id);
  doneCurrent();
  if (error) return error;
  techniqueId_ = renderer_->techniqueId();
  update();
  return std::nullopt;
}

void ViewportWidget::setCamera(const sl::Camera& camera) {
  camera_ = camera;
  markViewChanged();
  Q_EMIT cameraChanged();
  update();
}

void ViewportWidget::goToBookmark(int index) {
  if (!scene_) return;
  if (index >= 0 && index < static_cast<int>(scene_->cameras.size()))
    setCamera(scene_->cameras[static_cast<size_t>(index)].camera);
  else
    setCamera(scene_->defaultCamera());
}

void ViewportWidget::resetView() {
  goToBookmark(0);
}

void ViewportWidget::setLight(const sl::DirectionalLight& light) {
  light_ = light;
  markViewChanged();
  update();
}

void ViewportWidget::setContinuous(bool on) {
  continuous_ = on;
  if (on) update();
}

std::optional<double> ViewportWidget::computeErrorNow() {
  if (!renderer_ || framesRendered_ == 0) return std::nullopt;
  makeCurrent();
  std::optional<double> pct;
  try {
    pct = errorPercentOf(renderer_->computeError().stats);
  } catch (const std::exception& e) {
    Q_EMIT renderProblem(
        QStringLiteral("error metric failed: %1").arg(QString::fromStdString(e.what())));
  }
  doneCurrent();
  if (!pct) return std::nullopt;
  errorRevision_ = viewRevision_;
  Q_EMIT errorComputed(*pct);
  return pct;
}

std::optional<std::string> ViewportWidget::reloadShaders() {
  if (!renderer_) return std::string("the renderer is not running");
  makeCurrent();
  auto error = renderer_->reloadShaders();
  doneCurrent();
  markViewChanged();
  update();
  return error;
}

void ViewportWidget::computeErrorIfStill() {
  if (errorIsCurrent()) return;
  if (dragButton_ != Qt::NoButton || !heldKeys_.empty()) {
    errorTimer_.start(kErrorDelayMs);  // still interacting: try again later
    return;
  }
  computeErrorNow();
}

void ViewportWidget::markViewChanged() {
  ++viewRevision_;
  Q_EMIT viewChanged();
}

float ViewportWidget::sceneScaleM() const {
  if (scene_ && scene_->bounds.valid()) return std::max(0.5f, glm::length(scene_->bounds.size()));
  return std::max(0.5f, glm::length(camera_.position - camera_.target));
}

// --- Mouse: left-drag orbit, right/middle-drag (or shift+left) pan, ctrl+left look, wheel dolly.

void ViewportWidget::mousePressEvent(QMouseEvent* event) {
  if (dragButton_ == Qt::NoButton) {
    dragButton_ = event->button();
    lastMouse_ = event->position().toPoint();
  }
  setFocus(Qt::MouseFocusReason);
  event->accept();
}

void ViewportWidget::mouseMoveEvent(QMouseEvent* event) {
  if (dragButton_ == Qt::NoButton) return;
  const QPoint pos = event->position().toPoint();
  const QPoint d = pos - lastMouse_;
  lastMouse_ = pos;
  if (d.isNull()) return;
  const Qt::KeyboardModifiers mods = event->modifiers();
  sl::Camera cam = camera_;
  if (dragButton_ == Qt::LeftButton && (mods & Qt::ControlModifier)) {
    cam.look(-d.x() * kLookDegPerPixel, -d.y() * kLookDegPerPixel);
  } else if (dragButton_ == Qt::LeftButton && !(mods & Qt::ShiftModifier)) {
    cam.orbit(-d.x() * kOrbitDegPerPixel, d.y() * kOrbitDegPerPixel);
  } else {
    // Pan so that the point under the cursor (at the target's depth) follows the cursor.
    const float distM = glm::length(cam.position - cam.target);
    const float mPerPixel =
        2.0f * distM * std::tan(glm::radians(cam.fovYDeg) * 0.5f) / std::max(1, height());
    cam.pan(-d.x() * mPerPixel, d.y() * mPerPixel);
  }
  if (!cam.validate()) setCamera(cam);
}

void ViewportWidget::mouseReleaseEvent(QMouseEvent* event) {
  if (event->button() == dragButton_) dragButton_ = Qt::NoButton;
  if (!errorIsCurrent()) errorTimer_.start(kErrorDelayMs);
}

void ViewportWidget::wheelEvent(QWheelEvent* event) {
  const float steps = static_cast<float>(event->angleDelta().y()) / 120.0f;
  if (steps == 0.0f) return;
  sl::Camera cam = camera_;
  cam.dolly(std::pow(kDollyPerWheelStep, steps));
  if (!cam.validate()) setCamera(cam);
  event->accept();
}

// --- Keys: WASD move, Q/E down/up, shift = faster.

void ViewportWidget::keyPressEvent(QKeyEvent* event) {
  if (!isFlyKey(event->key()) || (event->modifiers() & (Qt::ControlModifier | Qt::AltModifier))) {
    QOpenGLWidget::keyPressEvent(event);
    return;
  }
  if (!event->isAutoRepeat()) heldKeys_.insert(event->key());
  if (!flyTimer_.isActive()) {
    flyClock_.start();
    flyTimer_.start();
    flyStep();
  }
  event->accept();
}

void ViewportWidget::keyReleaseEvent(QKeyEvent* event) {
  if (!isFlyKey(event->key())) {
    QOpenGLWidget::keyReleaseEvent(event);
    return;
  }
  if (!event->isAutoRepeat()) heldKeys_.erase(event->key());
  if (heldKeys_.empty()) flyTimer_.stop();
  event->accept();
}

void ViewportWidget::focusOutEvent(QFocusEvent* event) {
  heldKeys_.clear();
  flyTimer_.stop();
  dragButton_ = Qt::NoButton;
  QOpenGLWidget::focusOutEvent(event);
}

void ViewportWidget::flyStep() {
  if (heldKeys_.empty()) {
    flyTimer_.stop();
    return;
  }
  const float dtS = std::clamp(static_cast<float>(flyClock_.restart()) / 1000.0f, 0.001f, 0.1f);
  float speed = sceneScaleM() * kFlySceneFractionPerS;
  if (QGuiApplication::keyboardModifiers() & Qt::ShiftModifier) speed *= kFastFlyFactor;
  auto axis = [this](int plus, int minus) {
    return (heldKeys_.count(plus) ? 1.0f : 0.0f) - (heldKeys_.count(minus) ? 1.0f : 0.0f);
  };
  const float stepM = speed * dtS;
  sl::Camera cam = camera_;
  cam.fly(axis(Qt::Key_W, Qt::Key_S) * stepM, axis(Qt::Key_D, Qt::Key_A) * stepM,
          axis(Qt::Key_E, Qt::Key_Q) * stepM);
  if (!cam.validate()) setCamera(cam);
}

}  // namespace sl::ui
