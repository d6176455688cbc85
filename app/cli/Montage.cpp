// The compare montage (Montage.h), drawn with QPainter on the offscreen platform.
#include "Montage.h"

#include <algorithm>

#include "Chart.h"

#if SHADOWLAB_CLI_CHARTS
#include <QFont>
#include <QFontMetrics>
#include <QImage>
#include <QPainter>
#endif

namespace sl::cli {

std::optional<std::string> writeMontage(const std::vector<MontageCell>& cells,
                                        const std::string& title, int columns,
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
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const MontageCell& c = cells[i];
    const int x = int(i % std::size_t(cols)) * cellW + pad;
    const int y = titleH + int(i / std::size_t(cols)) * cellH;
    if (c.shaded.valid()) p.drawImage(QPoint(x, y), toQImage(c.shaded));
    if (c.error.valid()) p.drawImage(QPoint(x, y + imageH + pad), toQImage(c.error));
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
  (void)cells, (void)title, (void)columns, (void)pngPath;
  return "--montage: this shadowlab-cli was built without Qt (the montage draws its labels "
         "with Qt); install Qt 6 and rebuild";
#endif
}

}  // namespace sl::cli
