// The Shadow map panel (see ShadowMapPanel.h). The grid lines come from the CPU reference
// of the warp (sl::rtw::warpCoordinate / unwarpCoordinate, algo/rtw/Warp.h): on the warped
// map, the lines of a regular 16x16 grid of the unwarped map (cells grow where the warp
// spends more texels); on the uniform map, the warped map's regular grid pulled back
// (lines crowd where the importance is high).
#include "ShadowMapPanel.h"

#include <algorithm>
#include <cmath>

#include <QCheckBox>
#include <QCoreApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QVBoxLayout>

#include "algo/rtw/Warp.h"

namespace sl::ui {

namespace {
constexpr int kMaxDisplayTexels = 1024;  ///< larger maps are point-sampled for display

void showDepth(ImageView* view, const sl::FloatImage& image, const QString& caption) {
  const auto full = std::make_shared<const sl::FloatImage>(image);
  const sl::FloatImage shown = displayCopy(image, kMaxDisplayTexels);
  // Depth 1 = nothing rendered there (the clear value): left out of the range.
  const ValueRange range = finiteRange(shown.values, 1, 0, 1.0f);
  view->setImage(colorize(shown, 0, range, ColorMap::Grey), image.width, image.height);
  view->setLegend(range, ColorMap::Grey, QObject::tr("depth"));
  view->setCaption(caption);
  view->setValueReader([full](int x, int y) {
    const float d = full->values[(size_t(y) * full->width + x) * full->channels];
    return QStringLiteral("depth = %1").arg(d >= 1.0f ? QObject::tr("1 (empty)") : formatValue(d));
  });
}

void drawGrid(QPainter& p, const QRectF& r, const std::vector<float>& xs,
              const std::vector<float>& ys, const QColor& color) {
  p.setPen(QPen(color, 1.0));
  for (float u : xs) {
    const double x = r.left() + u * r.width();
    p.drawLine(QPointF(x, r.top()), QPointF(x, r.bottom()));
  }
  for (float v : ys) {
    const double y = r.bottom() - v * r.height();
    p.drawLine(QPointF(r.left(), y), QPointF(r.right(), y));
  }
}
}  // namespace

ShadowMapPanel::ShadowMapPanel(QWidget* parent) : PublicationPanel(parent) {
  auto [content, layout] = newPanelColumn();
  auto* bar = new QHBoxLayout;
  grid_ = new QCheckBox(tr("warp grid"));
  grid_->setChecked(true);
  grid_->setToolTip(tr("Lines every 1/%1 of the map, mapped through the warp").arg(kGridLines));
  connect(grid_, &QCheckBox::toggled, this, [this] { updateOverlays(); });
  bar->addWidget(grid_);
  bar->addStretch(1);
  layout->addLayout(bar);
  auto* views = new QHBoxLayout;
  warped_ = new ImageView;
  warped_->setObjectName(QStringLiteral("warpedMapView"));
  uniform_ = new ImageView;
  uniform_->setObjectName(QStringLiteral("uniformMapView"));
  views->addWidget(warped_);
  views->addWidget(uniform_);
  layout->addLayout(views, 1);
  info_ = new QLabel;
  info_->setWordWrap(true);
  info_->setForegroundRole(QPalette::PlaceholderText);
  layout->addWidget(info_);
  setContent(content);
}

namespace {
/// "2048×2048", or "16384×16384 (shown at 2048×2048)" for a map published downsampled.
QString mapSizeText(const sl::FloatImage& image) {
  const QString shown = QStringLiteral("%1×%2").arg(image.width).arg(image.height);
  if (image.sourceWidth <= 0) return shown;
  return QCoreApplication::translate("ShadowMapPanel", "%1×%2 (shown at %3)")
      .arg(image.sourceWidth)
      .arg(image.sourceHeight)
      .arg(shown);
}
}  // namespace

void ShadowMapPanel::showPublication(const sl::Publication& pub) {
  auto sm = pub.images.find("shadow map");
  if (sm == pub.images.end() || sm->second.width <= 0) {
    drawn_ = {};
    showContent(false, noDataText(QString::fromStdString(pub.techniqueId), tr("shadow map"),
                                  observedKeys()));
    return;
  }
  showContent(true);
  auto curve = [&pub](const char* key) {
    auto it = pub.curves.find(key);
    return it == pub.curves.end() ? std::vector<float>{} : it->second;
  };
  warpX_ = curve("warp.x");
  warpY_ = curve("warp.y");
  const bool warped = warpX_.size() >= 2 || warpY_.size() >= 2;
  showDepth(warped_, sm->second,
            (warped ? tr("Warped shadow map %1 (as rendered), warp grid") : tr("Shadow map %1"))
                .arg(mapSizeText(sm->second)));
  auto uni = pub.images.find("shadow map.uniform");
  // A map that does not warp takes the whole panel (a projector's big panel): no empty
  // "unwarped" half beside it.
  uniform_->setVisible(warped || (uni != pub.images.end() && uni->second.width > 0));
  if (uni != pub.images.end() && uni->second.width > 0) {
    showDepth(uniform_, uni->second,
              tr("Unwarped (uniform) map %1, warped texel grid pulled back")
                  .arg(mapSizeText(uni->second)));
  } else {
    uniform_->clearImage(warped ? tr("This technique publishes no unwarped map for contrast.")
                                : tr("This technique does not warp: its map is the uniform "
                                     "map. RTW techniques show both side by side."));
    uniform_->setLegend({}, ColorMap::Grey, QString(), false);
    uniform_->setCaption(tr("Unwarped (uniform) map"));
  }
  info_->setText(warped ? tr("Left: each grid cell is 1/%1 of the unwarped map per axis; large "
                             "cells = many texels spent there. Right: the warped map's texel "
                             "columns and rows, crowding where importance is high.")
                              .arg(kGridLines)
                        : tr("A uniform map spends its texels evenly over the light frustum "
                             "(it does not warp: RTW techniques show their unwarped map beside "
                             "the warped one)."));
  drawn_ = {{QStringLiteral("width"), sm->second.width},
            {QStringLiteral("height"), sm->second.height},
            {QStringLiteral("map_width"),
             sm->second.sourceWidth ? sm->second.sourceWidth : sm->second.width},
            {QStringLiteral("warped"), warped},
            {QStringLiteral("uniform_published"), uni != pub.images.end()}};
  updateOverlays();
}

void ShadowMapPanel::updateOverlays() {
  const bool on = grid_->isChecked();
  if (!on) {
    warped_->setOverlay({});
    uniform_->setOverlay({});
    return;
  }
  std::vector<float> fx, fy, bx, by;  // forward (warped) and pulled-back grid lines
  for (int k = 1; k < kGridLines; ++k) {
    const float u = float(k) / kGridLines;
    fx.push_back(warpX_.size() >= 2 ? sl::rtw::warpCoordinate(warpX_, u) : u);
    fy.push_back(warpY_.size() >= 2 ? sl::rtw::warpCoordinate(warpY_, u) : u);
    bx.push_back(warpX_.size() >= 2 ? sl::rtw::unwarpCoordinate(warpX_, u) : u);
    by.push_back(warpY_.size() >= 2 ? sl::rtw::unwarpCoordinate(warpY_, u) : u);
  }
  warped_->setOverlay([fx, fy](QPainter& p, const QRectF& r) {
    drawGrid(p, r, fx, fy, QColor(255, 190, 40, 200));
  });
  uniform_->setOverlay([bx, by](QPainter& p, const QRectF& r) {
    drawGrid(p, r, bx, by, QColor(90, 200, 255, 200));
  });
}

void ShadowMapPanel::highlightPass(const QString& passId) {
  warped_->setHighlighted(passId == QLatin1String("warped shadow map"));
  uniform_->setHighlighted(false);
}

QJsonObject ShadowMapPanel::drawnValues() const {
  return drawn_;
}

}  // namespace sl::ui
