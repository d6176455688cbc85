// The compare montage (Montage.h), drawn with QPainter on the offscreen platform.
#include "Montage.h"

#include <algorithm>

#include "Chart.h"

#if SHADOWLAB_CLI_CHARTS
#include <QFont>
#include <QFontMetrics>
#include <QImage>
#include <QPainter>
#include <QPen>
#endif

namespace sl::cli {

std::optional<std::string> writeMontage(const std::vector<MontageCell>& cells,
                                        const std::string& title, int columns,
                                        const std::optional<MontageInset>& inset,
                                        const std::string& pngPath) {
#if SHADOWLAB_CLI_CHARTS
  if (cells.empty()) return "--montage: no configurations to show";
  ensureOffscreenApplication();
  const int cols = columns > 0 ? std::min<int>(columns, int(cells.size())) : int(cells.size());
  const int rows = (int(cells.size()) + cols - 1) / cols;
  int imageW = 0, imageH = 0;
  for (const MontageCell& c : cells) {
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
    const MontageCell& c = cells[i];
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
  if (!out.save(QString::fromStdString(pngPath), "PNG"))
    return "--montage: cannot write '" + pngPath + "'";
  return std::nullopt;
#else
  (void)cells, (void)title, (void)columns, (void)inset, (void)pngPath;
  return "--montage: this shadowlab-cli was built without Qt (the montage draws its labels "
         "with Qt); install Qt 6 and rebuild";
#endif
}

}  // namespace sl::cli
