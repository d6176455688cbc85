// The Omni map panel (see OmniMapPanel.h).
#include "OmniMapPanel.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <QLabel>
#include <QPainter>

#include "algo/omni/OmniMapping.h"
#include "common/shared_constants.h"

namespace sl::ui {

namespace {
constexpr int kMaxCellTexels = 256;  ///< each face / disc is point-sampled to at most this
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

OmniMapPanel::OmniMapPanel(QWidget* parent)
    : OmniPanelBase({.name = QStringLiteral("omni"),
                     .densityText = tr("Texel density (log2 texels per steradian, one scale for "
                                       "cube and paraboloid)"),
                     .mapNoun = tr("an omni map"),
                     .keys = {"face.*.map", "cube.faces", "cube.near_m", "cube.far_m", "half.*.map",
                              "dp.far_m"},
                     .passes = {QStringLiteral("cube faces"), QStringLiteral("paraboloid halves")}},
                    parent) {}

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
  allocateLayout(cols * cell, rows * cell);
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
  showLayout();
  auto depth = depth_, log2d = density_log2_;
  view_->setValueReader([depth, log2d, nearM = nearM_, farM = farM_](int x, int y) {
    const size_t at = size_t(y) * size_t(depth->width) + size_t(x);
    const float d = depth->values[at], l = log2d->values[at];
    if (std::isnan(l)) return QObject::tr("no texel");
    return QObject::tr("distance = %1, %2 texels/sr")
        .arg(storedDistanceText(d, nearM, farM), formatValue(std::exp2(l)));
  });
  view_->setCaption(kind_ == QLatin1String("cube") ? tr("cube faces") : tr("paraboloid discs"));
  view_->setOverlay([this](QPainter& p, const QRectF& r) { drawProbeMarker(p, r); });
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

QString OmniMapPanel::probeText(const sl::PixelProbe& probe) const {
  const bool cube = kind_ == QLatin1String("cube");
  const QString map = cube ? tr("face %1").arg(QString::fromUtf8(omni::cubeFaceName(probe.map)))
                           : tr("hemisphere %1").arg(probe.map);
  return tr("Pixel (%1, %2) looks up %3 at uv (%4, %5), texel (%6, %7): %8, m = %9.")
      .arg(probe.x)
      .arg(probe.y)
      .arg(map)
      .arg(probe.mapUv.x, 0, 'f', 3)
      .arg(probe.mapUv.y, 0, 'f', 3)
      .arg(int(probe.mapUv.x * resolution_))
      .arg(int(probe.mapUv.y * resolution_))
      .arg(probe.hard == SL_MASK_LIT ? tr("lit") : tr("shadowed"))
      .arg(formatValue(probe.aliasing));
}

}  // namespace sl::ui
