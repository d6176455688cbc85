// The Omni map panel (see OmniMapPanel.h).
#include "OmniMapPanel.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <QCheckBox>
#include <QLabel>
#include <QPainter>
#include <QPen>
#include <QVBoxLayout>

#include "algo/omni/OmniMapping.h"
#include "common/shared_constants.h"

namespace sl::ui {

namespace {
constexpr int kMaxCellTexels = 256;  ///< each face / disc is point-sampled to at most this
/// The one density scale of both mappings: log2 texels per steradian (256^2 cube faces: 14;
/// 4096^2 paraboloid rims: 22).
constexpr float kDensityLog2Min = 12.0f, kDensityLog2Max = 24.0f;
const float kNaN = std::numeric_limits<float>::quiet_NaN();

/// Cross cells (column, row from the bottom, rotated 180°) of faces 0..5 (+x, -x, +y, -y,
/// +z, -z): row 1 is +x, +z, -x, -z (up = +y each); +y and -y turned half round so that
/// their edges meet +z's.
struct Cell {
  int col, row;
  bool rotate;
};
const Cell kCross[omni::kCubeFaces] = {{0, 1, false}, {2, 1, false}, {1, 2, true},
                                       {1, 0, true},  {1, 1, false}, {3, 1, false}};
}  // namespace

OmniMapPanel::OmniMapPanel(QWidget* parent) : PublicationPanel(parent) {
  auto* content = new QWidget;
  auto* layout = new QVBoxLayout(content);
  layout->setContentsMargins(4, 4, 4, 4);
  density_ =
      new QCheckBox(tr("Texel density (log2 texels per steradian, one scale for cube "
                       "and paraboloid)"));
  density_->setObjectName(QStringLiteral("omniDensity"));
  layout->addWidget(density_);
  view_ = new ImageView;
  view_->setObjectName(QStringLiteral("omniMap"));
  layout->addWidget(view_, 1);
  info_ = new QLabel;
  info_->setObjectName(QStringLiteral("omniInfo"));
  info_->setWordWrap(true);
  layout->addWidget(info_);
  probeInfo_ = new QLabel(tr("Hover over the view: a marker shows the texel its pixel looks up."));
  probeInfo_->setObjectName(QStringLiteral("omniProbe"));
  probeInfo_->setWordWrap(true);
  layout->addWidget(probeInfo_);
  setContent(content);
  connect(density_, &QCheckBox::toggled, this, [this] { redraw(); });
}

std::set<std::string> OmniMapPanel::observedKeys() const {
  return {"face.*.map", "cube.faces", "cube.near_m", "cube.far_m", "half.*.map", "dp.far_m"};
}

void OmniMapPanel::showPublication(const sl::Publication& pub) {
  auto image = [&](const std::string& key) -> const sl::FloatImage* {
    auto it = pub.images.find(key);
    return it == pub.images.end() || it->second.width <= 0 ? nullptr : &it->second;
  };
  std::vector<const sl::FloatImage*> faces(omni::kCubeFaces), halves(2);
  int nFaces = 0, nHalves = 0;
  for (int i = 0; i < omni::kCubeFaces; ++i)
    nFaces += (faces[size_t(i)] = image("face." + std::to_string(i) + ".map")) != nullptr;
  for (int i = 0; i < 2; ++i)
    nHalves += (halves[size_t(i)] = image("half." + std::to_string(i) + ".map")) != nullptr;
  if (nFaces == 0 && nHalves == 0) {
    depth_.reset();
    kind_.clear();
    drawn_ = {};
    showContent(false, noDataText(QString::fromStdString(pub.techniqueId),
                                  tr("omni-directional maps"), observedKeys()));
    return;
  }
  showContent(true);
  const bool cube = nFaces > 0;
  const sl::FloatImage* any = nullptr;
  for (const sl::FloatImage* f : cube ? faces : halves)
    if (f) any = f;
  resolution_ = any->width;
  const int cell = std::min(resolution_, kMaxCellTexels);
  const int cols = cube ? 4 : 2, rows = cube ? 3 : 1;
  depth_ = std::make_shared<sl::FloatImage>();
  density_log2_ = std::make_shared<sl::FloatImage>();
  for (auto* img : {depth_.get(), density_log2_.get()}) {
    img->width = cols * cell;
    img->height = rows * cell;
    img->values.assign(size_t(img->width) * size_t(img->height), kNaN);
  }
  const omni::ParaboloidFrame frame = omni::paraboloidFrame({0, 1, 0});  // density only
  for (int m = 0; m < (cube ? omni::kCubeFaces : 2); ++m) {
    const sl::FloatImage* src = cube ? faces[size_t(m)] : halves[size_t(m)];
    const Cell c = cube ? kCross[m] : Cell{m, 0, false};
    for (int y = 0; y < cell; ++y)
      for (int x = 0; x < cell; ++x) {
        const glm::dvec2 uv((x + 0.5) / cell, (y + 0.5) / cell);
        double log2Density = kNaN;
        if (cube) {
          log2Density =
              std::log2(omni::cubeTexelsPerSteradian(omni::cubeDirection(m, uv), resolution_));
        } else if (glm::length(uv - 0.5) <= 0.5) {
          log2Density = std::log2(omni::paraboloidTexelsPerSteradian(
              frame, omni::paraboloidDirection(frame, 0, uv), resolution_));
        }
        float depth = 1.0f;
        if (src && !std::isnan(log2Density)) {
          const int sx = std::min(int(uv.x * src->width), src->width - 1);
          const int sy = std::min(int(uv.y * src->height), src->height - 1);
          depth = src->values[size_t(sy) * size_t(src->width) + size_t(sx)];
        } else if (!src) {
          depth = kNaN;  // a face a spot's cone does not reach: not rendered
        }
        const int dx = c.rotate ? cell - 1 - x : x, dy = c.rotate ? cell - 1 - y : y;
        const size_t at =
            size_t(c.row * cell + dy) * size_t(depth_->width) + size_t(c.col * cell + dx);
        depth_->values[at] = std::isnan(log2Density) ? kNaN : depth;
        density_log2_->values[at] = src ? float(log2Density) : kNaN;
      }
  }
  kind_ = cube ? QStringLiteral("cube") : QStringLiteral("paraboloid");
  nearM_ = cube ? pub.number("cube.near_m", 0.0) : 0.0;
  farM_ = pub.number(cube ? "cube.far_m" : "dp.far_m", 0.0);
  const double analytic = cube ? 3.0 * std::sqrt(3.0) : 4.0;
  info_->setText(cube ? tr("Cube: %1 of 6 faces of %2 × %2 texels (cross: +y above, −y below +x +z "
                           "−x −z). Texels "
                           "per steradian grow %3× from a face's centre to its corners.")
                            .arg(nFaces)
                            .arg(resolution_)
                            .arg(formatValue(analytic))
                      : tr("Dual paraboloid: %1 hemisphere(s) of %2 × %2 texels (left: along "
                           "dp.axis). Texels per "
                           "steradian grow %3× from a disc's centre to its rim (the split plane).")
                            .arg(nHalves)
                            .arg(resolution_)
                            .arg(formatValue(analytic)));
  drawn_ = {{QStringLiteral("kind"), kind_},
            {QStringLiteral("maps"), cube ? nFaces : nHalves},
            {QStringLiteral("resolution"), resolution_},
            {QStringLiteral("density_ratio_analytic"), analytic}};
  redraw();
}

void OmniMapPanel::redraw() {
  if (!depth_) return;
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
  auto depth = depth_, log2d = density_log2_;
  view_->setValueReader([depth, log2d, nearM = nearM_, farM = farM_](int x, int y) {
    const size_t at = size_t(y) * size_t(depth->width) + size_t(x);
    const float d = depth->values[at], l = log2d->values[at];
    if (std::isnan(l)) return QObject::tr("no texel");
    const QString stored =
        d >= 1.0f ? QObject::tr("1 (empty)")
        : farM > nearM
            ? QObject::tr("%1 m (stored %2)")
                  .arg(formatValue(omni::distanceFromStored(d, nearM, farM)), formatValue(d))
            : formatValue(d);
    return QObject::tr("distance = %1, %2 texels/sr").arg(stored, formatValue(std::exp2(l)));
  });
  view_->setCaption(kind_ == QLatin1String("cube") ? tr("cube faces") : tr("paraboloid discs"));
  view_->setOverlay([this](QPainter& p, const QRectF& r) { drawProbe(p, r); });
}

std::optional<QPointF> OmniMapPanel::probeInLayout() const {
  if (!depth_ || !probe_ || !probe_->covered) return std::nullopt;
  const bool cube = kind_ == QLatin1String("cube");
  const int maps = cube ? omni::kCubeFaces : 2;
  if (probe_->map < 0 || probe_->map >= maps) return std::nullopt;
  const int cell = depth_->height / (cube ? 3 : 1);
  const Cell c = cube ? kCross[probe_->map] : Cell{probe_->map, 0, false};
  const double u = std::clamp(double(probe_->mapUv.x), 0.0, 1.0);
  const double v = std::clamp(double(probe_->mapUv.y), 0.0, 1.0);
  return QPointF((c.col + (c.rotate ? 1.0 - u : u)) * cell,
                 (c.row + (c.rotate ? 1.0 - v : v)) * cell);
}

void OmniMapPanel::drawProbe(QPainter& painter, const QRectF& imageRect) const {
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

void OmniMapPanel::showProbe(const std::optional<sl::PixelProbe>& probe) {
  probe_ = probe;
  if (!probe) {
    probeInfo_->setText(tr("Hover over the view: a marker shows the texel its pixel looks up."));
  } else if (!probe->covered) {
    probeInfo_->setText(tr("Pixel (%1, %2): no surface.").arg(probe->x).arg(probe->y));
  } else if (!probeInLayout()) {
    probeInfo_->setText(
        tr("Pixel (%1, %2): not looked up in an omni map.").arg(probe->x).arg(probe->y));
  } else {
    const bool cube = kind_ == QLatin1String("cube");
    const QString map = cube ? tr("face %1").arg(QString::fromUtf8(omni::cubeFaceName(probe->map)))
                             : tr("hemisphere %1").arg(probe->map);
    probeInfo_->setText(tr("Pixel (%1, %2) looks up %3 at uv (%4, %5), texel (%6, %7): %8, m = %9.")
                            .arg(probe->x)
                            .arg(probe->y)
                            .arg(map)
                            .arg(probe->mapUv.x, 0, 'f', 3)
                            .arg(probe->mapUv.y, 0, 'f', 3)
                            .arg(int(probe->mapUv.x * resolution_))
                            .arg(int(probe->mapUv.y * resolution_))
                            .arg(probe->hard == SL_MASK_LIT ? tr("lit") : tr("shadowed"))
                            .arg(formatValue(probe->aliasing)));
  }
  view_->update();
}

void OmniMapPanel::highlightPass(const QString& passId) {
  view_->setHighlighted(passId == QLatin1String("cube faces") ||
                        passId == QLatin1String("paraboloid halves"));
}

QJsonObject OmniMapPanel::drawnValues() const {
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
