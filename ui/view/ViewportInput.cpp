// The view's input (see ViewportWidget.h): left-drag orbit, right/middle-drag (or
// Shift+left) pan, Ctrl+left look, Alt+left moves the light, wheel dolly, WASD/QE fly,
// Ctrl+Shift+drag the zoom inset; in the outside view, drag and wheel move the third camera.
// Camera and light changes go out as frame requests; nothing here waits for a frame.
#include <algorithm>
#include <cmath>

#include <QGuiApplication>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QWheelEvent>

#include "view/ViewportWidget.h"
#include "window/WindowShortcuts.h"
#include "algo/CameraNavigation.h"

namespace sl::ui {

void ViewportWidget::dragLight(const QPoint& d) {
  sl::Light l = light_;
  if (l.type == sl::LightType::Directional) {
    l.azimuthDeg = std::remainder(l.azimuthDeg + float(d.x()) * 0.5f, 360.0f);
    l.elevationDeg = std::clamp(l.elevationDeg - float(d.y()) * 0.5f, 1.0f, 90.0f);
  } else {
    // Move on the horizontal plane through the light, right/forward as the camera sees it.
    const glm::vec3 fw = camera_.forward();
    glm::vec3 forward(fw.x, 0.0f, fw.z);
    if (glm::length(forward) < 1e-3f) forward = glm::vec3(0, 0, -1);
    forward = glm::normalize(forward);
    const glm::vec3 right(-forward.z, 0.0f, forward.x);
    const float distM = std::max(0.1f, glm::length(l.positionM - camera_.position));
    const float mPerPixel = 2.0f * distM * std::tan(glm::radians(camera_.fovYDeg) * 0.5f) /
                            float(std::max(1, height()));
    l.positionM += right * (float(d.x()) * mPerPixel) - forward * (float(d.y()) * mPerPixel);
  }
  if (!l.validate()) setLight(l);
}

void ViewportWidget::adjustOutsideView(float azimuthDeg, float elevationDeg, float zoomFactor) {
  auto clampSet = [&](const char* key, double v) {
    const sl::ParamDecl* d = shared_.find(key);
    if (d) (void)shared_.set(key, std::clamp(v, d->minValue, d->maxValue));
  };
  const double az = std::remainder(shared_.get("view.outside.azimuth_deg") + azimuthDeg, 360.0);
  clampSet("view.outside.azimuth_deg", az);
  clampSet("view.outside.elevation_deg", shared_.get("view.outside.elevation_deg") + elevationDeg);
  clampSet("view.outside.zoom", shared_.get("view.outside.zoom") * zoomFactor);
  requestFrame();
}

// --- Mouse: left-drag orbit, right/middle-drag (or shift+left) pan, ctrl+left look, alt+left
// moves the light, wheel dolly.

void ViewportWidget::mousePressEvent(QMouseEvent* event) {
  constexpr Qt::KeyboardModifiers kZoomMods = Qt::ControlModifier | Qt::ShiftModifier;
  if (event->button() == Qt::LeftButton && (event->modifiers() & kZoomMods) == kZoomMods &&
      dragButton_ == Qt::NoButton) {  // the zoom inset's area
    zoomDragStart_ = event->position().toPoint();
    zoomDragging_ = QRect(zoomDragStart_, QSize(1, 1));
    event->accept();
    return;
  }
  if (dragButton_ == Qt::NoButton) {
    dragButton_ = event->button();
    lastMouse_ = event->position().toPoint();
  }
  setFocus(Qt::MouseFocusReason);
  event->accept();
}

void ViewportWidget::mouseMoveEvent(QMouseEvent* event) {
  const QPoint pos = event->position().toPoint();
  if (zoomDragging_) {
    zoomDragging_ = QRect(zoomDragStart_, pos).normalized().intersected(rect());
    updateOverlayWidget();
    return;
  }
  if (pointerHighlight_ && dragButton_ == Qt::NoButton) {
    hover_ = event->position();
    updateOverlayWidget();
  }
  if (dragButton_ == Qt::NoButton) {
    hover_ = event->position();
    if (!probeWanted_) return;  // no visible panel shows it: no readback
    probeHover();
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
  if (outsideView() && dragButton_ == Qt::LeftButton && !(mods & Qt::ShiftModifier)) {
    // Outside view: the drag orbits the third camera, the main camera stays.
    const float degPerPx = sl::orbitDegPerPixel(height());
    adjustOutsideView(-d.x() * degPerPx, d.y() * degPerPx, 1.0f);
    return;
  }
  // Rates from algo/CameraNavigation: per view height, so that a drag turns or pans as far at
  // any window size (a pan keeps the point under the cursor, at the target's depth, under it).
  const float dx = static_cast<float>(d.x()), dy = static_cast<float>(d.y());
  sl::Camera cam;
  if (dragButton_ == Qt::LeftButton && (mods & Qt::ControlModifier))
    cam = sl::lookByDrag(camera_, dx, dy, height());
  else if (dragButton_ == Qt::LeftButton && !(mods & Qt::ShiftModifier))
    cam = sl::orbitByDrag(camera_, dx, dy, height());
  else
    cam = sl::panByDrag(camera_, dx, dy, height());
  if (!cam.validate()) setCamera(cam);
}

void ViewportWidget::leaveEvent(QEvent* event) {
  hover_ = QPointF(-1.0, -1.0);
  Q_EMIT pixelProbed(std::nullopt);
  if (pointerHighlight_) updateOverlayWidget();
  QWidget::leaveEvent(event);
}

void ViewportWidget::mouseReleaseEvent(QMouseEvent* event) {
  if (zoomDragging_ && event->button() == Qt::LeftButton) {
    const QRect area = *zoomDragging_;
    zoomDragging_.reset();
    // A click (no real rectangle) clears the inset.
    setZoomArea(area.width() >= 4 && area.height() >= 4 ? std::optional<QRect>(area)
                                                        : std::nullopt);
    return;
  }
  if (event->button() == dragButton_) dragButton_ = Qt::NoButton;
  if (!errorIsCurrent()) errorTimer_.start(kErrorDelayMs);
}

void ViewportWidget::wheelEvent(QWheelEvent* event) {
  const float steps = static_cast<float>(event->angleDelta().y()) / 120.0f;
  if (steps == 0.0f) return;
  if (outsideView()) {
    adjustOutsideView(0.0f, 0.0f, sl::dollyFactor(steps));
    event->accept();
    return;
  }
  // A share of the distance to the target per notch, never through it nor beyond a few scene
  // sizes (algo/CameraNavigation).
  const sl::Camera cam = sl::dollyByWheel(camera_, steps, scene_ ? scene_->bounds : sl::Aabb{});
  if (!cam.validate()) setCamera(cam);
  event->accept();
}

// --- Keys: WASD move, Q/E down/up, shift = faster. ui/window/WindowShortcuts sends them here from
// anywhere in the window; the view's own key events take the same way.

void ViewportWidget::keyPressEvent(QKeyEvent* event) {
  if ((event->modifiers() & (Qt::ControlModifier | Qt::AltModifier)) ||
      !flyKeyPressed(event->key(), event->isAutoRepeat())) {
    QWidget::keyPressEvent(event);
    return;
  }
  event->accept();
}

void ViewportWidget::keyReleaseEvent(QKeyEvent* event) {
  if (!flyKeyReleased(event->key(), event->isAutoRepeat())) {
    QWidget::keyReleaseEvent(event);
    return;
  }
  event->accept();
}

bool ViewportWidget::flyKeyPressed(int key, bool autoRepeat) {
  if (!WindowShortcuts::isFlyKey(key)) return false;
  if (!autoRepeat) heldKeys_.insert(key);
  if (!heldKeys_.empty() && !flyTimer_.isActive()) {
    flyClock_.start();
    flyTimer_.start();
    flyStep();
  }
  return true;
}

bool ViewportWidget::flyKeyReleased(int key, bool autoRepeat) {
  if (!WindowShortcuts::isFlyKey(key)) return false;
  if (!autoRepeat) heldKeys_.erase(key);
  if (heldKeys_.empty()) flyTimer_.stop();
  return true;
}

void ViewportWidget::stopFlying() {
  heldKeys_.clear();
  flyTimer_.stop();
}

void ViewportWidget::focusOutEvent(QFocusEvent* event) {
  // Held fly keys are the window's (their releases reach the view wherever the focus is);
  // a window that loses the keyboard lets go of them.
  if (event->reason() == Qt::ActiveWindowFocusReason) stopFlying();
  dragButton_ = Qt::NoButton;
  QWidget::focusOutEvent(event);
}

void ViewportWidget::flyStep() {
  if (heldKeys_.empty()) {
    flyTimer_.stop();
    return;
  }
  // A share of the scene's size per second (algo/CameraNavigation), Shift four times faster.
  const float dtS = static_cast<float>(flyClock_.restart()) / 1000.0f;
  const bool fast = QGuiApplication::keyboardModifiers().testFlag(Qt::ShiftModifier);
  const float stepM =
      sl::flyStepM(sl::navigationScaleM(scene_ ? scene_->bounds : sl::Aabb{}, camera_), dtS, fast);
  auto axis = [this](int plus, int minus) {
    return (heldKeys_.count(plus) ? 1.0f : 0.0f) - (heldKeys_.count(minus) ? 1.0f : 0.0f);
  };
  sl::Camera cam = camera_;
  cam.fly(axis(Qt::Key_W, Qt::Key_S) * stepM, axis(Qt::Key_D, Qt::Key_A) * stepM,
          axis(Qt::Key_E, Qt::Key_Q) * stepM);
  if (!cam.validate()) setCamera(cam);
}

}  // namespace sl::ui
