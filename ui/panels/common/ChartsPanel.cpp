// The Charts panel; see ChartsPanel.h.
#include "ChartsPanel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QCursor>
#include <QProgressBar>
#include <QRegularExpression>
#include <QToolTip>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QLegend>

#include "figures/ChartKit.h"
#include "window/MessageText.h"
#include "window/Theme.h"
#include "service/RenderService.h"
#include "view/ViewportWidget.h"
#include "core/ViewSide.h"

namespace sl::ui {

namespace {

constexpr int kWidth = 320, kHeight = 180;
/// A sweep's render-service job measures one frame: the view never waits for more than one.
constexpr std::size_t kFramesPerJob = 1;

}  // namespace

ChartsPanel::ChartsPanel(ViewportWidget* viewport, QWidget* parent)
    : QWidget(parent), viewport_(viewport) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  auto* row = new QHBoxLayout;
  sweepEdit_ = new QLineEdit;
  sweepEdit_->setObjectName(QStringLiteral("chartsSweep"));
  sweepEdit_->setPlaceholderText(
      tr("current technique and a baseline (uniform; for a point light the other omni map) at 3 "
         "resolutions"));
  sweepEdit_->setToolTip(
      tr("Configurations, as in shadowlab-cli bench --technique: ID[:KEY=V1,V2,...], several "
         "separated by spaces (e.g. \"uniform:resolution=512,1024 rtw-backward\"). Empty: the "
         "technique shown and a baseline that renders the view's light (uniform; for a point "
         "light the other omni map), at 3 resolutions each."));
  row->addWidget(sweepEdit_, 1);
  framesSpin_ = new QSpinBox;
  framesSpin_->setRange(1, 100);
  framesSpin_->setValue(frames_);
  framesSpin_->setSuffix(tr(" frames"));
  framesSpin_->setToolTip(tr("Frames per configuration, along the scene's camera path"));
  row->addWidget(framesSpin_);
  xCombo_ = new QComboBox;
  xCombo_->setObjectName(QStringLiteral("chartsX"));
  xCombo_->addItem(tr("x: time (ms)"), QStringLiteral("ms"));
  xCombo_->addItem(tr("x: memory (bytes)"), QStringLiteral("bytes"));
  xCombo_->setToolTip(
      tr("What the x axis and the Pareto front are against: the whole frame's time, or the "
         "technique's shadow memory (as shadowlab-cli chart --x ms|bytes); no new sweep"));
  connect(xCombo_, &QComboBox::currentIndexChanged, this, [this](int index) {
    chartX_ = sl::parseChartX(xCombo_->itemData(index).toString().toStdString())
                  .value_or(sl::ChartX::TimeMs);
    redrawChart();
  });
  runButton_ = new QPushButton(tr("Run"));
  runButton_->setObjectName(QStringLiteral("chartsRun"));
  connect(runButton_, &QPushButton::clicked, this, [this] { startSweep(); });
  row->addWidget(runButton_);
  cancelButton_ = new QPushButton(tr("Cancel"));
  cancelButton_->setEnabled(false);
  connect(cancelButton_, &QPushButton::clicked, this, &ChartsPanel::cancelSweep);
  row->addWidget(cancelButton_);
  layout->addLayout(row);

  progress_ = new QProgressBar;
  progress_->setRange(0, 1);
  progress_->setValue(0);
  auto* progressRow = new QHBoxLayout;  // the x choice here keeps the sweep text wide
  progressRow->addWidget(progress_, 1);
  progressRow->addWidget(xCombo_);
  layout->addLayout(progressRow);
  status_ =
      new QLabel(tr("Run a sweep to chart speed against accuracy for this scene; click a "
                    "point to view that configuration."));
  status_->setWordWrap(true);
  layout->addWidget(status_);

  chartView_ = new QChartView;
  chartView_->setRenderHint(QPainter::Antialiasing);
  chartView_->setMinimumSize(300, 220);
  layout->addWidget(chartView_, 1);
  followBodyFont(chartView_, [this] { redrawChart(); });  // draws it now

  // The sweep's renderer lives on the viewport's context: it goes before the context does.
  connect(viewport_, &ViewportWidget::rendererAboutToBeDestroyed, this, [this] {
    if (running()) finish(false);
    releaseRenderer();
  });
}

ChartsPanel::~ChartsPanel() {
  releaseRenderer();
}

void ChartsPanel::releaseRenderer() {
  running_ = false;
  ++sweepSerial_;  // a measurement still on the render thread is dropped when it returns
}

void ChartsPanel::setSweepText(const QString& text) {
  sweepEdit_->setText(text);
}
void ChartsPanel::setFramesPerConfig(int frames) {
  framesSpin_->setValue(frames);
}
void ChartsPanel::setChartX(sl::ChartX x) {
  xCombo_->setCurrentIndex(x == sl::ChartX::Bytes ? 1 : 0);  // redraws when it changes
}
QString ChartsPanel::xAxisTitle() const {
  const QChart* chart = chartView_->chart();
  const QList<QAbstractAxis*> axes = chart ? chart->axes(Qt::Horizontal) : QList<QAbstractAxis*>{};
  return axes.isEmpty() ? QString() : axes.front()->titleText();
}
double ChartsPanel::chartXOf(const Config& c) const {
  return chartX_ == sl::ChartX::Bytes ? c.medianBytes / xUnitScale_ : c.medianMs;
}

QString ChartsPanel::defaultSweepText() const {
  // The technique shown and a baseline that renders the view's light: uniform for a sun or
  // a spot, the other omni map (cube / dual-paraboloid) for a point light, which uniform
  // refuses.
  const QString current = QString::fromStdString(viewport_->techniqueId());
  const sl::LightType light = viewport_->camera()->light().type;
  auto renders = [&](const sl::TechniqueInfo& info) {
    return std::find(info.lights.begin(), info.lights.end(), light) != info.lights.end();
  };
  QStringList parts;
  auto add = [&](const sl::TechniqueInfo& info) {
    const QString id = QString::fromStdString(info.id);
    const bool hasRes = std::any_of(info.params.begin(), info.params.end(),
                                    [](const sl::ParamDecl& d) { return d.key == "resolution"; });
    parts << (hasRes ? id + QStringLiteral(":resolution=512,1024,2048") : id);
  };
  const sl::TechniqueInfo* shown = sl::Renderer::findTechnique(current.toStdString());
  if (shown && renders(*shown)) add(*shown);
  const sl::TechniqueInfo* uniform =
      sl::Renderer::findTechnique(sl::Renderer::baselineTechniqueId());
  if (uniform && renders(*uniform)) {
    if (uniform != shown) add(*uniform);
    return parts.join(QLatin1Char(' '));
  }
  for (const sl::TechniqueInfo& info : sl::Renderer::techniques())
    if (&info != shown && renders(info) &&
        std::find(info.lights.begin(), info.lights.end(), sl::LightType::Directional) ==
            info.lights.end()) {
      add(info);  // the first omni technique that is not the one shown
      break;
    }
  return parts.join(QLatin1Char(' '));
}

QString ChartsPanel::parseSweep(const QString& text) {
  configs_.clear();
  const QStringList items =
      text.split(QRegularExpression(QStringLiteral("[\\s;]+")), Qt::SkipEmptyParts);
  if (items.isEmpty()) return tr("no configurations");
  for (const QString& item : items) {
    const QStringList parts = item.split(QLatin1Char(':'));
    const QString id = parts.front();
    const sl::TechniqueInfo* info = sl::Renderer::findTechnique(id.toStdString());
    if (!info) return tr("unknown technique '%1'").arg(id);
    sl::ParamSet own(info->params), shared(sl::rendererParamDecls());
    // Cartesian product of the listed values, last key fastest.
    std::vector<QStringList> combos{{}};
    for (int k = 1; k < parts.size(); ++k) {
      const QString key = parts[k].section(QLatin1Char('='), 0, 0);
      const QStringList values =
          parts[k].section(QLatin1Char('='), 1).split(QLatin1Char(','), Qt::SkipEmptyParts);
      if (key.isEmpty() || values.isEmpty())
        return tr("'%1': expected KEY=V1,V2,... after ':'").arg(parts[k]);
      sl::ParamSet* set = own.has(key.toStdString())      ? &own
                          : shared.has(key.toStdString()) ? &shared
                                                          : nullptr;
      if (!set) return tr("%1 has no parameter '%2'").arg(id, key);
      for (const QString& v : values)
        if (auto e = set->setFromString(key.toStdString(), v.toStdString()))
          return QString::fromStdString(*e);
      std::vector<QStringList> next;
      for (const QStringList& c : combos)
        for (const QString& v : values) next.push_back(c + QStringList{key + '=' + v});
      combos = std::move(next);
    }
    for (const QStringList& c : combos) {
      Config config;
      config.techniqueId = id;
      config.assignments = c;
      config.label = c.isEmpty() ? id : id + ' ' + c.join(' ');
      configs_.push_back(std::move(config));
    }
  }
  return {};
}

bool ChartsPanel::startSweep() {
  if (running()) return false;
  if (!viewport_ || !viewport_->mainSide() || !viewport_->scene()) {
    status_->setText(tr("The view is not ready."));
    return false;
  }
  QString text = sweepEdit_->text().trimmed();
  if (text.isEmpty()) text = defaultSweepText();
  if (QString error = parseSweep(text); !error.isEmpty()) {
    status_->setText(shownMessage(tr("Sweep: %1").arg(error)));
    configs_.clear();
    redrawChart();
    return false;
  }
  // What the render thread needs, copied now: the view's values, then each configuration's.
  sl::ViewSide* main = viewport_->mainSide();
  sweep_.clear();
  for (const Config& config : configs_) {
    const std::string id = config.techniqueId.toStdString();
    sl::measure::SweepConfig rendered{id, main->paramsOf(id), main->rendererParams()};
    for (const QString& a : config.assignments) {
      const std::string key = a.section('=', 0, 0).toStdString();
      const std::string value = a.section('=', 1).toStdString();
      sl::ParamSet& set = rendered.own.has(key) ? rendered.own : rendered.shared;
      if (auto e = set.setFromString(key, value)) {
        status_->setText(shownMessage(tr("%1: %2").arg(config.label, QString::fromStdString(*e))));
        configs_.clear();
        sweep_.clear();
        redrawChart();
        return false;
      }
    }
    sweep_.push_back(std::move(rendered));
  }
  frames_ = framesSpin_->value();
  cameras_ = sl::measure::sweepCameras(*viewport_->scene(), viewport_->camera()->camera(), frames_);
  progress_->setRange(0, int(configs_.size()) * frames_);
  progress_->setValue(0);
  runButton_->setEnabled(false);
  cancelButton_->setEnabled(true);
  status_->setText(tr("Measuring %1 configurations × %2 frames at %3×%4…")
                       .arg(configs_.size())
                       .arg(frames_)
                       .arg(kWidth)
                       .arg(kHeight));
  redrawChart();
  running_ = true;
  ++sweepSerial_;
  postSweep({});
  return true;
}

void ChartsPanel::cancelSweep() {
  if (!running()) return;
  if (viewport_) viewport_->service().cancel(RenderTag::kCharts);  // its result is dropped
  finish(false);
}

void ChartsPanel::finish(bool completed) {
  running_ = false;
  ++sweepSerial_;
  runButton_->setEnabled(true);
  cancelButton_->setEnabled(false);
  int done = 0, unmeasured = 0;
  for (const Config& c : configs_) {
    done += c.done ? 1 : 0;
    unmeasured += c.done && !std::isfinite(c.medianErrorPct) ? 1 : 0;
  }
  QString text =
      completed ? tr("%1 configurations measured (medians of %2 frames at %3×%4). "
                     "Click a point to view it.")
                      .arg(done)
                      .arg(frames_)
                      .arg(kWidth)
                      .arg(kHeight)
                : tr("Cancelled after %1 of %2 configurations.").arg(done).arg(configs_.size());
  if (unmeasured > 0)
    text +=
        tr(" Error n/a for %1 of them (no covered pixel in a frame): not drawn.").arg(unmeasured);
  status_->setText(text);
  redrawChart();
  Q_EMIT sweepFinished(completed);
}

void ChartsPanel::postSweep(sl::measure::SweepPosition from) {
  if (!running_ || !viewport_ || !viewport_->scene()) {
    if (running_) finish(false);
    return;
  }
  const std::shared_ptr<const sl::Scene> scene = viewport_->scene();
  const sl::Light light = viewport_->camera()->light();
  const std::uint64_t serial = sweepSerial_;
  QPointer<ChartsPanel> self(this);
  // One job per frame, tagged: the next is posted when this one has ended, so the view's
  // frames (which run when no other job waits) go on between two frames of the sweep; a new
  // sweep replaces the old sweep's unstarted job, and Cancel drops or stops it.
  viewport_->service().post(RenderTag::kCharts, [self, serial, scene, light, from, configs = sweep_,
                                                 cameras = cameras_](RenderContext& c) {
    const sl::measure::SweepPosition at = sl::measure::runSweep(
        c.renderer("charts"), scene, light, configs, cameras, kWidth, kHeight, from, &c.stopFlag(),
        [self, serial](std::size_t config, std::size_t frame, const sl::measure::SweepFrame& m) {
          QMetaObject::invokeMethod(
              self.data(),
              [self, serial, config, frame, m] {
                if (self) self->measured(serial, config, frame, m);
              },
              Qt::QueuedConnection);
        },
        kFramesPerJob);
    QMetaObject::invokeMethod(
        self.data(),
        [self, serial, at] {
          if (self) self->sweepEnded(serial, at);
        },
        Qt::QueuedConnection);
  });
}

void ChartsPanel::measured(std::uint64_t serial, std::size_t config, std::size_t frame,
                           const sl::measure::SweepFrame& m) {
  if (!running_ || serial != sweepSerial_ || config >= configs_.size()) return;
  Config& c = configs_[config];
  if (!m.problem.empty()) {
    status_->setText(shownMessage(tr("%1: %2").arg(c.label, QString::fromStdString(m.problem))));
    finish(false);
    return;
  }
  c.ms.push_back(m.ms);
  c.bytes.push_back(m.bytes);
  c.errorPct.push_back(m.errorPct);
  progress_->setValue(int(config) * frames_ + int(frame) + 1);
  if (int(frame) + 1 >= frames_) {
    c.medianMs = sl::measure::sweepMedian(c.ms);
    c.medianBytes = sl::measure::sweepMedian(c.bytes);
    c.medianErrorPct = sl::measure::sweepMedian(c.errorPct);
    c.done = true;
    redrawChart();
  }
}

void ChartsPanel::sweepEnded(std::uint64_t serial, sl::measure::SweepPosition at) {
  if (!running_ || serial != sweepSerial_) return;
  if (at.config >= configs_.size())
    finish(true);
  else
    postSweep(at);  // the next frame (or the same, when a blocking call stopped this job)
}

void ChartsPanel::redrawChart() {
  auto* chart = new QChart();
  chart->setTitle(QStringLiteral("<b>%1</b><br>%2")
                      .arg(QString::fromUtf8(sl::chartHeadline(chartX_)),
                           viewport_ && viewport_->scene()
                               ? QString::fromStdString(viewport_->scene()->name).toHtmlEscaped()
                               : QString()));
  chart->setBackgroundBrush(Qt::white);
  chart->setAnimationOptions(QChart::NoAnimation);
  chart->legend()->setAlignment(Qt::AlignBottom);
  chart->legend()->setBackgroundVisible(false);

  std::vector<std::size_t> shown;
  std::vector<sl::CostPoint> costs;  ///< of the shown configurations, against the chosen x
  std::vector<double> xs, ys;
  for (std::size_t i = 0; i < configs_.size(); ++i) {
    const Config& c = configs_[i];
    const double cost = chartX_ == sl::ChartX::Bytes ? c.medianBytes : c.medianMs;
    if (!c.done || !std::isfinite(cost) || !std::isfinite(c.medianErrorPct)) continue;
    shown.push_back(i);
    costs.push_back({cost, c.medianErrorPct});
    xs.push_back(cost);
    ys.push_back(c.medianErrorPct);
  }
  const sl::ChartAxis xPlan = sl::planCostAxis(chartX_, xs);
  xUnitScale_ = xPlan.unitScale;
  QAbstractAxis* axisX = makeChartAxis(xPlan);
  QAbstractAxis* axisY = makeChartAxis(sl::planChartAxis(
      ys, sl::AxisScale::Auto, 20.0, 0.12, "shadow error, % of covered pixels (median)"));
  chart->addAxis(axisX, Qt::AlignBottom);
  chart->addAxis(axisY, Qt::AlignLeft);

  QLineSeries* front = makeParetoSeries(tr("Pareto front"));
  drawnFront_.clear();
  for (std::size_t k : sl::paretoFront(costs)) {
    drawnFront_.push_back(shown[k]);
    const Config& c = configs_[shown[k]];
    front->append(chartXOf(c), c.medianErrorPct);
  }
  chart->addSeries(front);
  front->attachAxis(axisX);
  front->attachAxis(axisY);

  std::vector<QString> order;
  std::map<QString, QScatterSeries*> series;
  for (std::size_t i : shown) {
    const QString& id = configs_[i].techniqueId;
    if (!series.count(id)) {
      series[id] = makeTechniqueSeries(order.size(), id);
      order.push_back(id);
    }
    series[id]->append(chartXOf(configs_[i]), configs_[i].medianErrorPct);
  }
  for (const QString& id : order) {
    QScatterSeries* s = series[id];
    chart->addSeries(s);
    s->attachAxis(axisX);
    s->attachAxis(axisY);
    // A click: the configuration of this technique nearest to the clicked point.
    connect(s, &QScatterSeries::clicked, this, [this, id](const QPointF& p) {
      int best = -1;
      double bestD = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < configs_.size(); ++i) {
        const Config& c = configs_[i];
        if (!c.done || c.techniqueId != id) continue;
        const double d = std::hypot(chartXOf(c) - p.x(), c.medianErrorPct - p.y());
        if (d < bestD) bestD = d, best = int(i);
      }
      if (best >= 0) choose(best);
    });
    connect(s, &QScatterSeries::hovered, this, [this, id](const QPointF& p, bool state) {
      if (!state) return QToolTip::hideText();
      for (const Config& c : configs_)
        if (c.done && c.techniqueId == id && chartXOf(c) == p.x() && c.medianErrorPct == p.y())
          QToolTip::showText(QCursor::pos(), tr("%1\n%2 ms, %3 MiB, %4 % error\nclick to view it")
                                                 .arg(c.label)
                                                 .arg(c.medianMs, 0, 'g', 3)
                                                 .arg(c.medianBytes / (1024.0 * 1024.0), 0, 'g', 3)
                                                 .arg(c.medianErrorPct, 0, 'g', 3));
    });
  }
  setChartFonts(*chart);
  QChart* old = chartView_->chart();
  chartView_->setChart(chart);
  delete old;
}

void ChartsPanel::choose(int index) {
  if (index < 0 || index >= int(configs_.size())) return;
  const Config& c = configs_[std::size_t(index)];
  status_->setText(tr("Showing %1 (%2 ms, %3 MiB, %4 % error in the sweep).")
                       .arg(c.label)
                       .arg(c.medianMs, 0, 'g', 3)
                       .arg(c.medianBytes / (1024.0 * 1024.0), 0, 'g', 3)
                       .arg(c.medianErrorPct, 0, 'g', 3));
  Q_EMIT configurationChosen(c.techniqueId, c.assignments);
}

}  // namespace sl::ui
