#include "view/ViewOverlay.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <QPainter>

#include "common/shared_constants.h"
#include "algo/OutsideView.h"

namespace sl::ui {

void ViewOverlay::setLegends(const sl::ParamSet& shared, const sl::FrameStats& stats, bool outside,
                             const std::string& aliasingPattern) {
  legend = sl::enumIs(shared, "view.overlay", "error")       ? Legend::Error
           : sl::enumIs(shared, "view.overlay", "aliasing")  ? Legend::Aliasing
           : sl::enumIs(shared, "view.overlay", "warp-grid") ? Legend::WarpGrid
           : sl::enumIs(shared, "view.overlay", "changed")   ? Legend::Changed
                                                             : Legend::None;
  changedCount.reset();
  if (legend == Legend::Changed && stats.maskChange)
    changedCount = std::make_pair(stats.maskChange->changed, stats.maskChange->compared);
  outsideLegend.clear();
  if (outside && stats.outsideCamera) {
    auto colour = [](sl::OutlineRole role, int map) {
      const glm::vec3 c = sl::outlineColour(role, map);
      return QColor::fromRgbF(c.r, c.g, c.b);
    };
    const sl::FrameOutlines& o = stats.outlines;
    auto& rows = outsideLegend;
    rows.append(
        {colour(sl::OutlineRole::Camera, 0), tr("camera frustum (to the scene's far end)")});
    if (!o.splitDepthsM.empty())
      rows.append({colour(sl::OutlineRole::Split, 0), tr("split planes")});
    int maps = 0;
    bool warp = false;
    for (const sl::FrustumOutline& f : o.frusta) {
      if (f.role == sl::OutlineRole::LightMap) maps = std::max(maps, f.map + 1);
      warp = warp || f.role == sl::OutlineRole::Warp;
    }
    for (int i = 0; i < std::min(maps, 8); ++i)
      rows.append({colour(sl::OutlineRole::LightMap, i),
                   maps == 1 ? (warp ? tr("light frustum (unwarped)") : tr("light frustum"))
                             : tr("light frustum, map %1").arg(i)});
    if (warp)
      rows.append({colour(sl::OutlineRole::Warp, 0), tr("warped map's frustum, to its centre")});
    // m and the error are the main camera's pixels' (Renderer: compositeInto): not drawn here.
    if (legend == Legend::Aliasing || legend == Legend::Error) {
      rows.append({QColor(0, 0, 0, 0), legend == Legend::Aliasing
                                           ? tr("aliasing overlay: main view only (V)")
                                           : tr("error overlay: main view only (V)")});
      legend = Legend::None;
    }
  }
  aliasingNote = legend == Legend::Aliasing ? QString::fromStdString(aliasingPattern) : QString();
}

namespace {

constexpr double kGap = 8.0;  ///< between two boxes a collision moved apart

bool collides(const QRectF& r, const QVector<ViewOverlay::Box>& placed, QRectF* hit) {
  for (const ViewOverlay::Box& b : placed)
    if (r.intersects(b.rect.adjusted(-kGap / 2, -kGap / 2, kGap / 2, kGap / 2))) {
      *hit = b.rect;
      return true;
    }
  return false;
}

/// `r` moved down (top boxes) or up (bottom boxes) until it covers none of `placed`.
QRectF clearOf(QRectF r, const QVector<ViewOverlay::Box>& placed, bool down) {
  QRectF hit;
  for (int i = 0; i <= placed.size() && collides(r, placed, &hit); ++i) {
    if (down)
      r.moveTop(hit.bottom() + kGap);
    else
      r.moveBottom(hit.top() - kGap);
  }
  return r;
}

}  // namespace

std::array<QString, 2> ViewOverlay::errorRows() {
  return {tr("false lit (light leak)"), tr("false shadowed")};
}

const char* ViewOverlay::roleName(Role role) {
  switch (role) {
    case Role::Banner:
      return "banner";
    case Role::Paused:
      return "pause badge";
    case Role::OutsideLegend:
      return "outside view legend";
    case Role::LeftCaption:
      return "left caption";
    case Role::RightCaption:
      return "right caption";
    case Role::Legend:
      return "overlay legend";
    case Role::Note:
      return "note";
    case Role::Inset:
      return "zoom inset";
    case Role::InsetLabel:
      return "zoom inset label";
  }
  return "?";
}

QString ViewOverlay::legendText() const {
  switch (legend) {
    case Legend::Aliasing:
      return tr("texels per pixel m (red: undersampled)");
    case Legend::Changed:
      return changedCount ? tr("%L1 pixels changed since the last frame (of %L2)")
                                .arg(changedCount->first)
                                .arg(changedCount->second)
                          : tr("pixels changed since the last frame: needs two frames");
    case Legend::WarpGrid:
      return tr("shadow-map grid: every 1/16 of the map");
    case Legend::Error:
    case Legend::None:
      break;
  }
  return {};
}

int ViewOverlay::aliasingNoteHeight(double legendWidth) const {
  const int w = std::max(1, int(legendWidth) - 20);  // the bar's width
  return fontMetrics()
      .boundingRect(QRect(0, 0, w, 100000), Qt::AlignLeft | Qt::TextWordWrap, aliasingNote)
      .height();
}

QVector<ViewOverlay::Box> ViewOverlay::layout() const {
  QVector<Box> boxes;
  const QFontMetrics fm = fontMetrics();
  const int line = fm.height();
  const double W = width(), H = height();
  auto place = [&](Role role, QRectF r, bool down) {
    r = clearOf(r, boxes, down);
    boxes.append({role, r});
    return r;
  };
  // Top: the banner, then the pause badge and the outside view's legend on the right.
  if (!bannerTitle.isEmpty() || !bannerText.isEmpty()) {
    const int w = std::min(width() - 24, std::max(360, width() * 2 / 3));
    QFont bold = font();
    bold.setBold(true);
    const QRect textRect(0, 0, w - 20, 10000);
    const QRect textBounds =
        fm.boundingRect(textRect, Qt::TextWordWrap | Qt::AlignLeft, bannerText);
    const QRect titleBounds = QFontMetrics(bold).boundingRect(
        textRect, Qt::TextWordWrap | Qt::AlignLeft, bannerTitle);  // wrapped, never cut
    const int titleH = bannerTitle.isEmpty() ? 0 : titleBounds.height() + 4;
    place(Role::Banner,
          QRectF(12, 10, w, titleH + (bannerText.isEmpty() ? 0 : textBounds.height()) + 14), true);
  }
  if (!pausedText.isEmpty()) {
    const double tw = std::min<double>(W - 24, fm.horizontalAdvance(pausedText) + 20);
    place(Role::Paused, QRectF(W - tw - 12, 10, tw, line + 10), true);
  }
  if (!outsideLegend.isEmpty()) {
    int tw = fm.horizontalAdvance(tr("OUTSIDE VIEW (V)"));
    for (const auto& [colour, text] : outsideLegend) tw = std::max(tw, fm.horizontalAdvance(text));
    tw += 44;
    const int rows = int(outsideLegend.size()) + 1;
    place(Role::OutsideLegend, QRectF(W - tw - 12, 10, tw, rows * line + 12), true);
  }
  // Bottom: the captions (the split view), the legend on the left, the note and the inset on
  // the right.
  if (!split.isNull()) {
    const int half = width() / 2;
    for (int side = 0; side < 2; ++side) {
      const QString& text = side == 0 ? leftCaption : rightCaption;
      const int x0 = side == 0 ? 0 : half;
      const int w = side == 0 ? half : width() - half;
      const int tw = std::min(w - 16, fm.horizontalAdvance(text) + 16);
      const QRect bounds = fm.boundingRect(QRect(0, 0, std::max(1, tw - 8), 10000),
                                           Qt::TextWordWrap | Qt::AlignCenter, text);
      const int th = std::max(line, bounds.height());
      place(side == 0 ? Role::LeftCaption : Role::RightCaption,
            QRectF(x0 + (w - tw) / 2.0, H - th - 18, tw, th + 10), false);
    }
  }
  if (legend != Legend::None) {
    QSizeF size;
    if (legend == Legend::Aliasing) {
      // As wide as its caption (and at least the bar's 260 px), never cutting it.
      size = {std::min<double>(W - 24, std::max(260, fm.horizontalAdvance(legendText()) + 24)),
              2.0 * line + 22};
      if (!aliasingNote.isEmpty()) {
        // The note wraps in the bar's width, or up to 28 lines' height wide where it is longer.
        size.setWidth(std::min(W - 24, std::max(size.width(), 28.0 * line)));
        size.rheight() += aliasingNoteHeight(size.width()) + 4;
      }
    } else if (legend == Legend::Error) {
      const int tw =
          std::max({fm.horizontalAdvance(errorRows()[0]), fm.horizontalAdvance(errorRows()[1]),
                    fm.horizontalAdvance(errorNote)}) +
          44;
      const int rows = errorNote.isEmpty() ? 2 : 3;
      size = {double(tw), rows * line + 12.0};
    } else if (legend == Legend::Changed) {
      size = {fm.horizontalAdvance(legendText()) + (line - 6) + 30.0, line + 10.0};
    } else {
      size = {fm.horizontalAdvance(legendText()) + 20.0, line + 10.0};
    }
    place(Role::Legend, QRectF(QPointF(12, H - 8 - size.height()), size), false);
  }
  if (!resolutionNote.isEmpty()) {
    const int tw = std::min(width() - 24, fm.horizontalAdvance(resolutionNote) + 20);
    const int th =
        std::max(line, fm.boundingRect(QRect(0, 0, std::max(1, tw - 8), 10000),
                                       Qt::TextWordWrap | Qt::AlignCenter, resolutionNote)
                           .height());
    place(Role::Note, QRectF(W - tw - 12, H - 8 - th - 10, tw, th + 10), false);
  }
  if (!zoomArea.isEmpty() && !zoomSource.isNull()) {
    // The largest whole magnification in 45 % of the view that covers no other box (its
    // label above it included).
    const int labelH = line + 6;
    for (int f = std::min(width() * 45 / 100 / zoomArea.width(),
                          height() * 45 / 100 / zoomArea.height());
         f >= 2; --f) {
      const QSizeF size(zoomArea.width() * f, zoomArea.height() * f);
      const QRectF withLabel =
          clearOf(QRectF(W - size.width() - 14, H - 8 - size.height() - labelH - 8, size.width(),
                         size.height() + labelH + 8),
                  boxes, false);
      if (withLabel.top() < 0) continue;
      const QRectF inset(withLabel.left(), withLabel.top() + labelH + 8, size.width(),
                         size.height());
      const QString label = QStringLiteral("\u00d7%1").arg(f);
      boxes.append({Role::InsetLabel, QRectF(inset.left(), inset.top() - line - 8,
                                             fm.horizontalAdvance(label) + 16, line + 6)});
      boxes.append({Role::Inset, inset});
      break;
    }
  }
  return boxes;
}

void ViewOverlay::placeInset() {
  takeInset(layout());
}

void ViewOverlay::takeInset(const QVector<Box>& boxes) {
  insetRect = QRect();
  insetFactor = 0;
  for (const Box& b : boxes)
    if (b.role == Role::Inset) {
      insetRect = b.rect.toRect();
      insetFactor = insetRect.width() / std::max(1, zoomArea.width());
    }
}

void ViewOverlay::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const QFontMetrics fm = fontMetrics();
  const int line = fm.height();
  QColor boxColor(20, 22, 25, 200);
  auto box = [&](const QRectF& r) {
    p.setPen(Qt::NoPen);
    p.setBrush(boxColor);
    p.drawRoundedRect(r, 5, 5);
  };
  const QVector<Box> boxes = layout();
  auto rectOf = [&](Role role) {
    for (const Box& b : boxes)
      if (b.role == role) return b.rect;
    return QRectF();
  };
  if (!gizmoLines.isEmpty() || gizmoPoint) {  // the light (Alt+drag moves it)
    p.setPen(QPen(QColor(255, 214, 60, 230), 1.6));
    p.drawLines(gizmoLines);
    if (gizmoPoint) {
      p.setBrush(QColor(255, 230, 120, 230));
      p.drawEllipse(*gizmoPoint, 6.0, 6.0);
    }
  }
  if (!split.isNull()) {
    const int half = width() / 2;
    p.drawImage(QRect(half, 0, width() - half, height()), split);
    p.setPen(QPen(QColor(255, 255, 255, 220), 2));
    p.drawLine(half, 0, half, height());
    // The captions wrap (never cut: the error is the number a comparison is about).
    for (const Role role : {Role::LeftCaption, Role::RightCaption}) {
      const QRectF r = rectOf(role);
      box(r);
      p.setPen(Qt::white);
      p.drawText(r.adjusted(4, 0, -4, 0), Qt::AlignCenter | Qt::TextWordWrap,
                 role == Role::LeftCaption ? leftCaption : rightCaption);
    }
  }
  if (!bannerTitle.isEmpty() || !bannerText.isEmpty()) {
    const QRectF r = rectOf(Role::Banner);
    const double w = r.width();
    QFont bold = font();
    bold.setBold(true);
    const QRect textRect(0, 0, int(w) - 20, 10000);
    const QRect textBounds =
        fm.boundingRect(textRect, Qt::TextWordWrap | Qt::AlignLeft, bannerText);
    const int titleH =
        bannerTitle.isEmpty()
            ? 0
            : QFontMetrics(bold)
                      .boundingRect(textRect, Qt::TextWordWrap | Qt::AlignLeft, bannerTitle)
                      .height() +
                  4;
    boxColor = QColor(20, 22, 25, 215);
    box(r);
    p.setPen(QColor(255, 200, 60));
    p.setFont(bold);
    p.drawText(QRectF(r.left() + 10, r.top() + 6, w - 20, titleH),
               Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, bannerTitle);
    p.setFont(font());
    p.setPen(Qt::white);
    p.drawText(QRectF(r.left() + 10, r.top() + 7 + titleH, w - 20, textBounds.height() + 2),
               Qt::TextWordWrap | Qt::AlignLeft, bannerText);
    boxColor = QColor(20, 22, 25, 200);
  }
  if (!pausedText.isEmpty()) {
    const QRectF r = rectOf(Role::Paused);
    boxColor = QColor(150, 40, 40, 220);
    box(r);
    boxColor = QColor(20, 22, 25, 200);
    p.setPen(Qt::white);
    p.drawText(r, Qt::AlignCenter, pausedText);
  }
  if (!outsideLegend.isEmpty()) {  // top right, under the pause badge
    const QRectF r = rectOf(Role::OutsideLegend);
    const double tw = r.width();
    box(r);
    p.setPen(QColor(255, 200, 60));
    p.drawText(QRectF(r.left() + 10, r.top() + 6, tw - 16, line), Qt::AlignLeft | Qt::AlignVCenter,
               tr("OUTSIDE VIEW (V)"));
    for (int i = 0; i < int(outsideLegend.size()); ++i) {
      const double y = r.top() + 6 + (i + 1) * line;
      p.fillRect(QRectF(r.left() + 10, y + line / 2.0 - 1.5, 18, 3), outsideLegend[i].first);
      p.setPen(Qt::white);
      p.drawText(QRectF(r.left() + 34, y, tw - 40, line), Qt::AlignLeft | Qt::AlignVCenter,
                 outsideLegend[i].second);
    }
  }
  if (!resolutionNote.isEmpty()) {  // bottom right: the view is not at full size, or busy
    const QRectF r = rectOf(Role::Note);
    box(r);
    p.setPen(QColor(255, 200, 60));
    p.drawText(r.adjusted(4, 0, -4, 0), Qt::AlignCenter | Qt::TextWordWrap, resolutionNote);
  }
  const QRectF legendRect = rectOf(Role::Legend);
  if (legend == Legend::Aliasing) {
    // Same colours as aliasingColor() in shaders/common/composite.frag (log2 m in -4..4,
    // blended at 70 % over the shaded scene there).
    const QRectF r = legendRect;
    box(r);
    const QRectF bar(r.left() + 10, r.top() + 8, r.width() - 20, 10);
    for (int i = 0; i < int(bar.width()); ++i) {
      const double t = (i + 0.5) / bar.width() * 2.0 - 1.0;  // log2(m) / 4
      const QColor blue(38, 89, 242), red(230, 26, 26);
      const QColor end = t < 0 ? blue : red;
      const double f = std::abs(t);
      p.fillRect(QRectF(bar.left() + i, bar.top(), 1, bar.height()),
                 QColor::fromRgbF(1 + (end.redF() - 1) * f, 1 + (end.greenF() - 1) * f,
                                  1 + (end.blueF() - 1) * f));
    }
    p.setPen(Qt::white);
    const QRectF labels(bar.left(), bar.bottom() + 2, bar.width(), line);
    p.drawText(labels, Qt::AlignLeft, QStringLiteral("m \u2264 1/16"));
    p.drawText(labels, Qt::AlignHCenter, QStringLiteral("1"));
    p.drawText(labels, Qt::AlignRight, QStringLiteral("\u2265 16"));
    p.drawText(QRectF(bar.left(), labels.bottom(), bar.width(), line), Qt::AlignHCenter,
               legendText());
    if (!aliasingNote.isEmpty())
      p.drawText(QRectF(bar.left(), labels.bottom() + line + 4, bar.width(),
                        aliasingNoteHeight(r.width())),
                 Qt::AlignLeft | Qt::TextWordWrap, aliasingNote);
  } else if (legend == Legend::Error) {
    const QRectF r = legendRect;
    const double tw = r.width();
    box(r);
    const QColor colors[] = {QColor(255, 0, 255), QColor(0, 255, 255)};
    const std::array<QString, 2> texts = errorRows();
    for (int i = 0; i < 2; ++i) {
      const double y = r.top() + 6 + i * line;
      p.fillRect(QRectF(r.left() + 10, y + 3, 18, line - 6), colors[i]);
      p.setPen(Qt::white);
      p.drawText(QRectF(r.left() + 34, y, tw - 40, line), Qt::AlignLeft | Qt::AlignVCenter,
                 texts[i]);
    }
    if (!errorNote.isEmpty())
      p.drawText(QRectF(r.left() + 10, r.top() + 6 + 2 * line, tw - 16, line),
                 Qt::AlignLeft | Qt::AlignVCenter, errorNote);
  } else if (legend == Legend::Changed) {
    const QRectF r = legendRect;
    const int swatch = line - 6;
    box(r);
    const float c[3] = {SL_CHANGED_COLOUR};
    p.fillRect(QRectF(r.left() + 10, r.top() + 8, swatch, swatch),
               QColor::fromRgbF(c[0], c[1], c[2]));
    p.setPen(Qt::white);
    p.drawText(QRectF(r.left() + swatch + 18, r.top(), r.width() - swatch - 22, r.height()),
               Qt::AlignLeft | Qt::AlignVCenter, legendText());
  } else if (legend == Legend::WarpGrid) {
    const QRectF r = legendRect;
    box(r);
    p.setPen(QColor(255, 217, 26));
    p.drawText(r, Qt::AlignCenter, legendText());
  }
  takeInset(boxes);
  if (insetFactor > 0) {  // the zoom inset: nearest neighbour, whole texels per pixel
    const QRectF source(zoomArea.topLeft() * zoomSource.devicePixelRatio(),
                        zoomArea.size() * zoomSource.devicePixelRatio());
    p.setRenderHint(QPainter::SmoothPixmapTransform, false);
    p.drawImage(QRectF(insetRect), zoomSource, source);
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(QColor(255, 230, 0), 3));
    p.drawRect(QRectF(insetRect).adjusted(-1.5, -1.5, 1.5, 1.5));
    p.setPen(QPen(QColor(255, 230, 0), 2, Qt::DashLine));
    p.drawRect(QRectF(zoomArea).adjusted(-1, -1, 1, 1));
    const QString label = QStringLiteral("\u00d7%1").arg(insetFactor);
    const QRectF lr = rectOf(Role::InsetLabel);
    box(lr);
    p.setPen(QColor(255, 230, 0));
    p.drawText(lr, Qt::AlignCenter, label);
  }
  if (!zoomDrag.isEmpty()) {
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(QColor(255, 230, 0), 2, Qt::DashLine));
    p.drawRect(zoomDrag);
  }
  if (pointerRing) {  // presenter mode: a ring around the pointer, dark halo for contrast
    const double radius = std::max(18.0, line * 1.1);
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(QColor(0, 0, 0, 170), 7));
    p.drawEllipse(*pointerRing, radius, radius);
    p.setPen(QPen(QColor(255, 40, 200), 4));
    p.drawEllipse(*pointerRing, radius, radius);
  }
}

}  // namespace sl::ui
