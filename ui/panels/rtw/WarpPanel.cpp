// The Warp functions panel (see WarpPanel.h). The warp curve's slope is the local
// magnification of the shadow map: slope 3 = three times the texels of a uniform map there.
#include "WarpPanel.h"

#include <algorithm>
#include <cmath>

#include <QGridLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace sl::ui {

namespace {
const QColor kBefore(120, 200, 255);
const QColor kAfter(255, 160, 40);
const QColor kWarp(255, 210, 40);
const QColor kIdentity(170, 170, 175);

std::vector<float> curveOf(const sl::Publication& pub, const std::string& key) {
  auto it = pub.curves.find(key);
  return it == pub.curves.end() ? std::vector<float>{} : it->second;
}

/// Texel-centre samples (u = (i + 0.5) / n) of a 1D map.
std::vector<QPointF> centreSamples(const std::vector<float>& values) {
  std::vector<QPointF> out;
  const double n = static_cast<double>(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) out.emplace_back((i + 0.5) / n, values[i]);
  return out;
}
}  // namespace

WarpPanel::WarpPanel(QWidget* parent) : PublicationPanel(parent) {
  auto [content, layout] = newPanelColumn();
  auto* grid = new QGridLayout;
  grid->setSpacing(4);
  const QString axes[] = {QStringLiteral("x"), QStringLiteral("y")};
  for (int a = 0; a < 2; ++a) {
    importance_[a] = new PlotWidget;
    importance_[a]->setObjectName(QStringLiteral("importancePlot_%1").arg(axes[a]));
    importance_[a]->setTitle(tr("%1: 1D importance before and after blur").arg(axes[a]));
    importance_[a]->setAxisLabels(
        tr("%1 (unwarped)")
            .arg(axes[a] == QLatin1String("x") ? QStringLiteral("u") : QStringLiteral("v")),
        QString());
    importance_[a]->setXRange(0.0, 1.0);
    warp_[a] = new PlotWidget;
    warp_[a]->setObjectName(QStringLiteral("warpPlot_%1").arg(axes[a]));
    warp_[a]->setTitle(tr("%1: warp curve (warped vs unwarped coordinate)").arg(axes[a]));
    warp_[a]->setAxisLabels(a == 0 ? tr("u (unwarped)") : tr("v (unwarped)"), QString());
    warp_[a]->setXRange(0.0, 1.0);
    warp_[a]->setYRange(0.0, 1.0);
    grid->addWidget(importance_[a], 0, a);
    grid->addWidget(warp_[a], 1, a);
  }
  layout->addLayout(grid, 1);
  info_ = new QLabel;
  info_->setWordWrap(true);
  info_->setForegroundRole(QPalette::PlaceholderText);
  layout->addWidget(info_);
  setContent(content);
}

void WarpPanel::showPublication(const sl::Publication& pub) {
  const std::vector<float> wx = curveOf(pub, "warp.x"), wy = curveOf(pub, "warp.y");
  if (wx.size() < 2 && wy.size() < 2) {
    drawn_ = {};
    showContent(false, noDataText(QString::fromStdString(pub.techniqueId), tr("warp maps"),
                                  observedKeys()));
    return;
  }
  showContent(true);
  const char* axes[] = {"x", "y"};
  QStringList notes;
  drawn_ = {};
  for (int a = 0; a < 2; ++a) {
    const std::string axis = axes[a];
    const std::vector<float> before = curveOf(pub, "importance." + axis);
    const std::vector<float> after = curveOf(pub, "importance." + axis + ".blurred");
    importance_[a]->setSeries({{tr("collapsed (max)"), centreSamples(before), kBefore},
                               {tr("blurred + floor"), centreSamples(after), kAfter}});
    importance_[a]->setPlaceholder(tr("No 1D importance published."));

    const std::vector<float>& w = a == 0 ? wx : wy;
    PlotWidget::Series warp{tr("u' = u + warp(u)"), {}, kWarp};
    const double n = static_cast<double>(w.size()) - 1.0;
    double maxSlope = 0.0, minSlope = 1e30, maxOffset = 0.0;
    for (std::size_t e = 0; e < w.size(); ++e) {
      const double u = e / std::max(n, 1.0);
      warp.points.emplace_back(u, u + w[e]);
      maxOffset = std::max(maxOffset, std::abs(double(w[e])));
      if (e > 0) {
        const double slope = (warp.points[e].y() - warp.points[e - 1].y()) * n;
        maxSlope = std::max(maxSlope, slope);
        minSlope = std::min(minSlope, slope);
      }
    }
    PlotWidget::Series identity{
        tr("identity (uniform)"), {{0.0, 0.0}, {1.0, 1.0}}, kIdentity, Qt::DashLine, 1.2};
    warp_[a]->setSeries({identity, warp});
    warp_[a]->setPlaceholder(tr("No warp map published for this axis."));
    if (w.size() >= 2) {
      notes << tr("%1: magnification %2× (densest) to %3× (sparsest), largest shift %4")
                   .arg(QString::fromLatin1(axes[a]))
                   .arg(maxSlope, 0, 'f', 2)
                   .arg(minSlope, 0, 'f', 2)
                   .arg(maxOffset, 0, 'f', 3);
      drawn_[QStringLiteral("%1.max_magnification").arg(QString::fromLatin1(axes[a]))] = maxSlope;
      drawn_[QStringLiteral("%1.min_magnification").arg(QString::fromLatin1(axes[a]))] = minSlope;
      drawn_[QStringLiteral("%1.edges").arg(QString::fromLatin1(axes[a]))] =
          static_cast<int>(w.size());
    }
  }
  info_->setText(notes.join(QStringLiteral(" · ")) +
                 tr("  — slope of the warp curve = shadow-map texels per uniform texel."));
  applyHighlight();
}

void WarpPanel::highlightPass(const QString& passId) {
  pass_ = passId;
  applyHighlight();
}

void WarpPanel::applyHighlight() {
  for (int a = 0; a < 2; ++a) {
    std::vector<PlotWidget::Series> s = importance_[a]->series();
    if (s.size() == 2) {
      s[0].highlighted = pass_ == QLatin1String("collapse");
      s[1].highlighted = pass_ == QLatin1String("blur");
      importance_[a]->setSeries(std::move(s));
    }
    std::vector<PlotWidget::Series> w = warp_[a]->series();
    if (w.size() == 2) {
      w[1].highlighted = pass_ == QLatin1String("scan + warp");
      warp_[a]->setSeries(std::move(w));
    }
    importance_[a]->setHighlighted(pass_ == QLatin1String("collapse") ||
                                   pass_ == QLatin1String("blur"));
    warp_[a]->setHighlighted(pass_ == QLatin1String("scan + warp"));
  }
}

QJsonObject WarpPanel::drawnValues() const {
  return drawn_;
}

}  // namespace sl::ui
