// The speed- or memory-against-accuracy chart with Qt Charts, rendered offscreen (no display: the
// "offscreen" platform plugin) into a QImage and saved as PNG. See Chart.h.
#include "Chart.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

#include "CliCommon.h"
#include "algo/InputFile.h"
#include "algo/metrics/BenchStats.h"

#if SHADOWLAB_CLI_CHARTS
#include <QApplication>
#include <QBuffer>
#include <QByteArray>
#include <QFont>
#include <QFontMetricsF>
#include <QGraphicsLayout>
#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>
#include <QImage>
#include <QPainter>
#include <QtCharts/QChart>
#include <QtCharts/QLegend>

#include "figures/ChartKit.h"
#endif

namespace sl::cli {

/// A point label or legend entry is cut to this many bytes (a title to kMaxMessageBytes).
constexpr std::size_t kMaxLabelBytes = 80;

#if SHADOWLAB_CLI_CHARTS
std::optional<std::string> savePng(const QImage& image, const std::string& path) {
  QByteArray png;
  QBuffer buffer(&png);
  buffer.open(QIODevice::WriteOnly);
  if (!image.save(&buffer, "PNG")) return path + ": cannot encode the image as PNG";
  return writeFile(path, png.toStdString());
}

/// A folder only this user can enter, for Qt's runtime files: <tmp>/shadowlab-runtime-UID when
/// it is a real folder (not a symbolic link) this user owns with mode 0700, created so (never
/// a chmod: a planted link must not change its target's mode); else a new mkdtemp folder.
std::optional<std::string> privateRuntimeFolder() {
  std::error_code ec;
  const std::filesystem::path tmp = std::filesystem::temp_directory_path(ec);
  if (ec) return std::nullopt;
  const std::string fixed = (tmp / ("shadowlab-runtime-" + std::to_string(getuid()))).string();
  if (::mkdir(fixed.c_str(), 0700) == 0 || errno == EEXIST) {
    struct stat st {};
    if (::lstat(fixed.c_str(), &st) == 0 && S_ISDIR(st.st_mode) && st.st_uid == getuid() &&
        (st.st_mode & 0777) == 0700)
      return fixed;
  }
  std::string pattern = (tmp / "shadowlab-runtime-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) return std::nullopt;
  return pattern;
}

void ensureOffscreenApplication() {
  if (QCoreApplication::instance()) return;
  setenv("QT_QPA_PLATFORM", "offscreen", 1);
  if (!std::getenv("XDG_RUNTIME_DIR"))  // Qt warns without one; give it a private folder
    if (auto dir = privateRuntimeFolder()) setenv("XDG_RUNTIME_DIR", dir->c_str(), 1);
  static int argc = 1;
  static char name[] = "shadowlab-cli";
  static char* argv[] = {name, nullptr};
  static QApplication app(argc, argv);
}

/// The rectangles already taken on the chart (markers, placed labels), in a grid of 32-pixel
/// cells, so that placing n labels costs O(n) (comparing each with every earlier one took
/// 120 s for 100,000 rows): a cell holding kMaxPerCell rectangles counts as full, and no
/// label is clear of a full cell.
class TakenRects {
 public:
  TakenRects(double width, double height)
      : cols_(std::max(1, int(std::ceil(width / kCell)))),
        rows_(std::max(1, int(std::ceil(height / kCell)))),
        cells_(std::size_t(cols_) * std::size_t(rows_)) {}
  void add(const QRectF& r) {
    forCells(r, [&](Cell& c) {
      if (c.rects.size() < kMaxPerCell)
        c.rects.push_back(r);
      else
        c.full = true;
    });
  }
  bool clear(const QRectF& r) {
    bool ok = true;
    forCells(r, [&](Cell& c) {
      ok = ok && !c.full;
      for (std::size_t i = 0; ok && i < c.rects.size(); ++i) ok = !c.rects[i].intersects(r);
    });
    return ok;
  }

 private:
  static constexpr double kCell = 32.0;
  static constexpr std::size_t kMaxPerCell = 16;
  struct Cell {
    std::vector<QRectF> rects;
    bool full = false;
  };
  template <class F>
  void forCells(const QRectF& r, F&& f) {
    auto index = [](double v, int n) { return std::clamp(int(std::floor(v / kCell)), 0, n - 1); };
    const int x0 = index(r.left(), cols_), x1 = index(r.right(), cols_);
    const int y0 = index(r.top(), rows_), y1 = index(r.bottom(), rows_);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        f(cells_[std::size_t(y) * std::size_t(cols_) + std::size_t(x)]);
  }
  int cols_, rows_;
  std::vector<Cell> cells_;
};
#endif

#if SHADOWLAB_CLI_CHARTS
namespace {
// The series' circle (its fill, border and size) as an image.
QImage markerImage(const QScatterSeries* s) {
  const int size = int(std::ceil(s->markerSize()));
  QImage image(size, size, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::transparent);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.setPen(QPen(s->borderColor(), 1.0));
  painter.setBrush(s->color());
  painter.drawEllipse(QRectF(0.5, 0.5, size - 1.0, size - 1.0));
  return image;
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
  // Titles and legend entries come from input (a CSV cell, a glTF animation's name): cut.
  chart->setTitle(QString("<b>%1</b><br>%2")
                      .arg(QString::fromStdString(cutText(spec.title)).toHtmlEscaped(),
                           QString::fromStdString(cutText(spec.subtitle)).toHtmlEscaped()));
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
    std::string name = cutText(p.technique, kMaxLabelBytes);
    if (i < spec.seriesNotes.size() && !spec.seriesNotes[i].empty())
      name += " (" + cutText(spec.seriesNotes[i], kMaxLabelBytes) + ")";
    QScatterSeries* s = ui::makeTechniqueSeries(i, QString::fromStdString(name));
    // Drawn as one image per marker: Qt Charts 6.4 colours its marker items one by one, each
    // looking its point up in the whole series (quadratic: 60,000 markers took 4 s).
    s->setLightMarker(markerImage(s));
    series[p.technique] = s;
  }
  // One marker per technique and 4-pixel cell: markers drawn over one another show nothing
  // more, and Qt Charts' scatter series slows down with every point (100,000 took 9 s).
  auto fraction = [](double v, const sl::ChartAxis& a) {
    return a.log ? (std::log(v) - std::log(a.min)) / (std::log(a.max) - std::log(a.min))
                 : (v - a.min) / (a.max - a.min);
  };
  std::map<std::string, std::set<std::pair<long, long> > > drawn;
  for (const ChartPoint& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    const QPointF v = at(p);
    const double fx = fraction(v.x(), xPlan), fy = fraction(v.y(), yPlan);
    const std::pair<long, long> cell =
        std::isfinite(fx) && std::isfinite(fy)
            ? std::pair<long, long>(long(std::floor(std::clamp(fx, -1.0, 2.0) * spec.width / 4)),
                                    long(std::floor(std::clamp(fy, -1.0, 2.0) * spec.height / 4)))
            : std::pair<long, long>(-1000000, long(drawn[p.technique].size()));
    if (drawn[p.technique].insert(cell).second) series[p.technique]->append(v);
  }
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
  // first side where it overlaps no other label or marker; none free: not drawn.
  TakenRects taken(spec.width, spec.height);
  for (const ChartPoint& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    QPointF c = chart->mapToPosition(at(p), series[p.technique]);
    taken.add(QRectF(c - QPointF(6, 6), QSizeF(12, 12)));
  }
  QFont labelFont = chart->legend()->font();
  labelFont.setPointSizeF(labelFont.pointSizeF() * 0.9);
  const QFontMetricsF metrics(labelFont);
  for (const ChartPoint& p : points) {
    if (p.label.empty() || !std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    const QString label = QString::fromStdString(cutText(p.label, kMaxLabelBytes));
    const QSizeF sz = metrics.boundingRect(label).size();
    const QPointF c = chart->mapToPosition(at(p), series[p.technique]);
    const QPointF candidates[] = {{c.x() + 8, c.y() - sz.height() / 2},
                                  {c.x() - sz.width() / 2, c.y() - 8 - sz.height()},
                                  {c.x() - sz.width() / 2, c.y() + 8},
                                  {c.x() - 8 - sz.width(), c.y() - sz.height() / 2},
                                  {c.x() + 8, c.y() - 6 - sz.height()},
                                  {c.x() + 8, c.y() + 6},
                                  {c.x() - 8 - sz.width(), c.y() - 6 - sz.height()},
                                  {c.x() - 8 - sz.width(), c.y() + 6}};
    std::optional<QPointF> chosen;
    for (const QPointF& cand : candidates) {
      QRectF r(cand, sz);
      if (chart->plotArea().contains(r) && taken.clear(r)) {
        chosen = cand;
        break;
      }
    }
    if (!chosen) continue;  // no free side: a label over others would hide them
    auto* text = new QGraphicsSimpleTextItem(label, chart);
    text->setFont(labelFont);
    text->setBrush(
        ui::chartTechniqueColor(
            std::size_t(std::find(order.begin(), order.end(), p.technique) - order.begin()))
            .darker(150));
    text->setPos(*chosen);
    taken.add(QRectF(*chosen, sz));
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
  return savePng(image, pngPath);
#endif
}

}  // namespace sl::cli
