// The view's camera and light under the mouse and keys (a part of ViewportWidget): left-drag
// orbit, right/middle-drag (or Shift+left) pan, Ctrl+left look, Alt+left moves the light,
// wheel dolly, WASD/QE fly, Ctrl+Shift+drag the zoom inset's area; in the outside view, drag
// and wheel move the third camera. Rates from algo/CameraNavigation. It filters the widget's
// input events and changes the view model; it asks for frames through its signals and never
// waits for one.
#pragma once

#include <optional>
#include <set>

#include <QElapsedTimer>
#include <QObject>
#include <QPoint>
#include <QRect>
#include <QTimer>

#include "core/Renderer.h"

class QWidget;
class QMouseEvent;

namespace sl::ui {

struct ViewModel;

class CameraController : public QObject {
  Q_OBJECT

 public:
  /// Filters `widget`'s mouse, wheel, key and focus events; `model` is the view's state.
  CameraController(QWidget& widget, ViewModel& model);

  void setCamera(const sl::Camera& camera);
  const sl::Camera& camera() const;
  /// Camera of the scene's bookmark `index`, or the framing view for -1.
  void goToBookmark(int index);
  void resetView();
  /// A new scene is shown: the light goes to the scene's sun when it has one and the camera to
  /// its first bookmark (or a framing view).
  void frameScene();
  /// The outside view (the renderer's view.outside): a third camera showing the frusta;
  /// while on, a left drag orbits it and the wheel moves it in or out (main camera fixed).
  bool outsideView() const;
  bool setOutsideView(bool on);  ///< false when the renderer has no such parameter

  void setLight(const sl::Light& light);
  const sl::Light& light() const;

  /// A drag or a held fly key moves the camera now (the view is not still).
  bool interacting() const { return dragButton_ != Qt::NoButton || !heldKeys_.empty(); }
  /// The rectangle while Ctrl+Shift+drag draws the zoom inset's area (widget pixels).
  std::optional<QRect> zoomDrag() const { return zoomDragging_; }

  /// The fly keys' tick while one is held.
  static constexpr int kFlyTickMs = 16;

 public Q_SLOTS:
  /// The fly keys W/S, A/D, Q/E (ui/window/WindowShortcuts sends them from anywhere in the window):
  /// the view flies while one is held. A repeat changes nothing; false for another key.
  bool flyKeyPressed(int key, bool autoRepeat);
  bool flyKeyReleased(int key, bool autoRepeat);
  /// Lets go of every held fly key (the window lost the keyboard).
  void stopFlying();

 Q_SIGNALS:
  /// The camera moved (mouse, keys, bookmark, reset).
  void cameraChanged();
  /// The light changed (setLight, a new scene, Alt+drag in the view).
  void lightChanged();
  /// The image changes (camera or light): the view's revision moves on (sent before
  /// cameraChanged and frameWanted).
  void viewEdited();
  /// A new frame is wanted.
  void frameWanted();
  /// What the overlay draws changed (outside view, the zoom drag, the hover ring).
  void overlayChanged();
  /// The mouse moved over the view without a drag (the model's hover is where).
  void hoverMoved();
  /// The mouse left the view (the model's hover is cleared).
  void hoverLeft();
  /// A drag ended: the view may be still now.
  void dragEnded();
  /// Ctrl+Shift+drag ended: the zoom inset's new area (nothing: a click, which clears it).
  void zoomAreaPicked(const std::optional<QRect>& area);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  bool mousePressed(QMouseEvent* event);
  void mouseMoved(QMouseEvent* event);
  void mouseReleased(QMouseEvent* event);
  /// Alt+left drag: az/el for a directional light, the position on a horizontal plane
  /// for spot and point (the point under the cursor follows it, at the light's depth).
  void dragLight(const QPoint& delta);
  /// Turns the outside camera and scales its zoom (clamped to the declared ranges).
  void adjustOutsideView(float azimuthDeg, float elevationDeg, float zoomFactor);
  void flyStep();

  QWidget& widget_;
  ViewModel& model_;
  QTimer flyTimer_;  ///< ticks while a fly key is held
  QElapsedTimer flyClock_;
  std::set<int> heldKeys_;
  Qt::MouseButton dragButton_ = Qt::NoButton;
  QPoint lastMouse_;
  std::optional<QRect> zoomDragging_;  ///< the rectangle while Ctrl+Shift+drag draws it
  QPoint zoomDragStart_;
};

}  // namespace sl::ui
