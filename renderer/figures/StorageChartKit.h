// Qt pieces of the storage-factor plots (Lloyd et al. 2006, Figs. 6 and 7) shared by
// shadowlab-cli's PNGs (app/cli/StorageCharts.cpp) and the GUI's Storage factor panel: the
// eta chart (Qt Charts), the hemisphere disk, its light mark and the log colour bar
// (QPainter). Header-only and GL-free: the CLI draws them without linking shadowlab_ui.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <vector>

#include <QColor>
#include <QFont>
#include <QPainter>
#include <QPen>
#include <QRectF>
#include <QString>
#include <QtCharts/QChart>
#include <QtCharts/QLegend>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>

#include "algo/partition/StoragePlots.h"

namespace sl::ui {

/// A perceptual ramp (viridis, 6 stops) at t in [0, 1].
inline QColor storageRamp(double t) {
  static const int stops[6][3] = {{68, 1, 84},    {65, 68, 135},  {42, 120, 142},
                                  {34, 168, 132}, {122, 209, 81}, {253, 231, 37}};
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * 5.0;
  const int i = std::min(int(t), 4);
  const double f = t - i;
  auto mix = [&](int c) { return int(std::lround(stops[i][c] * (1 - f) + stops[i + 1][c] * f)); };
  return QColor(mix(0), mix(1), mix(2));
}

/// log10 S range shared by several disks, widened to half decades.
struct StorageScale {
  double lo = 0.0, hi = 1.0;  ///< log10 S
  double t(double s) const { return (std::log10(s) - lo) / (hi - lo); }
};
inline std::optional<StorageScale> storageScale(
    const std::vector<sl::partition::HemispherePanel>& panels) {
  double lo = std::numeric_limits<double>::max(), hi = -lo;
  for (const auto& p : panels)
    for (double s : p.s)
      if (std::isfinite(s) && s > 0.0)
        lo = std::min(lo, std::log10(s)), hi = std::max(hi, std::log10(s));
  if (!(hi >= lo)) return std::nullopt;
  StorageScale sc;
  sc.lo = std::floor(lo * 2.0) / 2.0;
  sc.hi = std::max(std::ceil(hi * 2.0) / 2.0, sc.lo + 0.5);
  return sc;
}

/// Where disk coordinates (u right, v up, [-1, 1]) lie in `disk` and back.
inline QPointF diskToWidget(const QRectF& disk, double u, double v) {
  return {disk.left() + (u + 1.0) * 0.5 * disk.width(),
          disk.top() + (1.0 - v) * 0.5 * disk.height()};
}
inline QPointF widgetToDisk(const QRectF& disk, const QPointF& p) {
  return {(p.x() - disk.left()) / disk.width() * 2.0 - 1.0,
          1.0 - (p.y() - disk.top()) / disk.height() * 2.0};
}

/// One hemisphere disk: the cells coloured by log10 S, the rim, and where behind / in
/// front / right lie. Returns the panel's smallest and largest S.
inline std::pair<double, double> paintHemisphereDisk(QPainter& g, const QRectF& disk,
                                                     const sl::partition::HemispherePanel& p,
                                                     const StorageScale& scale,
                                                     int labelPixels = 11) {
  double pmin = std::numeric_limits<double>::max(), pmax = 0.0;
  const double cw = disk.width() / p.grid, ch = disk.height() / p.grid;
  for (int r = 0; r < p.grid; ++r)
    for (int c = 0; c < p.grid; ++c) {
      const double s = p.s[std::size_t(r * p.grid + c)];
      if (!std::isfinite(s) || s <= 0.0) continue;
      pmin = std::min(pmin, s), pmax = std::max(pmax, s);
      g.fillRect(QRectF(disk.left() + c * cw, disk.top() + r * ch, cw + 0.6, ch + 0.6),
                 storageRamp(scale.t(s)));
    }
  g.setPen(QPen(QColor(60, 60, 60), 1.2));
  g.setBrush(Qt::NoBrush);
  g.drawEllipse(disk);
  QFont font = g.font();
  font.setPixelSize(labelPixels);
  g.setFont(font);
  g.setPen(QColor(90, 90, 90));
  const int tw = labelPixels * 6, th = labelPixels + 5;
  g.drawText(QRectF(disk.left() - tw - 4, disk.center().y() - th / 2.0, tw, th), Qt::AlignRight,
             QStringLiteral("behind"));
  g.drawText(QRectF(disk.right() + 4, disk.center().y() - th / 2.0, tw, th), Qt::AlignLeft,
             QStringLiteral("in front"));
  g.drawText(QRectF(disk.left(), disk.top() - th - 1, disk.width(), th), Qt::AlignHCenter,
             QStringLiteral("right"));
  return {pmin, pmax};
}

/// The light's mark: a black cross with a white halo.
inline void paintLightMark(QPainter& g, const QPointF& m, double r = 7.0) {
  for (const auto& [color, width] : {std::pair{QColor(Qt::white), 3.0}, {QColor(Qt::black), 1.4}}) {
    g.setPen(QPen(color, width));
    g.drawLine(m + QPointF(-r, -r), m + QPointF(r, r));
    g.drawLine(m + QPointF(-r, r), m + QPointF(r, -r));
  }
}

/// A vertical colour bar of `scale` in `bar`, S labelled at every half (or whole) decade.
inline void paintStorageColorBar(QPainter& g, const QRect& bar, const StorageScale& scale,
                                 int labelPixels = 13) {
  for (int i = 0; i < bar.height(); ++i)
    g.fillRect(QRect(bar.left(), bar.top() + i, bar.width(), 1),
               storageRamp(1.0 - double(i) / std::max(1, bar.height() - 1)));
  g.setPen(QPen(QColor(60, 60, 60), 1.0));
  g.setBrush(Qt::NoBrush);
  g.drawRect(bar);
  QFont font = g.font();
  font.setPixelSize(labelPixels);
  g.setFont(font);
  g.setPen(Qt::black);
  const double step = scale.hi - scale.lo > 4.0 ? 1.0 : 0.5;
  for (double v = scale.lo; v <= scale.hi + 1e-9; v += step) {
    const int y =
        bar.top() + int(std::lround((scale.hi - v) / (scale.hi - scale.lo) * (bar.height() - 1)));
    g.drawLine(bar.right(), y, bar.right() + 6, y);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", std::pow(10.0, v));
    g.drawText(QRect(bar.right() + 9, y - labelPixels, 80, 2 * labelPixels),
               Qt::AlignLeft | Qt::AlignVCenter, QString::fromLatin1(buf));
  }
}

/// Fig. 6: M_x, M_z and S over eta, each normalised by its maximum (as the paper), the
/// legend naming each maximum; `markEta` draws a vertical line at the current eta. The
/// caller owns the chart (a QChartView or a QGraphicsScene takes it).
inline QChart* makeEtaChart(const sl::partition::EtaCurve& c, std::optional<double> markEta = {},
                            const QString& markName = {}) {
  auto* chart = new QChart();
  if (!c.title.empty() || !c.subtitle.empty())
    chart->setTitle(QStringLiteral("<b>%1</b><br>%2")
                        .arg(QString::fromStdString(c.title).toHtmlEscaped(),
                             QString::fromStdString(c.subtitle).toHtmlEscaped()));
  chart->setBackgroundBrush(Qt::white);
  chart->setAnimationOptions(QChart::NoAnimation);
  auto* ax = new QValueAxis();
  ax->setRange(-1.0, 1.0);
  ax->setTickCount(9);
  ax->setLabelFormat(QStringLiteral("%.2f"));
  ax->setTitleText(QStringLiteral(
      "eta (eq. 11): -1 uniform (n' = inf), 0 LiSPSM (n' = n + sqrt(f n)), 1 PSM (n' = n)"));
  auto* ay = new QValueAxis();
  ay->setRange(0.0, 1.05);
  ay->setTickCount(8);
  ay->setLabelFormat(QStringLiteral("%.2f"));
  ay->setTitleText(QStringLiteral("value / its maximum over eta"));
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
    series->setName(QString::fromLatin1(buf));
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
  if (markEta) {
    auto* mark = new QLineSeries();
    mark->setName(markName);
    QPen pen(QColor(230, 140, 0));
    pen.setWidthF(2.0);
    mark->setPen(pen);
    mark->append(*markEta, 0.0);
    mark->append(*markEta, 1.05);
    chart->addSeries(mark);
    mark->attachAxis(ax);
    mark->attachAxis(ay);
  }
  chart->legend()->setAlignment(Qt::AlignBottom);
  return chart;
}

}  // namespace sl::ui
