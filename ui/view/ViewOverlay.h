// What the view draws over the rendered image: the split view's right half, the captions,
// the banner, the pause badge, the busy note, the overlay legends, the light gizmo, the
// zoom inset and the presenter's pointer ring. Plain QPainter, no GL.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include <QImage>
#include <QLineF>
#include <QPointF>
#include <QRect>
#include <QString>
#include <QVector>
#include <QWidget>

#include "algo/Params.h"
#include "core/FrameStats.h"

namespace sl::ui {

/// Drawn over the view (a plain child widget, composited by Qt; no GL): the split view's
/// right half, the captions, the banner, the pause badge and the overlay legends.
class ViewOverlay : public QWidget {
 public:
  explicit ViewOverlay(QWidget* parent) : QWidget(parent) {
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
  }

  QImage split;  ///< right half (device pixels), null when the split view is off
  QString leftCaption, rightCaption, bannerTitle, bannerText, pausedText;
  enum class Legend { None, Error, Aliasing, WarpGrid, Changed } legend = Legend::None;
  /// The outside view's line colours and what they stand for (empty: not in outside view).
  QVector<QPair<QColor, QString>> outsideLegend;
  /// The light gizmo (widget pixels): lines, and the light's own point when on screen.
  QVector<QLineF> gizmoLines;
  std::optional<QPointF> gizmoPoint;
  QString errorNote;  ///< under the error legend: the reference's state, empty when current
  /// Under the aliasing legend: what the main technique's own pattern in m comes from
  /// (TechniqueInfo::aliasingPattern), empty when it draws none.
  QString aliasingNote;
  QString resolutionNote;  ///< adaptive resolution: the internal size and why (empty: full)
  /// The changed overlay's count (pixels whose hard test flipped since the last frame, of
  /// those covered in both), or nothing yet.
  std::optional<std::pair<std::uint64_t, std::uint64_t>> changedCount;
  std::optional<QPointF> pointerRing;  ///< presenter mode's pointer highlight (widget px)
  QImage zoomSource;                   ///< the zoom area's pixels, device pixels
  QRect zoomArea;                      ///< widget pixels (empty: no inset)
  QRect zoomDrag;                      ///< the rectangle being dragged (empty: none)
  QRect insetRect;                     ///< where paintEvent drew the inset (widget px)
  int insetFactor = 0;

  /// One box of text (or the zoom inset) the overlay draws, in widget pixels.
  enum class Role {
    Banner,
    Paused,
    OutsideLegend,
    LeftCaption,
    RightCaption,
    Legend,
    Note,
    Inset,
    InsetLabel
  };
  struct Box {
    Role role;
    QRectF rect;
  };
  /// Where every box goes at the widget's size and font, the order they are placed in: the
  /// banner top left, the pause badge and the outside view's legend top right, the captions at
  /// the bottom, the overlay legend bottom left, the note (reduced resolution, "computing ...")
  /// and the zoom inset bottom right. A box never covers one placed before it: a top box moves
  /// down under it, a bottom box up over it; the inset shrinks to a smaller magnification, or
  /// is left out, when it would cover another box.
  QVector<Box> layout() const;
  /// Places the zoom inset (insetRect, insetFactor) as layout() does: the largest whole
  /// magnification of `zoomArea` that fits in 45 % of the view's width and height, in the
  /// bottom-right corner, clear of the other boxes.
  void placeInset();
  static const char* roleName(Role role);
  /// The legends of the renderer's overlays (view.overlay), the changed overlay's count,
  /// the aliasing note of the main technique (`aliasingPattern`) and the outside view's line
  /// colours, from the shared parameters and the last main frame.
  void setLegends(const sl::ParamSet& shared, const sl::FrameStats& stats, bool outside,
                  const std::string& aliasingPattern);

  bool hasContent() const {
    return !split.isNull() || !bannerTitle.isEmpty() || !bannerText.isEmpty() || pointerRing ||
           !zoomArea.isEmpty() || !zoomDrag.isEmpty() || changedCount || !pausedText.isEmpty() ||
           legend != Legend::None || !gizmoLines.isEmpty() || gizmoPoint ||
           !outsideLegend.isEmpty() || !resolutionNote.isEmpty();
  }

 protected:
  void paintEvent(QPaintEvent*) override;

 private:
  /// The one-line text of the overlay legend (the aliasing bar's caption, the changed count,
  /// the warp grid's note); empty for the error legend, which has rows.
  QString legendText() const;
  /// The height of aliasingNote wrapped in an aliasing legend `legendWidth` wide.
  int aliasingNoteHeight(double legendWidth) const;
  /// The error legend's two rows (false lit, false shadowed), beside their colours.
  static std::array<QString, 2> errorRows();
  /// insetRect and insetFactor from a layout's Inset box (none: empty, 0).
  void takeInset(const QVector<Box>& boxes);
};

}  // namespace sl::ui
