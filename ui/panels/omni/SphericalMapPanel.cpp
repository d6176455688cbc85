// The Spherical map panel (see SphericalMapPanel.h).
#include "SphericalMapPanel.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <QLabel>
#include <QPainter>
#include <QPen>

#include "algo/omni/LatLongMapping.h"
#include "algo/omni/OmniMapping.h"
#include "common/shared_constants.h"

namespace sl::ui {

namespace {
constexpr int kMaxHalfTexels = 256;  ///< each half is point-sampled to at most this
}  // namespace

SphericalMapPanel::SphericalMapPanel(QWidget* parent)
    : OmniPanelBase({.name = QStringLiteral("spherical"),
                     .densityText = tr(
                         "Texel density (log2 texels per steradian, the Omni map panel's scale)"),
                     .mapNoun = tr("a lat-long map"),
                     .keys = {"sph.half.*.map", "sph.far_m"},
                     .passes = {QStringLiteral("lat-long halves")}},
                    parent) {}

void SphericalMapPanel::showPublication(const sl::Publication& pub) {
  const sl::FloatImage* halves[omni::kLatLongHalves] = {nullptr, nullptr};
  for (int i = 0; i < omni::kLatLongHalves; ++i) {
    auto it = pub.images.find("sph.half." + std::to_string(i) + ".map");
    if (it != pub.images.end() && it->second.width > 0) halves[i] = &it->second;
  }
  if (!halves[0] || !halves[1]) {
    depth_.reset();
    drawn_ = {};
    showContent(false, noDataText(QString::fromStdString(pub.techniqueId),
                                  tr("a latitude-longitude map"), observedKeys()));
    return;
  }
  showContent(true);
  resolution_ = halves[0]->height;
  const int cell = std::min(resolution_, kMaxHalfTexels);
  allocateLayout(omni::kLatLongHalves * cell, cell);
  // Density depends on latitude only: any frame.
  const omni::LatLongFrame frame = omni::latLongFrame({0, 1, 0});
  for (int y = 0; y < cell; ++y) {
    const glm::dvec2 uv(0.25, (y + 0.5) / cell);
    const float log2Density = float(std::log2(
        omni::latLongTexelsPerSteradian(frame, omni::latLongUvDirection(frame, uv), resolution_)));
    for (int m = 0; m < omni::kLatLongHalves; ++m) {
      const sl::FloatImage& src = *halves[m];
      const int sy = std::min(int(uv.y * src.height), src.height - 1);
      for (int x = 0; x < cell; ++x) {
        const int sx = std::min(int((x + 0.5) / cell * src.width), src.width - 1);
        const size_t at = size_t(y) * size_t(depth_->width) + size_t(m * cell + x);
        depth_->values[at] = src.values[size_t(sy) * size_t(src.width) + size_t(sx)];
        density_log2_->values[at] = log2Density;
      }
    }
  }
  farM_ = pub.number("sph.far_m", 0.0);
  const double poleRatio = 1.0 / std::tan(std::numbers::pi / (2.0 * resolution_));
  info_->setText(
      tr("Latitude-longitude map of %1 × %2 texels (two halves of %2 × %2): longitude −180° "
         "(left) to 180° (right) about sph.axis, the south pole at the bottom. The seam "
         "(orange) is one meridian at both side edges; each pole (magenta) is one point spread "
         "over a whole row. Texels per steradian: %3 on the equator, growing as "
         "1 / cos(latitude); a top- or bottom-row texel is %4× smaller than an equator one "
         "(cot(π / 2H), growing with resolution; the cube's ratio is 3√3 and the paraboloid's 4).")
          .arg(2 * resolution_)
          .arg(resolution_)
          .arg(formatValue(double(resolution_) * resolution_ /
                           (std::numbers::pi * std::numbers::pi)))
          .arg(formatValue(poleRatio)));
  drawn_ = {{QStringLiteral("kind"), QStringLiteral("latlong")},
            {QStringLiteral("maps"), omni::kLatLongHalves},
            {QStringLiteral("resolution"), resolution_},
            {QStringLiteral("pole_ratio_analytic"), poleRatio}};
  redraw();
}

void SphericalMapPanel::redraw() {
  if (!depth_) return;
  showLayout();
  auto depth = depth_, log2d = density_log2_;
  view_->setValueReader([depth, log2d, farM = farM_](int x, int y) {
    const size_t at = size_t(y) * size_t(depth->width) + size_t(x);
    const float d = depth->values[at], l = log2d->values[at];
    const double lonDeg = (x + 0.5) / depth->width * 360.0 - 180.0;
    const double latDeg = (y + 0.5) / depth->height * 180.0 - 90.0;
    return QObject::tr("longitude %1°, latitude %2°: distance = %3, %4 texels/sr")
        .arg(lonDeg, 0, 'f', 1)
        .arg(latDeg, 0, 'f', 1)
        .arg(storedDistanceText(d, 0.0, farM), formatValue(std::exp2(l)));
  });
  view_->setCaption(tr("latitude-longitude map"));
  view_->setOverlay([this](QPainter& p, const QRectF& r) { drawOverlay(p, r); });
}

std::optional<QPointF> SphericalMapPanel::probeInLayout() const {
  if (!depth_ || !probe_ || !probe_->covered) return std::nullopt;
  if (probe_->map < 0 || probe_->map >= omni::kLatLongHalves) return std::nullopt;
  const int cell = depth_->height;
  const double u = std::clamp(double(probe_->mapUv.x), 0.0, 1.0);
  const double v = std::clamp(double(probe_->mapUv.y), 0.0, 1.0);
  return QPointF((probe_->map + u) * cell, v * cell);
}

void SphericalMapPanel::drawOverlay(QPainter& painter, const QRectF& r) const {
  if (!depth_) return;
  painter.setRenderHint(QPainter::Antialiasing);
  // The seam: the left and right edges (one meridian, ±180°).
  QPen seam(QColor(255, 150, 0), 3.0, Qt::DashLine);
  painter.setPen(seam);
  painter.drawLine(r.topLeft(), r.bottomLeft());
  painter.drawLine(r.topRight(), r.bottomRight());
  // The poles: the top and bottom edges (each one direction).
  painter.setPen(QPen(QColor(255, 64, 200), 3.0));
  painter.drawLine(r.topLeft(), r.topRight());
  painter.drawLine(r.bottomLeft(), r.bottomRight());
  // The halves' border (longitude 0) and the equator, thin.
  painter.setPen(QPen(QColor(160, 160, 160), 1.0, Qt::DotLine));
  painter.drawLine(QPointF(r.center().x(), r.top()), QPointF(r.center().x(), r.bottom()));
  painter.drawLine(QPointF(r.left(), r.center().y()), QPointF(r.right(), r.center().y()));
  painter.setPen(QColor(255, 255, 255));
  painter.drawText(r.adjusted(6, 4, -6, -4), Qt::AlignTop | Qt::AlignHCenter, tr("north pole"));
  painter.drawText(r.adjusted(6, 4, -6, -4), Qt::AlignBottom | Qt::AlignHCenter, tr("south pole"));
  painter.drawText(r.adjusted(6, 4, -6, -4), Qt::AlignVCenter | Qt::AlignLeft, tr("seam"));
  painter.drawText(r.adjusted(6, 4, -6, -4), Qt::AlignVCenter | Qt::AlignRight, tr("seam"));
  drawProbeMarker(painter, r);
}

QString SphericalMapPanel::probeText(const sl::PixelProbe& probe) const {
  const double lonDeg = (probe.map + double(probe.mapUv.x)) * 180.0 - 180.0;
  const double latDeg = double(probe.mapUv.y) * 180.0 - 90.0;
  return tr("Pixel (%1, %2) looks up half %3 at longitude %4°, latitude %5°, texel (%6, %7): "
            "%8, m = %9.")
      .arg(probe.x)
      .arg(probe.y)
      .arg(probe.map)
      .arg(lonDeg, 0, 'f', 1)
      .arg(latDeg, 0, 'f', 1)
      .arg(int((probe.map + probe.mapUv.x) * resolution_))
      .arg(int(probe.mapUv.y * resolution_))
      .arg(probe.hard == SL_MASK_LIT ? tr("lit") : tr("shadowed"))
      .arg(formatValue(probe.aliasing));
}

}  // namespace sl::ui
