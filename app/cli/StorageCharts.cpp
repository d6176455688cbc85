// Draws the storage-factor plots (Lloyd et al. 2006, Figs. 6-7) offscreen with Qt: Qt Charts
// lines for the eta plot, QPainter disks and a colour bar for the hemisphere. See
// StorageCharts.h.
#include "StorageCharts.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "Chart.h"

#if SHADOWLAB_CLI_CHARTS
#include <QCoreApplication>
#include <QFont>
#include <QGraphicsLayout>
#include <QGraphicsScene>
#include <QImage>
#include <QPainter>
#include <QtCharts/QChart>
#include <QtCharts/QLegend>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>
#endif

namespace sl::cli {

#if SHADOWLAB_CLI_CHARTS
namespace {

QImage renderScene(QGraphicsScene& scene, int w, int h) {
  QImage image(w, h, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::white);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.setRenderHint(QPainter::TextAntialiasing);
  scene.render(&painter, QRectF(0, 0, w, h), QRectF(0, 0, w, h));
  return image;
}

/// A perceptual ramp (viridis, 6 stops) at x in [0, 1].
QColor ramp(double x) {
  static const int stops[6][3] = {{68, 1, 84},    {65, 68, 135},  {42, 120, 142},
                                  {34, 168, 132}, {122, 209, 81}, {253, 231, 37}};
  x = std::clamp(x, 0.0, 1.0) * 5.0;
  const int i = std::min(int(x), 4);
  const double f = x - i;
  auto mix = [&](int c) { return int(std::lround(stops[i][c] * (1 - f) + stops[i + 1][c] * f)); };
  return QColor(mix(0), mix(1), mix(2));
}

std::optional<std::string> save(const QImage& image, const std::string& pngPath) {
  if (!image.save(QString::fromStdString(pngPath), "PNG")) return "cannot write " + pngPath;
  return std::nullopt;
}

}  // namespace
#endif

std::optional<std::string> writeEtaChart(const EtaCurve& c, const std::string& pngPath) {
  if (c.eta.empty()) return "eta chart: no points";
#if !SHADOWLAB_CLI_CHARTS
  return "storage: this shadowlab-cli was built without Qt Charts (" + pngPath + " not written)";
#else
  ensureOffscreenApplication();
  auto* chart = new QChart();
  chart->setTitle(QString("<b>%1</b><br>%2")
                      .arg(QString::fromStdString(c.title).toHtmlEscaped(),
                           QString::fromStdString(c.subtitle).toHtmlEscaped()));
  chart->setBackgroundBrush(Qt::white);
  chart->setAnimationOptions(QChart::NoAnimation);
  auto* ax = new QValueAxis();
  ax->setRange(-1.0, 1.0);
  ax->setTickCount(9);
  ax->setLabelFormat("%.2f");
  ax->setTitleText(
      "eta (eq. 11): -1 uniform (n' = inf), 0 LiSPSM (n' = n + sqrt(f n)), 1 PSM (n' = n)");
  auto* ay = new QValueAxis();
  ay->setRange(0.0, 1.05);
  ay->setTickCount(8);
  ay->setLabelFormat("%.2f");
  ay->setTitleText("value / its maximum over eta");
  chart->addAxis(ax, Qt::AlignBottom);
  chart->addAxis(ay, Qt::AlignLeft);
  struct Curve {
    const std::vector<double>* v;
    const char* name;
    QColor color;
    Qt::PenStyle style;
  };
  const Curve curves[] = {{&c.mx, "M_x (eq. 9)", QColor(31, 119, 180), Qt::DashLine},
                          {&c.mz, "M_z (eq. 10)", QColor(214, 39, 40), Qt::DotLine},
                          {&c.s, "S = M_x M_z (eq. 12)", QColor(20, 20, 20), Qt::SolidLine}};
  for (const Curve& cv : curves) {
    double mx = 0.0;
    for (double v : *cv.v)
      if (std::isfinite(v)) mx = std::max(mx, v);
    auto* series = new QLineSeries();
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s, maximum %.4g", cv.name, mx);
    series->setName(buf);
    QPen pen(cv.color);
    pen.setWidthF(2.4);
    pen.setStyle(cv.style);
    series->setPen(pen);
    for (std::size_t i = 0; i < c.eta.size(); ++i)
      if (std::isfinite((*cv.v)[i]) && mx > 0.0) series->append(c.eta[i], (*cv.v)[i] / mx);
    chart->addSeries(series);
    series->attachAxis(ax);
    series->attachAxis(ay);
  }
  chart->legend()->setAlignment(Qt::AlignBottom);
  QGraphicsScene scene;
  scene.addItem(chart);
  const int w = 1100, h = 720;
  chart->setGeometry(0, 0, w, h);
  chart->layout()->activate();
  QCoreApplication::processEvents();
  return save(renderScene(scene, w, h), pngPath);
#endif
}

std::optional<std::string> writeHemisphereChart(const HemisphereFigure& fig,
                                                const std::string& pngPath) {
  if (fig.panels.empty()) return "hemisphere chart: no panels";
#if !SHADOWLAB_CLI_CHARTS
  return "storage: this shadowlab-cli was built without Qt Charts (" + pngPath + " not written)";
#else
  ensureOffscreenApplication();
  double lo = std::numeric_limits<double>::max(), hi = -lo;
  for (const HemispherePanel& p : fig.panels)
    for (double s : p.s)
      if (std::isfinite(s) && s > 0.0)
        lo = std::min(lo, std::log10(s)), hi = std::max(hi, std::log10(s));
  if (!(hi >= lo)) return "hemisphere chart: no finite storage factor";
  lo = std::floor(lo * 2.0) / 2.0;
  hi = std::max(std::ceil(hi * 2.0) / 2.0, lo + 0.5);
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
    const HemispherePanel& p = fig.panels[k];
    const int x0 = pad + int(k % std::size_t(cols)) * (disk + pad);
    const int y0 = titleH + int(k / std::size_t(cols)) * (disk + labelH + pad);
    double pmin = std::numeric_limits<double>::max(), pmax = 0.0;
    const double cell = double(disk) / p.grid;
    for (int r = 0; r < p.grid; ++r)
      for (int c = 0; c < p.grid; ++c) {
        const double s = p.s[std::size_t(r * p.grid + c)];
        if (!std::isfinite(s) || s <= 0.0) continue;
        pmin = std::min(pmin, s), pmax = std::max(pmax, s);
        g.fillRect(QRectF(x0 + c * cell, y0 + r * cell, cell + 0.6, cell + 0.6),
                   ramp((std::log10(s) - lo) / (hi - lo)));
      }
    g.setPen(QPen(QColor(60, 60, 60), 1.2));
    g.setBrush(Qt::NoBrush);
    g.drawEllipse(QRectF(x0, y0, disk, disk));
    // The --light: a cross.
    const QPointF m(x0 + (fig.markU + 1.0) * 0.5 * disk, y0 + (1.0 - fig.markV) * 0.5 * disk);
    g.setPen(QPen(Qt::white, 3.0));
    g.drawLine(m + QPointF(-7, -7), m + QPointF(7, 7));
    g.drawLine(m + QPointF(-7, 7), m + QPointF(7, -7));
    g.setPen(QPen(Qt::black, 1.4));
    g.drawLine(m + QPointF(-7, -7), m + QPointF(7, 7));
    g.drawLine(m + QPointF(-7, 7), m + QPointF(7, -7));
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s   (S %.3g .. %.3g)", p.title.c_str(), pmin, pmax);
    font.setPixelSize(15);
    g.setFont(font);
    g.setPen(Qt::black);
    g.drawText(QRect(x0 - pad / 2, y0 + disk + 4, disk + pad, labelH), Qt::AlignHCenter, buf);
    font.setPixelSize(11);
    g.setFont(font);
    g.setPen(QColor(90, 90, 90));
    g.drawText(QRect(x0 - 62, y0 + disk / 2 - 8, 58, 16), Qt::AlignRight, "behind");
    g.drawText(QRect(x0 + disk + 4, y0 + disk / 2 - 8, 58, 16), Qt::AlignLeft, "in front");
    g.drawText(QRect(x0, y0 - 15, disk, 14), Qt::AlignHCenter, "right");
  }
  // Colour bar: log10 S.
  const int bx = w - barW + 20, by = titleH + 10,
            bh = std::max(200, rows * (disk + labelH + pad) - 80);
  for (int i = 0; i < bh; ++i)
    g.fillRect(QRect(bx, by + i, 24, 1), ramp(1.0 - double(i) / (bh - 1)));
  g.setPen(QPen(QColor(60, 60, 60), 1.0));
  g.setBrush(Qt::NoBrush);
  g.drawRect(QRect(bx, by, 24, bh));
  font.setPixelSize(13);
  g.setFont(font);
  g.setPen(Qt::black);
  const double step = hi - lo > 4.0 ? 1.0 : 0.5;
  for (double v = lo; v <= hi + 1e-9; v += step) {
    const int y = by + int(std::lround((hi - v) / (hi - lo) * (bh - 1)));
    g.drawLine(bx + 24, y, bx + 30, y);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", std::pow(10.0, v));
    g.drawText(QRect(bx + 33, y - 9, 80, 18), Qt::AlignLeft | Qt::AlignVCenter, buf);
  }
  g.drawText(QRect(bx - 20, by + bh + 6, 110, 40), Qt::AlignHCenter | Qt::TextWordWrap,
             "S (log10 colour)");
  g.end();
  return save(image, pngPath);
#endif
}

}  // namespace sl::cli
