// A labelled figure of several renderings for handouts, shared by `shadowlab-cli compare
// --montage` and the GUI's File > Export figure: each cell the shaded image above its error
// image (error pixels dilated for print by sl::makeErrorImage), its configuration and facts
// under it, a wrapped title on top, an optional zoom inset in every image's corner.
// Header-only: the CLI draws it without linking shadowlab_ui.
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <QColor>
#include <QFont>
#include <QFontMetrics>
#include <QImage>
#include <QPainter>
#include <QPen>
#include <QString>

#include "figures/FigureTypes.h"

namespace sl::ui {

/// The figure (`columns` cells per row; 0 = all in one row); a null image without cells.
inline QImage drawFigure(const std::vector<FigureCell>& cells, const std::string& title,
                         int columns, const std::optional<FigureInset>& inset) {
  if (cells.empty()) return {};
  const int cols = columns > 0 ? std::min<int>(columns, int(cells.size())) : int(cells.size());
  const int rows = (int(cells.size()) + cols - 1) / cols;
  int imageW = 0, imageH = 0;
  for (const FigureCell& c : cells) {
    imageW = std::max(imageW, c.shaded.width);
    imageH = std::max(imageH, c.shaded.height);
  }
  // Text sized for print: about 1/40 of an image's width, at least 13 px.
  QFont font(QStringLiteral("DejaVu Sans"));
  font.setPixelSize(std::max(13, imageW / 40));
  QFont bold = font;
  bold.setBold(true);
  const int line = QFontMetrics(font).height();
  const int pad = std::max(8, line / 2);
  const int cellW = imageW + 2 * pad;
  const int cellH = 2 * imageH + pad + 2 * line + 3 * pad;
  const QString titleText = QString::fromStdString(title);
  const int titleTextH = QFontMetrics(bold)
                             .boundingRect(QRect(0, 0, cols * cellW - 2 * pad, 100 * line),
                                           Qt::TextWordWrap, titleText)
                             .height();
  const int titleH = titleTextH + 2 * pad;
  QImage out(cols * cellW, titleH + rows * cellH, QImage::Format_RGB32);
  out.fill(Qt::white);
  QPainter p(&out);
  p.setRenderHint(QPainter::TextAntialiasing);
  p.setPen(Qt::black);
  p.setFont(bold);
  p.drawText(QRect(pad, pad, out.width() - 2 * pad, titleTextH), Qt::AlignLeft | Qt::TextWordWrap,
             titleText);
  auto toQImage = [](const ImageRGBA8& img) {
    return QImage(img.pixels.data(), img.width, img.height, 4 * img.width, QImage::Format_RGBA8888)
        .copy();
  };
  // The inset: the region magnified (nearest texel: pixels stay pixels) into the corner,
  // framed, and the region itself outlined.
  auto drawImage = [&](const ImageRGBA8& img, QPoint at) {
    const QImage q = toQImage(img);
    p.drawImage(at, q);
    if (!inset) return;
    const QRect region(int(inset->x * q.width()), int(inset->y * q.height()),
                       std::max(1, int(inset->w * q.width())),
                       std::max(1, int(inset->h * q.height())));
    const QImage zoomed = q.copy(region).scaled(region.size() * inset->zoom, Qt::IgnoreAspectRatio,
                                                Qt::FastTransformation);
    const QRect target(at.x() + q.width() - zoomed.width() - 2,
                       at.y() + q.height() - zoomed.height() - 2, zoomed.width(), zoomed.height());
    p.drawImage(target.topLeft(), zoomed);
    p.setBrush(Qt::NoBrush);
    for (const auto& [colour, width] : {std::pair{QColor(0, 0, 0), 3}, {QColor(255, 200, 0), 1}}) {
      p.setPen(QPen(colour, width));
      p.drawRect(target);
      p.drawRect(region.translated(at));
    }
    p.setPen(Qt::black);
  };
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const FigureCell& c = cells[i];
    const int x = int(i % std::size_t(cols)) * cellW + pad;
    const int y = titleH + int(i / std::size_t(cols)) * cellH;
    if (c.shaded.valid()) drawImage(c.shaded, QPoint(x, y));
    if (c.error.valid()) drawImage(c.error, QPoint(x, y + imageH + pad));
    const int textY = y + 2 * imageH + 2 * pad;
    p.setFont(bold);
    p.drawText(QRect(x, textY, imageW, line), Qt::AlignLeft | Qt::AlignVCenter,
               QString::fromStdString(c.label));
    p.setFont(font);
    p.drawText(QRect(x, textY + line, imageW, line), Qt::AlignLeft | Qt::AlignVCenter,
               QString::fromStdString(c.facts));
  }
  p.end();
  return out;
}

}  // namespace sl::ui
