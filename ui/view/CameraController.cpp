// The view's input (see CameraController.h). Camera and light changes go out as signals
// (the widget turns them into frame requests); nothing here waits for a frame.
#include "view/CameraController.h"

#include <algorithm>
#include <cmath>

#include <QGuiApplication>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QWheelEvent>
#include <QWidget>

#include "algo/CameraNavigation.h"
#include "view/ViewModel.h"
#include "window/WindowShortcuts.h"

namespace sl::ui {

CameraController::CameraController(QWidget& widget, ViewModel& model)
    : QObject(&widget), widget_(widget), model_(model) {
  flyTimer_.setInterval(kFlyTickMs);
  connect(&flyTimer_, &QTimer::timeout, this, &CameraController::flyStep);
  widget_.installEventFilter(this);
}

const sl::Camera& CameraController::camera() const {
  return model_.camera;
}

const sl::Light& CameraController::light() const {
  return model_.light;
}

void CameraController::setCamera(const sl::Camera& camera) {
  model_.camera = camera;
  Q_EMIT viewEdited();
  Q_EMIT cameraChanged();
  Q_EMIT frameWanted();
}

void CameraController::goToBookmark(int index) {
  if (!model_.scene) return;
  if (index >= 0 && index < static_cast<int>(model_.scene->cameras.size()))
    setCamera(model_.scene->cameras[static_cast<size_t>(index)].camera);
  else
    setCamera(model_.scene->defaultCamera());
}

void CameraController::resetView() {
  goToBookmark(0);
}

void CameraController::frameScene() {
  if (model_.scene && model_.scene->light) model_.light = *model_.scene->light;
  Q_EMIT lightChanged();
  resetView();
}

bool CameraController::outsideView() const {
  return model_.outsideView();
}

bool CameraController::setOutsideView(bool on) {
  if (!model_.shared.has("view.outside")) return false;
  if (outsideView() == on) return true;
  if (model_.shared.set("view.outside", on ? 1.0 : 0.0)) return false;
  Q_EMIT overlayChanged();
  Q_EMIT frameWanted();
  return true;
}

void CameraController::setLight(const sl::Light& light) {
  if (model_.light == light) return;
  model_.light = light;
  Q_EMIT viewEdited();
  Q_EMIT frameWanted();
  Q_EMIT lightChanged();
}

void CameraController::dragLight(const QPoint& d) {
  sl::Light l = model_.light;
  const sl::Camera& camera = model_.camera;
  if (l.type == sl::LightType::Directional) {
    l.azimuthDeg = std::remainder(l.azimuthDeg + float(d.x()) * 0.5f, 360.0f);
    l.elevationDeg = std::clamp(l.elevationDeg - float(d.y()) * 0.5f, 1.0f, 90.0f);
  } else {
    // Move on the horizontal plane through the light, right/forward as the camera sees it.
    const glm::vec3 fw = camera.forward();
    glm::vec3 forward(fw.x, 0.0f, fw.z);
    if (glm::length(forward) < 1e-3f) forward = glm::vec3(0, 0, -1);
    forward = glm::normalize(forward);
    const glm::vec3 right(-forward.z, 0.0f, forward.x);
    const float distM = std::max(0.1f, glm::length(l.positionM - camera.position));
    const float mPerPixel = 2.0f * distM * std::tan(glm::radians(camera.fovYDeg) * 0.5f) /
                            float(std::max(1, widget_.height()));
    l.positionM += right * (float(d.x()) * mPerPixel) - forward * (float(d.y()) * mPerPixel);
  }
  if (!l.validate()) setLight(l);
}

void CameraController::adjustOutsideView(float azimuthDeg, float elevationDeg, float zoomFactor) {
  sl::ParamSet& shared = model_.shared;
  auto clampSet = [&](const char* key, double v) {
    const sl::ParamDecl* d = shared.find(key);
    if (d) (void)shared.set(key, std::clamp(v, d->minValue, d->maxValue));
  };
  const double az = std::remainder(shared.get("view.outside.azimuth_deg") + azimuthDeg, 360.0);
  clampSet("view.outside.azimuth_deg", az);
  clampSet("view.outside.elevation_deg", shared.get("view.outside.elevation_deg") + elevationDeg);
  clampSet("view.outside.zoom", shared.get("view.outside.zoom") * zoomFactor);
  Q_EMIT frameWanted();
}

bool CameraController::eventFilter(QObject* watched, QEvent* event) {
  if (watched != &widget_) return false;
  switch (event->type()) {
    case QEvent::MouseButtonPress:
      return mousePressed(static_cast<QMouseEvent*>(event));
    case QEvent::MouseMove:
      mouseMoved(static_cast<QMouseEvent*>(event));
      return true;
    case QEvent::MouseButtonRelease:
      mouseReleased(static_cast<QMouseEvent*>(event));
      return true;
    case QEvent::Wheel: {
      auto* wheel = static_cast<QWheelEvent*>(event);
      const float steps = static_cast<float>(wheel->angleDelta().y()) / 120.0f;
      if (steps == 0.0f) return true;
      if (outsideView()) {
        adjustOutsideView(0.0f, 0.0f, sl::dollyFactor(steps));
        return true;
      }
      // A share of the distance to the target per notch, never through it nor beyond a few
      // scene sizes (algo/CameraNavigation).
      const sl::Camera cam =
          sl::dollyByWheel(model_.camera, steps, model_.scene ? model_.scene->bounds : sl::Aabb{});
      if (!cam.validate()) setCamera(cam);
      return true;
    }
    // Keys: WASD move, Q/E down/up, shift = faster. ui/window/WindowShortcuts sends them here
    // from anywhere in the window; the view's own key events take the same way.
    case QEvent::KeyPress: {
      auto* key = static_cast<QKeyEvent*>(event);
      if ((key->modifiers() & (Qt::ControlModifier | Qt::AltModifier)) ||
          !flyKeyPressed(key->key(), key->isAutoRepeat()))
        return false;  // the widget's own handling
      key->accept();
      return true;
    }
    case QEvent::KeyRelease: {
      auto* key = static_cast<QKeyEvent*>(event);
      if (!flyKeyReleased(key->key(), key->isAutoRepeat())) return false;
      key->accept();
      return true;
    }
    case QEvent::Leave:
      model_.hover = QPointF(-1.0, -1.0);
      Q_EMIT hoverLeft();
      return false;
    case QEvent::FocusOut:
      // Held fly keys are the window's (their releases reach the view wherever the focus is);
      // a window that loses the keyboard lets go of them.
      if (static_cast<QFocusEvent*>(event)->reason() == Qt::ActiveWindowFocusReason) stopFlying();
      dragButton_ = Qt::NoButton;
      return false;
    default:
      return false;
  }
}

// --- Mouse: left-drag orbit, right/middle-drag (or shift+left) pan, ctrl+left look, alt+left
// moves the light.

bool CameraController::mousePressed(QMouseEvent* event) {
  constexpr Qt::KeyboardModifiers kZoomMods = Qt::ControlModifier | Qt::ShiftModifier;
  if (event->button() == Qt::LeftButton && (event->modifiers() & kZoomMods) == kZoomMods &&
      dragButton_ == Qt::NoButton) {  // the zoom inset's area
    zoomDragStart_ = event->position().toPoint();
    zoomDragging_ = QRect(zoomDragStart_, QSize(1, 1));
    event->accept();
    return true;
  }
  if (dragButton_ == Qt::NoButton) {
    dragButton_ = event->button();
    lastMouse_ = event->position().toPoint();
  }
  widget_.setFocus(Qt::MouseFocusReason);
  event->accept();
  return true;
}

void CameraController::mouseMoved(QMouseEvent* event) {
  const QPoint pos = event->position().toPoint();
  if (zoomDragging_) {
    zoomDragging_ = QRect(zoomDragStart_, pos).normalized().intersected(widget_.rect());
    Q_EMIT overlayChanged();
    return;
  }
  if (dragButton_ == Qt::NoButton) {
    model_.hover = event->position();
    Q_EMIT hoverMoved();
    return;
  }
  const QPoint d = pos - lastMouse_;
  lastMouse_ = pos;
  if (d.isNull()) return;
  const Qt::KeyboardModifiers mods = event->modifiers();
  if (dragButton_ == Qt::LeftButton && (mods & Qt::AltModifier)) {
    dragLight(d);
    return;
  }
  const int height = widget_.height();
  if (outsideView() && dragButton_ == Qt::LeftButton && !(mods & Qt::ShiftModifier)) {
    // Outside view: the drag orbits the third camera, the main camera stays.
    const float degPerPx = sl::orbitDegPerPixel(height);
    adjustOutsideView(-d.x() * degPerPx, d.y() * degPerPx, 1.0f);
    return;
  }
  // Rates from algo/CameraNavigation: per view height, so that a drag turns or pans as far at
  // any window size (a pan keeps the point under the cursor, at the target's depth, under it).
  const float dx = static_cast<float>(d.x()), dy = static_cast<float>(d.y());
  sl::Camera cam;
  if (dragButton_ == Qt::LeftButton && (mods & Qt::ControlModifier))
    cam = sl::lookByDrag(model_.camera, dx, dy, height);
  else if (dragButton_ == Qt::LeftButton && !(mods & Qt::ShiftModifier))
    cam = sl::orbitByDrag(model_.camera, dx, dy, height);
  else
    cam = sl::panByDrag(model_.camera, dx, dy, height);
  if (!cam.validate()) setCamera(cam);
}

void CameraController::mouseReleased(QMouseEvent* event) {
  if (zoomDragging_ && event->button() == Qt::LeftButton) {
    const QRect area = *zoomDragging_;
    zoomDragging_.reset();
    // A click (no real rectangle) clears the inset.
    Q_EMIT zoomAreaPicked(area.width() >= 4 && area.height() >= 4 ? std::optional<QRect>(area)
                                                                  : std::nullopt);
    return;
  }
  if (event->button() == dragButton_) dragButton_ = Qt::NoButton;
  Q_EMIT dragEnded();
}

bool CameraController::flyKeyPressed(int key, bool autoRepeat) {
  if (!WindowShortcuts::isFlyKey(key)) return false;
  if (!autoRepeat) heldKeys_.insert(key);
  if (!heldKeys_.empty() && !flyTimer_.isActive()) {
    flyClock_.start();
    flyTimer_.start();
    flyStep();
  }
  return true;
}

bool CameraController::flyKeyReleased(int key, bool autoRepeat) {
  if (!WindowShortcuts::isFlyKey(key)) return false;
  if (!autoRepeat) heldKeys_.erase(key);
  if (heldKeys_.empty()) flyTimer_.stop();
  return true;
}

void CameraController::stopFlying() {
  heldKeys_.clear();
  flyTimer_.stop();
}

void CameraController::flyStep() {
  if (heldKeys_.empty()) {
    flyTimer_.stop();
    return;
  }
  // A share of the scene's size per second (algo/CameraNavigation), Shift four times faster.
  const float dtS = static_cast<float>(flyClock_.restart()) / 1000.0f;
  const bool fast = QGuiApplication::keyboardModifiers().testFlag(Qt::ShiftModifier);
  const float stepM = sl::flyStepM(
      sl::navigationScaleM(model_.scene ? model_.scene->bounds : sl::Aabb{}, model_.camera), dtS,
      fast);
  auto axis = [this](int plus, int minus) {
    return (heldKeys_.count(plus) ? 1.0f : 0.0f) - (heldKeys_.count(minus) ? 1.0f : 0.0f);
  };
  sl::Camera cam = model_.camera;
  cam.fly(axis(Qt::Key_W, Qt::Key_S) * stepM, axis(Qt::Key_D, Qt::Key_A) * stepM,
          axis(Qt::Key_E, Qt::Key_Q) * stepM);
  if (!cam.validate()) setCamera(cam);
}

}  // namespace sl::ui
