// The speed-against-accuracy chart with Qt Charts, rendered offscreen (no display: the
// "offscreen" platform plugin) into a QImage and saved as PNG. See Chart.h.
#include "Chart.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>

#include <unistd.h>

#include "algo/metrics/BenchStats.h"

#if SHADOWLAB_CLI_CHARTS
#include <QApplication>
#include <QFont>
#include <QGraphicsLayout>
#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>
#include <QImage>
#include <QPainter>
#include <QPen>
#include <QtCharts/QChart>
#include <QtCharts/QLegend>
#include <QtCharts/QLineSeries>
#include <QtCharts/QLogValueAxis>
#include <QtCharts/QScatterSeries>
#include <QtCharts/QValueAxis>
#endif

namespace sl::cli {

#if SHADOWLAB_CLI_CHARTS
namespace {

/// A QApplication on the offscreen platform (Qt Charts draws with widgets' fonts and
/// styles). Made once, on first use, after any GL work has its own EGL context.
void ensureOffscreenApplication() {
  if (QCoreApplication::instance()) return;
  setenv("QT_QPA_PLATFORM", "offscreen", 1);
  if (!std::getenv("XDG_RUNTIME_DIR")) {  // Qt warns without one; give it a private folder
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("shadowlab-runtime-" + std::to_string(getuid()));
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    std::filesystem::permissions(dir, std::filesystem::perms::owner_all,
                                 std::filesystem::perm_options::replace, ec);
    if (!ec) setenv("XDG_RUNTIME_DIR", dir.c_str(), 1);
  }
  static int argc = 1;
  static char name[] = "shadowlab-cli";
  static char* argv[] = {name, nullptr};
  static QApplication app(argc, argv);
}

QColor techniqueColor(std::size_t i) {
  const auto rgb = sl::chartColorRgb(i);
  return QColor(rgb[0], rgb[1], rgb[2]);
}

}  // namespace
#endif

std::optional<std::string> writeSpeedAccuracyChart(const std::vector<ChartPoint>& points,
                                                   const ChartSpec& spec,
                                                   const std::string& pngPath) {
  if (points.empty()) return "chart: no points to draw";
#if !SHADOWLAB_CLI_CHARTS
  (void)spec;
  return "chart: this shadowlab-cli was built without Qt Charts (" + pngPath + " not written)";
#else
  ensureOffscreenApplication();
  QChart* chart = new QChart();  // owned by the scene below
  chart->setTitle(QString("<b>%1</b><br>%2")
                      .arg(QString::fromStdString(spec.title).toHtmlEscaped(),
                           QString::fromStdString(spec.subtitle).toHtmlEscaped()));
  QFont titleFont = chart->titleFont();
  titleFont.setPointSizeF(titleFont.pointSizeF() * 1.15);
  chart->setTitleFont(titleFont);
  chart->setBackgroundBrush(Qt::white);
  chart->setAnimationOptions(QChart::NoAnimation);

  double maxX = 0.0, maxY = 0.0;
  for (const ChartPoint& p : points) {
    if (std::isfinite(p.x)) maxX = std::max(maxX, p.x);
    if (std::isfinite(p.y)) maxY = std::max(maxY, p.y);
  }
  auto* axisX = new QValueAxis();
  axisX->setTitleText(QString::fromStdString(spec.xTitle));
  const auto [xMax, xTicks] = sl::niceAxisRange(maxX * 1.08);
  axisX->setRange(0.0, xMax);
  axisX->setTickCount(xTicks);
  axisX->setLabelFormat("%.3g");
  double minY = std::numeric_limits<double>::infinity();
  for (const ChartPoint& p : points)
    if (std::isfinite(p.y)) minY = std::min(minY, p.y);
  bool logY = spec.yScale == "log";
  if (spec.yScale == "auto") logY = minY > 0.0 && maxY / minY > 20.0;
  if (logY && !(minY > 0.0))
    return "chart: a log error axis needs every error above 0 (the smallest is " +
           std::to_string(minY) + ")";
  QAbstractAxis* axisY = nullptr;
  if (logY) {
    auto* a = new QLogValueAxis();
    a->setBase(10.0);
    a->setRange(minY / 1.6, maxY * 1.6);  // labels at the powers of ten inside
    a->setMinorTickCount(8);
    a->setLabelFormat("%g");
    a->setTitleText(QString::fromStdString(spec.yTitle + ", log scale"));
    axisY = a;
  } else {
    auto* a = new QValueAxis();
    const auto [yMax, yTicks] = sl::niceAxisRange(maxY * 1.12);
    a->setRange(0.0, yMax);
    a->setTickCount(yTicks);
    a->setLabelFormat("%.3g");
    a->setTitleText(QString::fromStdString(spec.yTitle));
    axisY = a;
  }
  chart->addAxis(axisX, Qt::AlignBottom);
  chart->addAxis(axisY, Qt::AlignLeft);

  // The Pareto front first, so the points draw over it.
  std::vector<CostPoint> costs;
  for (const ChartPoint& p : points) costs.push_back({p.x, p.y});
  const std::vector<std::size_t> front = paretoFront(costs);
  auto* frontSeries = new QLineSeries();
  frontSeries->setName("Pareto front");
  QPen frontPen(QColor(40, 40, 40));
  frontPen.setWidthF(1.6);
  frontPen.setStyle(Qt::DashLine);
  frontSeries->setPen(frontPen);
  for (std::size_t i : front) frontSeries->append(points[i].x, points[i].y);
  chart->addSeries(frontSeries);
  frontSeries->attachAxis(axisX);
  frontSeries->attachAxis(axisY);

  std::vector<std::string> order;
  std::map<std::string, QScatterSeries*> series;
  for (const ChartPoint& p : points) {
    if (series.count(p.technique)) continue;
    const std::size_t i = order.size();
    order.push_back(p.technique);
    auto* s = new QScatterSeries();
    std::string name = p.technique;
    if (i < spec.seriesNotes.size() && !spec.seriesNotes[i].empty())
      name += " (" + spec.seriesNotes[i] + ")";
    s->setName(QString::fromStdString(name));
    s->setColor(techniqueColor(i));
    s->setBorderColor(techniqueColor(i).darker(140));
    s->setMarkerShape(QScatterSeries::MarkerShapeCircle);
    s->setMarkerSize(11.0);
    series[p.technique] = s;
  }
  for (const ChartPoint& p : points)
    if (std::isfinite(p.x) && std::isfinite(p.y)) series[p.technique]->append(p.x, p.y);
  for (const std::string& t : order) {
    chart->addSeries(series[t]);
    series[t]->attachAxis(axisX);
    series[t]->attachAxis(axisY);
  }
  chart->legend()->setAlignment(Qt::AlignBottom);
  chart->legend()->setBackgroundVisible(false);

  QGraphicsScene scene;
  scene.addItem(chart);
  chart->setGeometry(0, 0, spec.width, spec.height);
  chart->layout()->activate();
  QCoreApplication::processEvents();

  // Point labels (Qt 6.4 has no per-point label text): placed next to each marker on the
  // first side where it overlaps no other label or marker.
  std::vector<QRectF> taken;
  for (const ChartPoint& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    QPointF c = chart->mapToPosition(QPointF(p.x, p.y), series[p.technique]);
    taken.push_back(QRectF(c - QPointF(6, 6), QSizeF(12, 12)));
  }
  QFont labelFont = chart->legend()->font();
  labelFont.setPointSizeF(labelFont.pointSizeF() * 0.9);
  for (const ChartPoint& p : points) {
    if (p.label.empty() || !std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    auto* text = new QGraphicsSimpleTextItem(QString::fromStdString(p.label), chart);
    text->setFont(labelFont);
    text->setBrush(techniqueColor(std::size_t(std::find(order.begin(), order.end(), p.technique) -
                                              order.begin()))
                       .darker(150));
    const QSizeF sz = text->boundingRect().size();
    const QPointF c = chart->mapToPosition(QPointF(p.x, p.y), series[p.technique]);
    const QPointF candidates[] = {{c.x() + 8, c.y() - sz.height() / 2},
                                  {c.x() - sz.width() / 2, c.y() - 8 - sz.height()},
                                  {c.x() - sz.width() / 2, c.y() + 8},
                                  {c.x() - 8 - sz.width(), c.y() - sz.height() / 2},
                                  {c.x() + 8, c.y() - 6 - sz.height()},
                                  {c.x() + 8, c.y() + 6},
                                  {c.x() - 8 - sz.width(), c.y() - 6 - sz.height()},
                                  {c.x() - 8 - sz.width(), c.y() + 6}};
    QPointF chosen = candidates[0];
    for (const QPointF& cand : candidates) {
      QRectF r(cand, sz);
      if (!chart->plotArea().contains(r)) continue;
      bool clear = true;
      for (const QRectF& t : taken) clear = clear && !t.intersects(r);
      if (clear) {
        chosen = cand;
        break;
      }
    }
    text->setPos(chosen);
    taken.push_back(QRectF(chosen, sz));
  }

  QImage image(spec.width, spec.height, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::white);
  {
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    scene.render(&painter, QRectF(0, 0, spec.width, spec.height),
                 QRectF(0, 0, spec.width, spec.height));
  }
  const std::filesystem::path out(pngPath);
  if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
  if (!image.save(QString::fromStdString(pngPath), "PNG")) return "chart: cannot write " + pngPath;
  return std::nullopt;
#endif
}

}  // namespace sl::cli
