// What the 3D view draws (a part of ViewportWidget): the frame on screen (ViewModel's images,
// a reduced adaptive frame stretched smoothly), and over it the overlay (ViewOverlay): the
// banner, the legends of the renderer's overlays, the split view's captions, the resolution,
// busy and error notes, the paused badge, the zoom inset, the pointer ring and the light
// gizmo. It reads the other parts and never asks for a frame.
#pragma once

#include <optional>

#include <QObject>
#include <QRect>
#include <QString>
#include "view/ViewParts.h"

namespace sl::ui {

class ViewOverlay;

class ViewPainter : public QObject {
  Q_OBJECT

 public:
  ViewPainter(QWidget& widget, const ViewModel& model, const CameraController& camera,
              const FrameLoop& frames, const MeasureService& measure);

  /// Draws the frame on screen over the whole widget (its paintEvent).
  void paint();
  /// The widget was resized: the overlay covers it.
  void resized();

  /// Presenter mode: a ring follows the mouse over the view (the pointer highlight).
  void setPointerHighlight(bool on);
  bool pointerHighlight() const { return pointerHighlight_; }
  /// The zoom inset: `area` of the view (widget pixels) magnified by a whole factor,
  /// nearest neighbour, into the bottom-right corner; nothing: off. Ctrl+Shift+drag over the
  /// view sets it, Ctrl+Shift+click clears it.
  void setZoomArea(const std::optional<QRect>& area);
  std::optional<QRect> zoomArea() const { return zoomArea_; }
  /// Where the inset was last drawn (empty when off) and its magnification (0 when off).
  QRect zoomInset() const;
  int zoomFactor() const;
  /// A banner over the top of the view (lesson title, pass being stepped); empty: none.
  void setBanner(const QString& title, const QString& text);
  /// The captions under the split view's halves (empty: none) and the line under the error
  /// overlay's legend, as last drawn.
  QString caption(bool right) const;
  QString errorOverlayNote() const;

  /// Puts the view's state into the overlay (captions, legends, notes, badge, gizmo).
  void updateOverlay();
  /// A new frame is on screen: the zoom inset's source, the overlay and the view are redrawn.
  void frameShown();

 private:
  /// The zoom inset's source: the view as shown, in device pixels.
  void updateZoomInset();

  QWidget& widget_;
  const ViewModel& model_;
  const CameraController& camera_;
  const FrameLoop& frames_;
  const MeasureService& measure_;
  ViewOverlay* overlay_ = nullptr;
  bool pointerHighlight_ = false;
  std::optional<QRect> zoomArea_;  ///< widget pixels
};

}  // namespace sl::ui
