// Draws the storage-factor plots (Lloyd et al. 2006, Figs. 6-7) offscreen into PNGs with the
// shared pieces of renderer/figures/StorageChartKit.h. See StorageCharts.h.
#include "StorageCharts.h"

#include <cstdio>

#include "Chart.h"

#if SHADOWLAB_CLI_CHARTS
#include <QCoreApplication>
#include <QGraphicsLayout>
#include <QGraphicsScene>
#include <QImage>

#include "figures/StorageChartKit.h"
#endif

namespace sl::cli {

std::optional<std::string> writeEtaChart(const partition::EtaCurve& c, const std::string& pngPath) {
  if (c.eta.empty()) return "eta chart: no points";
#if !SHADOWLAB_CLI_CHARTS
  return "storage: this shadowlab-cli was built without Qt Charts (" + pngPath + " not written)";
#else
  ensureOffscreenApplication();
  QChart* chart = ui::makeEtaChart(c);
  QGraphicsScene scene;
  scene.addItem(chart);
  const int w = 1100, h = 720;
  chart->setGeometry(0, 0, w, h);
  chart->layout()->activate();
  QCoreApplication::processEvents();
  QImage image(w, h, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::white);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.setRenderHint(QPainter::TextAntialiasing);
  scene.render(&painter, QRectF(0, 0, w, h), QRectF(0, 0, w, h));
  painter.end();
  return savePng(image, pngPath);
#endif
}

std::optional<std::string> writeHemisphereChart(const partition::HemisphereFigure& fig,
                                                const std::string& pngPath) {
  if (fig.panels.empty()) return "hemisphere chart: no panels";
#if !SHADOWLAB_CLI_CHARTS
  return "storage: this shadowlab-cli was built without Qt Charts (" + pngPath + " not written)";
#else
  ensureOffscreenApplication();
  const std::optional<ui::StorageScale> scale = ui::storageScale(fig.panels);
  if (!scale) return "hemisphere chart: no finite storage factor";
  const int cols = std::min<int>(4, int(fig.panels.size()));
  const int rows = int((fig.panels.size() + std::size_t(cols) - 1) / std::size_t(cols));
  const int disk = 300, pad = 130, titleH = 84, labelH = 30, barW = 120;
  const int w = pad + cols * (disk + pad) + barW, h = titleH + rows * (disk + labelH + pad) + 60;
  QImage image(w, h, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::white);
  QPainter g(&image);
  g.setRenderHint(QPainter::Antialiasing);
  g.setRenderHint(QPainter::TextAntialiasing);
  QFont font = g.font();
  font.setPixelSize(20);
  font.setBold(true);
  g.setFont(font);
  g.setPen(Qt::black);
  g.drawText(QRect(0, 8, w, 30), Qt::AlignHCenter, QString::fromStdString(fig.title));
  font.setBold(false);
  font.setPixelSize(14);
  g.setFont(font);
  g.drawText(QRect(0, 38, w, 40), Qt::AlignHCenter | Qt::TextWordWrap,
             QString::fromStdString(fig.subtitle));
  for (std::size_t k = 0; k < fig.panels.size(); ++k) {
    const partition::HemispherePanel& p = fig.panels[k];
    const int x0 = pad + int(k % std::size_t(cols)) * (disk + pad);
    const int y0 = titleH + int(k / std::size_t(cols)) * (disk + labelH + pad);
    const QRectF rect(x0, y0, disk, disk);
    const auto [pmin, pmax] = ui::paintHemisphereDisk(g, rect, p, *scale);
    ui::paintLightMark(g, ui::diskToWidget(rect, fig.markU, fig.markV));
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s   (S %.3g .. %.3g)", p.title.c_str(), pmin, pmax);
    font.setPixelSize(15);
    g.setFont(font);
    g.setPen(Qt::black);
    g.drawText(QRect(x0 - pad / 2, y0 + disk + 4, disk + pad, labelH), Qt::AlignHCenter, buf);
  }
  // Colour bar: log10 S.
  const int bx = w - barW + 20, by = titleH + 10,
            bh = std::max(200, rows * (disk + labelH + pad) - 80);
  ui::paintStorageColorBar(g, QRect(bx, by, 24, bh), *scale);
  font.setPixelSize(13);
  g.setFont(font);
  g.setPen(Qt::black);
  g.drawText(QRect(bx - 20, by + bh + 6, 110, 40), Qt::AlignHCenter | Qt::TextWordWrap,
             "S (log10 colour)");
  g.end();
  return savePng(image, pngPath);
#endif
}

}  // namespace sl::cli
