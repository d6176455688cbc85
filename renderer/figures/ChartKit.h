// Qt Charts pieces shared by the GUI's Charts dock and shadowlab-cli's chart PNG: an axis
// from a planned sl::ChartAxis (algo/metrics/BenchStats decides range, scale and title),
// the technique colours, the Pareto-front line and a technique's scatter series.
// Header-only: the CLI draws charts without linking shadowlab_ui.
#pragma once

#include <cstddef>

#include <QColor>
#include <QPen>
#include <QString>
#include <QtCharts/QAbstractAxis>
#include <QtCharts/QLineSeries>
#include <QtCharts/QLogValueAxis>
#include <QtCharts/QScatterSeries>
#include <QtCharts/QValueAxis>

#include "algo/metrics/BenchStats.h"

namespace sl::ui {

/// The axis `plan` describes (the caller adds it to a chart, which then owns it).
inline QAbstractAxis* makeChartAxis(const sl::ChartAxis& plan) {
  QAbstractAxis* axis = nullptr;
  if (plan.log) {
    auto* a = new QLogValueAxis();
    a->setBase(plan.logBase);
    a->setRange(plan.min, plan.max);  // labels at the powers of the base inside
    a->setMinorTickCount(plan.minorTicks);
    a->setLabelFormat(QStringLiteral("%g"));
    axis = a;
  } else {
    auto* a = new QValueAxis();
    a->setRange(plan.min, plan.max);
    a->setTickCount(plan.ticks);
    a->setLabelFormat(QStringLiteral("%.3g"));
    axis = a;
  }
  axis->setTitleText(QString::fromStdString(plan.title));
  return axis;
}

/// Colour of the i-th technique (sl::chartColorRgb).
inline QColor chartTechniqueColor(std::size_t i) {
  const auto rgb = sl::chartColorRgb(i);
  return QColor(rgb[0], rgb[1], rgb[2]);
}

/// The dashed line through the Pareto front (points appended by the caller).
inline QLineSeries* makeParetoSeries(const QString& name) {
  auto* s = new QLineSeries();
  s->setName(name);
  QPen pen(QColor(40, 40, 40));
  pen.setWidthF(1.6);
  pen.setStyle(Qt::DashLine);
  s->setPen(pen);
  return s;
}

/// The scatter series of the i-th technique (its colour, circles).
inline QScatterSeries* makeTechniqueSeries(std::size_t i, const QString& name) {
  auto* s = new QScatterSeries();
  const QColor color = chartTechniqueColor(i);
  s->setName(name);
  s->setColor(color);
  s->setBorderColor(color.darker(140));
  s->setMarkerShape(QScatterSeries::MarkerShapeCircle);
  s->setMarkerSize(11.0);
  return s;
}

}  // namespace sl::ui
