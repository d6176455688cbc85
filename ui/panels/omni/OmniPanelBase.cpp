// The omni family's map panels' shared frame (see OmniPanelBase.h).
#include "OmniPanelBase.h"

#include <cmath>
#include <limits>

#include <QCheckBox>
#include <QLabel>
#include <QPainter>
#include <QPen>
#include <QVBoxLayout>

#include "algo/omni/OmniMapping.h"

namespace sl::ui {

namespace {
/// The one density scale of every omni mapping: log2 texels per steradian (256^2 cube faces:
/// 14; 4096^2 paraboloid rims: 22).
constexpr float kDensityLog2Min = 12.0f, kDensityLog2Max = 24.0f;
}  // namespace

OmniPanelBase::OmniPanelBase(Setup setup, QWidget* parent)
    : PublicationPanel(parent),
      mapNoun_(std::move(setup.mapNoun)),
      keys_(std::move(setup.keys)),
      passes_(std::move(setup.passes)) {
  const QString& name = setup.name;
  auto [content, layout] = newPanelColumn();
  density_ = new QCheckBox(setup.densityText);
  density_->setObjectName(name + QStringLiteral("Density"));
  layout->addWidget(density_);
  view_ = new ImageView;
  view_->setObjectName(name + QStringLiteral("Map"));
  layout->addWidget(view_, 1);
  info_ = new QLabel;
  info_->setObjectName(name + QStringLiteral("Info"));
  info_->setWordWrap(true);
  layout->addWidget(info_);
  probeInfo_ = new QLabel(hoverText());
  probeInfo_->setObjectName(name + QStringLiteral("Probe"));
  probeInfo_->setWordWrap(true);
  layout->addWidget(probeInfo_);
  setContent(content);
  connect(density_, &QCheckBox::toggled, this, [this] { redraw(); });
}

QString OmniPanelBase::hoverText() const {
  return tr("Hover over the view: a marker shows the texel its pixel looks up.");
}

void OmniPanelBase::allocateLayout(int width, int height) {
  depth_ = std::make_shared<sl::FloatImage>();
  density_log2_ = std::make_shared<sl::FloatImage>();
  for (auto* img : {depth_.get(), density_log2_.get()}) {
    img->width = width;
    img->height = height;
    img->values.assign(size_t(width) * size_t(height), std::numeric_limits<float>::quiet_NaN());
  }
}

void OmniPanelBase::showLayout() {
  const bool density = density_->isChecked();
  const sl::FloatImage& shown = density ? *density_log2_ : *depth_;
  const ValueRange range = density ? ValueRange{kDensityLog2Min, kDensityLog2Max}
                                   : finiteRange(shown.values, 1, 0, 1.0f);
  const ColorMap map = density ? ColorMap::Viridis : ColorMap::Grey;
  view_->setImage(colorize(shown, 0, range, map), shown.width, shown.height);
  view_->setLegend(range, map, density ? tr("log2 texels/sr") : QString(), density);
  drawn_[QStringLiteral("density_shown")] = density;
  drawn_[QStringLiteral("scale_min")] = double(range.lo);
  drawn_[QStringLiteral("scale_max")] = double(range.hi);
}

QString OmniPanelBase::storedDistanceText(float stored, double nearM, double farM) {
  if (stored >= 1.0f) return QObject::tr("1 (empty)");
  if (farM > nearM)
    return QObject::tr("%1 m (stored %2)")
        .arg(formatValue(omni::distanceFromStored(stored, nearM, farM)), formatValue(stored));
  return formatValue(stored);
}

void OmniPanelBase::drawProbeMarker(QPainter& painter, const QRectF& imageRect) const {
  const std::optional<QPointF> at = probeInLayout();
  if (!at) return;
  const QPointF p(imageRect.left() + at->x() / depth_->width * imageRect.width(),
                  imageRect.bottom() - at->y() / depth_->height * imageRect.height());
  painter.setRenderHint(QPainter::Antialiasing);
  for (const auto& [colour, width] :
       {std::pair{QColor(0, 0, 0), 4.0}, {QColor(255, 64, 200), 2.0}}) {
    painter.setPen(QPen(colour, width));
    painter.setBrush(Qt::NoBrush);
    painter.drawEllipse(p, 7.0, 7.0);
    painter.drawLine(p - QPointF(13, 0), p - QPointF(8, 0));
    painter.drawLine(p + QPointF(8, 0), p + QPointF(13, 0));
    painter.drawLine(p - QPointF(0, 13), p - QPointF(0, 8));
    painter.drawLine(p + QPointF(0, 8), p + QPointF(0, 13));
  }
}

void OmniPanelBase::showProbe(const std::optional<sl::PixelProbe>& probe) {
  probe_ = probe;
  if (!probe) {
    probeInfo_->setText(hoverText());
  } else if (!probe->covered) {
    probeInfo_->setText(tr("Pixel (%1, %2): no surface.").arg(probe->x).arg(probe->y));
  } else if (!probeInLayout()) {
    probeInfo_->setText(
        tr("Pixel (%1, %2): not looked up in %3.").arg(probe->x).arg(probe->y).arg(mapNoun_));
  } else {
    probeInfo_->setText(probeText(*probe));
  }
  view_->update();
}

void OmniPanelBase::highlightPass(const QString& passId) {
  view_->setHighlighted(passes_.contains(passId));
}

QJsonObject OmniPanelBase::drawnValues() const {
  QJsonObject drawn = drawn_;
  if (const std::optional<QPointF> at = probeInLayout()) {
    drawn[QStringLiteral("probe_map")] = probe_->map;
    drawn[QStringLiteral("probe_u")] = probe_->mapUv.x;
    drawn[QStringLiteral("probe_v")] = probe_->mapUv.y;
    drawn[QStringLiteral("probe_layout_x")] = at->x();  // texels of the drawn layout, v up
    drawn[QStringLiteral("probe_layout_y")] = at->y();
  }
  return drawn;
}

}  // namespace sl::ui
