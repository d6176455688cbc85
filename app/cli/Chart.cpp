// The speed- or memory-against-accuracy chart with Qt Charts, rendered offscreen (no display: the
// "offscreen" platform plugin) into a QImage and saved as PNG. See Chart.h.
#include "Chart.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <stdexcept>

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
#include <QtCharts/QChart>
#include <QtCharts/QLegend>

#include "ChartKit.h"
#endif

namespace sl::cli {

#if SHADOWLAB_CLI_CHARTS
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

  // Axes from the values (x in its unit: ms, or bytes shown in KiB/MiB/GiB).
  std::vector<double> xs, ys;
  for (const ChartPoint& p : points) xs.push_back(p.x), ys.push_back(p.y);
  const sl::ChartAxis xPlan = sl::planCostAxis(spec.x, xs);
  sl::ChartAxis yPlan;
  try {
    const sl::AxisScale yScale = spec.yScale == "log"      ? sl::AxisScale::Log
                                 : spec.yScale == "linear" ? sl::AxisScale::Linear
                                                           : sl::AxisScale::Auto;
    yPlan = sl::planChartAxis(ys, yScale, 20.0, 0.12, spec.yTitle);
  } catch (const std::invalid_argument& e) {
    return std::string("chart: error axis: ") + e.what();
  }
  // Where point p sits (x in axis units).
  auto at = [&](const ChartPoint& p) { return QPointF(p.x / xPlan.unitScale, p.y); };
  QAbstractAxis* axisX = ui::makeChartAxis(xPlan);
  QAbstractAxis* axisY = ui::makeChartAxis(yPlan);
  chart->addAxis(axisX, Qt::AlignBottom);
  chart->addAxis(axisY, Qt::AlignLeft);

  // The Pareto front against the chosen x first, so the points draw over it.
  std::vector<CostPoint> costs;
  for (const ChartPoint& p : points) costs.push_back({p.x, p.y});
  QLineSeries* frontSeries = ui::makeParetoSeries("Pareto front");
  for (std::size_t i : paretoFront(costs)) frontSeries->append(at(points[i]));
  chart->addSeries(frontSeries);
  frontSeries->attachAxis(axisX);
  frontSeries->attachAxis(axisY);

  std::vector<std::string> order;
  std::map<std::string, QScatterSeries*> series;
  for (const ChartPoint& p : points) {
    if (series.count(p.technique)) continue;
    const std::size_t i = order.size();
    order.push_back(p.technique);
    std::string name = p.technique;
    if (i < spec.seriesNotes.size() && !spec.seriesNotes[i].empty())
      name += " (" + spec.seriesNotes[i] + ")";
    series[p.technique] = ui::makeTechniqueSeries(i, QString::fromStdString(name));
  }
  for (const ChartPoint& p : points)
    if (std::isfinite(p.x) && std::isfinite(p.y)) series[p.technique]->append(at(p));
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
    QPointF c = chart->mapToPosition(at(p), series[p.technique]);
    taken.push_back(QRectF(c - QPointF(6, 6), QSizeF(12, 12)));
  }
  QFont labelFont = chart->legend()->font();
  labelFont.setPointSizeF(labelFont.pointSizeF() * 0.9);
  for (const ChartPoint& p : points) {
    if (p.label.empty() || !std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    auto* text = new QGraphicsSimpleTextItem(QString::fromStdString(p.label), chart);
    text->setFont(labelFont);
    text->setBrush(
        ui::chartTechniqueColor(
            std::size_t(std::find(order.begin(), order.end(), p.technique) - order.begin()))
            .darker(150));
    const QSizeF sz = text->boundingRect().size();
    const QPointF c = chart->mapToPosition(at(p), series[p.technique]);
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
