// The Storage factor panel (see StoragePanel.h): the analysis of algo/partition for the
// frame's camera, light and scheme, drawn with renderer/figures/StorageChartKit.h (as
// shadowlab-cli's PNGs).
#include "panels/analysis/StoragePanel.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>

#include <QJsonObject>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QSplitter>
#include <QThreadPool>
#include <QVBoxLayout>
#include <QtCharts/QChartView>

#include "figures/StorageChartKit.h"
#include "window/Theme.h"

namespace sl::ui {

namespace {
/// The world's up (scenes are y up): the hemisphere's centre.
const glm::dvec3 kWorldUp(0.0, 1.0, 0.0);
}  // namespace

// --- The hemisphere view -------------------------------------------------------------------

/// S over the light's hemisphere (one disk, a colour bar), the light marked; a click picks
/// a direction.
class HemisphereView : public QWidget {
 public:
  explicit HemisphereView(std::function<void(double u, double v)> clicked)
      : clicked_(std::move(clicked)) {
    setMinimumSize(220, 200);
    setMouseTracking(true);
    setCursor(Qt::CrossCursor);
    setToolTip(
        tr("Storage factor S over the light's hemisphere for this camera (Lloyd et al. "
           "2006, Fig. 7). Centre: overhead; rim: horizon; right: in front of the "
           "camera; left: behind it; top: to its right. Click to move the light there."));
  }
  void setData(const sl::partition::HemispherePanel* panel, glm::dvec2 mark, QString caption) {
    panel_ = panel, mark_ = mark, caption_ = std::move(caption);
    update();
  }
  void setPlaceholder(const QString& text) {
    panel_ = nullptr, caption_ = text;
    update();
  }
  QSize sizeHint() const override { return {340, 300}; }
  /// Where disk coordinates (u, v) lie in this widget (what a click there picks).
  QPointF pointAt(double u, double v) const { return diskToWidget(diskRect(), u, v); }

 protected:
  /// The labels' font: kSmallText x the body size (presenter mode scales it).
  static QFont labelFont() { return bodyRelativeFont(kSmallText); }
  /// The disk with room for its labels ("behind" on the left, "right" above, the colour
  /// bar and its ticks on the right, two caption lines below) at the labels' size.
  QRectF diskRect() const {
    const QFontMetrics fm(labelFont());
    const double left = fm.horizontalAdvance(QStringLiteral("behind")) + 10.0;
    const double top = fm.height() + 8.0;
    const double right = fm.horizontalAdvance(QStringLiteral("in front")) + 22.0 + 14.0 +
                         fm.horizontalAdvance(QStringLiteral("0.000e+00"));
    const double below = 2.0 * fm.height() + 12.0;
    const double side = std::max(60.0, std::min(width() - left - right, height() - top - below));
    return {left, top, side, side};
  }
  void paintEvent(QPaintEvent*) override {
    QPainter g(this);
    g.setRenderHint(QPainter::Antialiasing);
    g.fillRect(rect(), Qt::white);
    g.setPen(Qt::black);
    if (!panel_) {
      g.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, caption_);
      return;
    }
    const std::optional<StorageScale> scale = storageScale({*panel_});
    if (!scale) return;
    const QRectF disk = diskRect();
    const QFont font = labelFont();
    const QFontMetrics fm(font);
    paintHemisphereDisk(g, disk, *panel_, *scale, font.pixelSize());
    paintLightMark(g, diskToWidget(disk, mark_.x, mark_.y), 6.0);
    const int barX = int(disk.right()) + fm.horizontalAdvance(QStringLiteral("in front")) + 12;
    paintStorageColorBar(g, QRect(barX, int(disk.top()), 14, int(disk.height())), *scale,
                         font.pixelSize());
    g.setFont(font);
    g.setPen(Qt::black);
    QString text = caption_;
    if (hover_) text += QStringLiteral("   |   cursor: S %1").arg(formatValue(*hover_));
    g.drawText(QRectF(4, disk.bottom() + 4, width() - 8, 2 * fm.height() + 6),
               Qt::AlignLeft | Qt::TextWordWrap, text);
  }
  std::optional<double> cellAt(const QPointF& p) const {
    if (!panel_) return std::nullopt;
    const QPointF uv = widgetToDisk(diskRect(), p);
    if (std::hypot(uv.x(), uv.y()) > 1.0) return std::nullopt;
    const int n = panel_->grid;
    const int c = std::clamp(int((uv.x() + 1.0) * 0.5 * n), 0, n - 1);
    const int r = std::clamp(int((1.0 - uv.y()) * 0.5 * n), 0, n - 1);
    const double s = panel_->s[std::size_t(r * n + c)];
    return std::isfinite(s) ? std::optional<double>(s) : std::nullopt;
  }
  void mouseMoveEvent(QMouseEvent* e) override {
    hover_ = cellAt(e->position());
    update();
  }
  void mousePressEvent(QMouseEvent* e) override {
    if (!panel_ || e->button() != Qt::LeftButton) return;
    const QPointF uv = widgetToDisk(diskRect(), e->position());
    if (std::hypot(uv.x(), uv.y()) <= 1.0) clicked_(uv.x(), uv.y());
  }
  void leaveEvent(QEvent*) override {
    hover_.reset();
    update();
  }

 private:
  std::function<void(double, double)> clicked_;
  const sl::partition::HemispherePanel* panel_ = nullptr;
  glm::dvec2 mark_{0.0};
  QString caption_;
  std::optional<double> hover_;
};

/// The eta plot (Fig. 6) in a chart view; a new chart per result.
class EtaView : public QChartView {
 public:
  EtaView() {
    setRenderHint(QPainter::Antialiasing);
    setMinimumSize(240, 200);
    followBodyFont(this, [this] {
      if (chart()) setChartFonts(*chart());
    });
  }
  void setCurve(const sl::partition::EtaCurve& curve, std::optional<double> eta) {
    QChart* old = chart();
    QChart* c = makeEtaChart(curve, eta,
                             eta ? tr("this technique: eta %1").arg(*eta, 0, 'g', 3) : QString());
    setChartFonts(*c);
    // Short names in a narrow dock (the CLI's PNG keeps the long ones).
    const QString names[] = {QStringLiteral("M_x"), QStringLiteral("M_z"),
                             QStringLiteral("S = M_x M_z"), tr("this technique")};
    const QList<QAbstractSeries*> series = c->series();
    for (int i = 0; i < series.size() && i < 4; ++i) series[i]->setName(names[i]);
    if (!c->axes(Qt::Horizontal).isEmpty())
      c->axes(Qt::Horizontal).front()->setTitleText(tr("eta: -1 uniform, 0 LiSPSM, 1 PSM"));
    if (!c->axes(Qt::Vertical).isEmpty()) {
      QAbstractAxis* y = c->axes(Qt::Vertical).front();
      y->setTitleText(tr("/ maximum over eta"));
      if (auto* v = qobject_cast<QValueAxis*>(y)) v->setTickCount(4);  // room for the labels
    }
    c->setMargins(QMargins(2, 2, 2, 2));
    setChart(c);
    delete old;  // setChart releases the previous chart's ownership
  }
};

// --- The panel ------------------------------------------------------------------------------

struct StoragePanel::Result {
  StorageInputs inputs;
  sl::partition::HemisphereFrame frame;
  sl::partition::HemispherePanel hemisphere;
  sl::partition::EtaCurve eta;
  sl::partition::StorageResult current;  ///< at the frame's light
  std::string error;
  double computeMs = 0.0;
};

/// The worker's way back: the panel, cleared (under the lock) when the panel goes away.
struct StoragePanel::Shared {
  std::mutex mutex;
  StoragePanel* panel = nullptr;
};

StoragePanel::StoragePanel(QWidget* parent)
    : PublicationPanel(parent), shared_(std::make_shared<Shared>()) {
  shared_->panel = this;
  auto [content, layout] = newPanelColumn();
  auto* split = new QSplitter(Qt::Vertical);
  hemisphere_ = new HemisphereView([this](double u, double v) {
    if (!result_) return;
    if (const auto l = result_->frame.direction(u, v)) {
      const sl::Light light = sl::Light::directionalFromTowards(glm::vec3(*l));
      Q_EMIT lightChosen(light.azimuthDeg, light.elevationDeg);
    }
  });
  eta_ = new EtaView;
  split->addWidget(hemisphere_);
  split->addWidget(eta_);
  layout->addWidget(split, 1);
  numbers_ = new QLabel;
  numbers_->setTextFormat(Qt::RichText);
  numbers_->setWordWrap(true);
  numbers_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(numbers_);
  setContent(content);
}

StoragePanel::~StoragePanel() {
  std::lock_guard lock(shared_->mutex);
  shared_->panel = nullptr;
}

void StoragePanel::showPublication(const sl::Publication& pub) {
  auto num = [&](const std::string& key) -> std::optional<double> {
    auto it = pub.numbers.find(key);
    if (it == pub.numbers.end() || !std::isfinite(it->second)) return std::nullopt;
    return it->second;
  };
  const auto nearM = num("camera.near_m"), farM = num("camera.far_m"), fov = num("camera.fov_deg"),
             aspect = num("camera.aspect"), az = num("light.azimuth_deg"),
             el = num("light.elevation_deg");
  const auto fx = num("camera.forward.x"), fy = num("camera.forward.y"),
             fz = num("camera.forward.z"), ux = num("camera.up.x"), uy = num("camera.up.y"),
             uz = num("camera.up.z");
  if (const auto type = num("light.type");
      type && *type != double(int(sl::LightType::Directional))) {
    showContent(false, tr("The storage factor (Lloyd et al. 2006) measures a directional light's "
                          "maps over the view frustum; the frame's light is a %1 light, whose maps "
                          "(cube faces, paraboloids, a spot's frustum) it does not analyse.")
                           .arg(QString::fromUtf8(
                               sl::lightTypeName(static_cast<sl::LightType>(int(*type))).data())));
    return;
  }
  if (!nearM || !farM || !fov || !aspect || !az || !el || !fx || !fy || !fz || !ux || !uy || !uz) {
    showContent(false, tr("The Storage factor panel needs the frame's camera and light "
                          "(renderer publications camera.*, light.*): none this frame."));
    return;
  }
  showContent(true);
  StorageInputs in;
  sl::Camera cam;
  cam.position = glm::vec3(0.0f);
  cam.target = glm::vec3(float(*fx), float(*fy), float(*fz));
  cam.up = glm::vec3(float(*ux), float(*uy), float(*uz));
  cam.nearM = float(*nearM), cam.farM = float(*farM), cam.fovYDeg = float(*fov);
  in.view = sl::warp::ViewFrustum::fromCamera(cam, *aspect);
  in.towardsLight = glm::dvec3(sl::Light::directional(float(*az), float(*el)).directionalTowards());
  schemeFromDeclarations(
      sl::Renderer::findTechnique(pub.techniqueId),
      [&](const std::string& key) { return num("param." + key); }, num, in);
  measuredP95_ = num("aliasing.p95").value_or(-1.0);
  measuredMax_ = num("aliasing.max").value_or(-1.0);
  binOctaves_ = num("aliasing.bin_octaves").value_or(0.0);
  heightPx_ = num("camera.height_px").value_or(0.0);
  mapResolution_ = num("param.resolution").value_or(0.0);
  inputs_ = in;
  if (!running_ && (!result_ || !(result_->inputs == in))) start();
  updateNumbers();
}

void StoragePanel::start() {
  running_ = inputs_;
  std::shared_ptr<Shared> shared = shared_;
  StorageInputs in = *inputs_;
  QThreadPool::globalInstance()->start([shared, in] {
    const auto t0 = std::chrono::steady_clock::now();
    auto r = std::make_shared<Result>();
    r->inputs = in;
    r->frame = sl::partition::HemisphereFrame::forView(in.view, kWorldUp);
    r->hemisphere.title = in.schemeLabel;
    std::optional<std::string> err =
        sl::partition::hemispherePanel(in.view, r->frame, in.settings, in.grid, r->hemisphere);
    if (!err) err = sl::partition::etaCurve(in.view, in.towardsLight, 81, r->eta);
    if (!err)
      err = sl::partition::evaluateScheme(in.view, in.towardsLight, in.settings, r->current);
    if (err) r->error = *err;
    r->computeMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    std::lock_guard lock(shared->mutex);
    if (StoragePanel* p = shared->panel)
      QMetaObject::invokeMethod(
          p, [p, r] { p->finished(r); }, Qt::QueuedConnection);
  });
}

void StoragePanel::finished(std::shared_ptr<const Result> result) {
  running_.reset();
  result_ = std::move(result);
  if (!result_->error.empty()) {
    hemisphere_->setPlaceholder(tr("analysis: %1").arg(QString::fromStdString(result_->error)));
  } else {
    const glm::dvec2 mark = result_->frame.disk(result_->inputs.towardsLight);
    hemisphere_->setData(&result_->hemisphere, mark,
                         tr("S for %1; %2x%2 cells in %3 ms off the UI thread")
                             .arg(QString::fromStdString(result_->inputs.schemeLabel))
                             .arg(result_->inputs.grid)
                             .arg(result_->computeMs, 0, 'f', 1));
    eta_->setCurve(result_->eta, result_->inputs.eta);
  }
  updateNumbers();
  // The frame moved on while this ran: analyse the latest inputs.
  if (inputs_ && !(result_->inputs == *inputs_)) start();
}

void StoragePanel::updateNumbers() {
  QJsonObject drawn;
  QString text;
  if (result_ && result_->error.empty()) {
    const StorageInputs& in = result_->inputs;
    const sl::partition::StorageResult& r = result_->current;
    const sl::Light light = sl::Light::directionalFromTowards(glm::vec3(in.towardsLight));
    text += tr("<b>%1</b> &nbsp; n %2 m, f %3 m, fov %4°, aspect %5, light az %6° el %7°<br>")
                .arg(QString::fromStdString(in.schemeLabel).toHtmlEscaped(),
                     formatValue(in.view.nearM), formatValue(in.view.farM),
                     formatValue(glm::degrees(in.view.fovYRad)), formatValue(in.view.aspect))
                .arg(light.azimuthDeg, 0, 'f', 1)
                .arg(light.elevationDeg, 0, 'f', 1);
    text += tr("Predicted over the whole view frustum (res 1): <b>S %1</b>, M<sub>x</sub> %2, "
               "M<sub>z</sub> %3 (%4 map%5)")
                .arg(formatValue(r.s), formatValue(r.mx), formatValue(r.mz))
                .arg(r.parts.size())
                .arg(r.parts.size() == 1 ? QString() : QStringLiteral("s"));
    // The first part that falls back to uniform, named with the algorithm's reason.
    const auto falling =
        std::find_if(r.parts.begin(), r.parts.end(), [](const auto& p) { return p.fit.fallback; });
    drawn[QStringLiteral("fallback")] = falling != r.parts.end();
    if (in.eta) drawn[QStringLiteral("eta")] = *in.eta;
    if (falling != r.parts.end())
      text += tr("; <span style='color:#b35900'>%1 falls back to uniform: %2</span>")
                  .arg(QString::fromStdString(falling->label).toHtmlEscaped(),
                       QString::fromStdString(falling->fit.fallbackReason).toHtmlEscaped());
    drawn[QStringLiteral("scheme")] = QString::fromStdString(in.schemeLabel);
    drawn[QStringLiteral("s")] = r.s;
    drawn[QStringLiteral("mx")] = r.mx;
    drawn[QStringLiteral("mz")] = r.mz;
    drawn[QStringLiteral("grid")] = in.grid;
    const glm::dvec2 mark = result_->frame.disk(in.towardsLight);
    drawn[QStringLiteral("mark_u")] = mark.x;
    drawn[QStringLiteral("mark_v")] = mark.y;
    drawn[QStringLiteral("light_azimuth_deg")] = double(light.azimuthDeg);
    drawn[QStringLiteral("light_elevation_deg")] = double(light.elevationDeg);
    drawn[QStringLiteral("compute_ms")] = result_->computeMs;
    if (heightPx_ > 0.0 && mapResolution_ > 0.0) {
      // m in texels per pixel: M (res 1) x image pixels / map texels along the axis.
      const double scale = heightPx_ / mapResolution_;
      text += tr("<br>Predicted max m (texels per pixel) at %1 px image height, %2 texels "
                 "per map side: x %3, z %4")
                  .arg(heightPx_, 0, 'f', 0)
                  .arg(mapResolution_, 0, 'f', 0)
                  .arg(formatValue(r.mx * scale), formatValue(r.mz * scale));
      drawn[QStringLiteral("predicted_m_x")] = r.mx * scale;
      drawn[QStringLiteral("predicted_m_z")] = r.mz * scale;
    }
  } else if (!result_) {
    text = tr("Analysing…");
  }
  if (measuredMax_ >= 0.0) {
    text += tr(" &nbsp;|&nbsp; <b>measured m</b> (visible pixels): p95 %1 (±%2 octave), max %3")
                .arg(formatValue(measuredP95_), formatValue(binOctaves_ / 2.0),
                     formatValue(measuredMax_));
    drawn[QStringLiteral("measured_p95")] = measuredP95_;
    drawn[QStringLiteral("measured_max")] = measuredMax_;
  }
  numbers_->setText(text);
  drawn_ = drawn;
}

QWidget* StoragePanel::hemisphereWidget() const {
  return hemisphere_;
}

QPointF StoragePanel::hemispherePoint(double u, double v) const {
  return hemisphere_->pointAt(u, v);
}

QJsonObject StoragePanel::drawnValues() const {
  return drawn_;
}

}  // namespace sl::ui
