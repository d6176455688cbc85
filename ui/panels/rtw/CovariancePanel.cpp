// The Covariance panel (see CovariancePanel.h). The principal axis is computed here, from
// the published top-level moment sums, with the CPU reference (sl::rtw::momentsFromTop);
// the grab test compares it with the e_x, e_y the renderer published.
//
// Ellipse geometry: Σ is in light-frustum metres (the sums' centred IM coordinates scaled
// by the half-extents S = diag(sx, sy)). The ellipse {p : pᵀ Σ⁻¹ p = k²} in IM coordinates
// is q = S⁻¹ p, which is the same as the ellipse of the unscaled Σ, so both scalings draw
// the same curve; the metric principal axis e is drawn as the direction S⁻¹ e.
#include "CovariancePanel.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <QGridLayout>
#include <QJsonArray>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QPushButton>
#include <QVBoxLayout>

#include "algo/rtw/Moments.h"
#include "algo/rtw/TurnPrediction.h"
#include "panels/common/ReadoutGrid.h"
#include "window/Theme.h"

namespace sl::ui {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kMinOneMinusEx = 1e-9;  ///< floor of 1 - e_x on the log scales
constexpr int kMiddleSpacing = 6;        ///< px between the image and its numbers

double numberOr(const std::map<std::string, double>& numbers, const std::string& key,
                double fallback) {
  auto it = numbers.find(key);
  return it == numbers.end() ? fallback : it->second;
}

/// Angle difference folded into (-90, 90] (an axis has no sign).
double axisDifferenceDeg(double a, double b) {
  double d = std::fmod(a - b, 180.0);
  if (d > 90.0) d -= 180.0;
  if (d <= -90.0) d += 180.0;
  return d;
}

/// The hold threshold as the Parameters panel shows it (0.9999, 1.0), not as 1 − threshold.
QString thresholdText(double threshold) {
  QString t = QString::number(threshold, 'f', 7);
  while (t.endsWith(QLatin1Char('0')) && !t.endsWith(QStringLiteral(".0"))) t.chop(1);
  return t;
}
}  // namespace

/// e_x on a log scale of 1 - e_x (0.9 .. 0.99999999), with the threshold marked: right of it
/// the rotation is held. The band of 1 - e_x over the last frames is drawn on the track, so a
/// class sees where the estimate's frame-to-frame noise lies; a click or a drag on the track
/// sets the threshold there (through the Parameters panel's editor: the same checks).
class ThresholdGauge : public QWidget {
 public:
  explicit ThresholdGauge(QWidget* parent = nullptr) : QWidget(parent) {
    setCursor(Qt::SizeHorCursor);
    setToolTip(QObject::tr(
        "Click or drag to set the vibration threshold on this scale of 1 − threshold. The "
        "pale band: 1 − e_x over the last frames. e_x is a 32-bit float, so 1 − e_x is 0 or at "
        "least 6e-8: a threshold closer to 1 than that never holds."));
  }
  void set(double ex, double threshold, bool valid, double bandLo, double bandHi, int bandFrames) {
    ex_ = ex;
    threshold_ = threshold;
    valid_ = valid;
    bandLo_ = bandLo;
    bandHi_ = bandHi;
    bandFrames_ = bandFrames;
    update();
  }
  /// Called with the threshold at a click or drag on the track.
  void setOnChosen(std::function<void(double)> onChosen) { onChosen_ = std::move(onChosen); }
  /// Where the value of 1 - e_x = `oneMinus` sits on the track (widget pixels).
  double xOfOneMinus(double oneMinus) const {
    const QRectF t = track();
    const double l = std::log10(std::max(oneMinus, kMinOneMinusEx));
    return t.left() + std::clamp((l - kL0) / (kL1 - kL0), 0.0, 1.0) * t.width();
  }
  QSize sizeHint() const override { return {260, 3 * fontMetrics().height() + 16}; }
  QSize minimumSizeHint() const override { return {160, 3 * fontMetrics().height() + 16}; }

 protected:
  void mousePressEvent(QMouseEvent* e) override { choose(e); }
  void mouseMoveEvent(QMouseEvent* e) override {
    if (e->buttons() & Qt::LeftButton) choose(e);
  }
  void paintEvent(QPaintEvent*) override {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPalette& pal = palette();
    const int line = fontMetrics().height();
    const QRectF track = this->track();
    auto xOf = [&](double ex) { return xOfOneMinus(1.0 - ex); };
    const double tx = xOf(threshold_);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(214, 128, 40, 170));
    p.drawRect(QRectF(track.left(), track.top(), tx - track.left(), track.height()));
    p.setBrush(QColor(60, 170, 90, 170));
    p.drawRect(QRectF(tx, track.top(), track.right() - tx, track.height()));
    if (bandFrames_ > 1 && bandHi_ >= bandLo_) {  // the last frames' 1 - e_x
      const double x0 = xOfOneMinus(bandHi_), x1 = xOfOneMinus(bandLo_);
      p.setBrush(QColor(255, 255, 255, 70));
      p.drawRect(QRectF(x0 - 1.5, track.top(), x1 - x0 + 3.0, track.height()));
    }
    p.setPen(Qt::white);
    p.drawText(QRectF(track.left() + 4, track.top(), tx - track.left() - 8, track.height()),
               Qt::AlignLeft | Qt::AlignVCenter, tr("rotate"));
    p.drawText(QRectF(tx + 4, track.top(), track.right() - tx - 8, track.height()),
               Qt::AlignRight | Qt::AlignVCenter, tr("hold"));
    p.setPen(pal.color(QPalette::PlaceholderText));
    const int decades = int(std::lround(kL0 - kL1));
    for (int d = 1; d <= decades + 1; ++d) {
      const double x = xOfOneMinus(std::pow(10.0, -d));
      p.drawLine(QPointF(x, track.bottom()), QPointF(x, track.bottom() + 3));
      const Qt::Alignment align =
          d == 1 ? Qt::AlignLeft : (d == decades + 1 ? Qt::AlignRight : Qt::AlignHCenter);
      const double left = d == 1 ? x : (d == decades + 1 ? x - 60 : x - 30);
      p.drawText(QRectF(left, track.bottom() + 3, 60, line), align, QStringLiteral("1e-%1").arg(d));
    }
    p.setPen(QPen(Qt::white, 2));
    p.drawLine(QPointF(tx, track.top() - 3), QPointF(tx, track.bottom() + 3));
    p.setPen(pal.color(QPalette::Text));
    const QString head =
        valid_ ? tr("1 − e_x = %1   (hold when e_x > threshold %2)")
                     .arg(formatValue(std::max(1.0 - ex_, 0.0)), thresholdText(threshold_))
               : tr("no principal axis   (threshold %1)").arg(thresholdText(threshold_));
    p.drawText(QRectF(8, 0, width() - 16, line + 4), Qt::AlignLeft | Qt::AlignVCenter, head);
    if (valid_) {
      const double x = xOf(ex_);
      QPainterPath marker;
      marker.moveTo(x, track.top() + 2);
      marker.lineTo(x - 6, track.top() - 6);
      marker.lineTo(x + 6, track.top() - 6);
      marker.closeSubpath();
      p.setPen(Qt::NoPen);
      p.setBrush(QColor(255, 210, 40));
      p.drawPath(marker);
      p.setPen(QPen(QColor(255, 210, 40), 2.5));
      p.drawLine(QPointF(x, track.top()), QPointF(x, track.bottom()));
    }
  }

 private:
  // log10(1 - e_x) at the left and right ends: 1e-8 is about float's step below 1 (6e-8).
  static constexpr double kL0 = -1.0, kL1 = -8.0;
  QRectF track() const {
    const int line = fontMetrics().height();
    return QRectF(8, line + 6, width() - 16, line + 4);
  }
  /// A click at x (widget pixels) sets 1 - threshold to the scale's value there.
  void choose(QMouseEvent* e) {
    const QRectF t = track();
    const double f =
        std::clamp((e->position().x() - t.left()) / std::max(1.0, t.width()), 0.0, 1.0);
    if (onChosen_) onChosen_(1.0 - std::pow(10.0, kL0 + f * (kL1 - kL0)));
  }
  double ex_ = 1.0, threshold_ = sl::rtw::kDefaultHoldThreshold;
  bool valid_ = false;
  double bandLo_ = 0.0, bandHi_ = 0.0;
  int bandFrames_ = 0;
  std::function<void(double)> onChosen_;
};

QWidget* CovariancePanel::thresholdGauge() const {
  return gauge_;
}

QPoint CovariancePanel::thresholdGaugePoint(double oneMinusThreshold) const {
  return QPoint(int(std::lround(gauge_->xOfOneMinus(oneMinusThreshold))), gauge_->height() / 2);
}

CovariancePanel::CovariancePanel(QWidget* parent) : PublicationPanel(parent) {
  // State and gauge across the top; the IM with the ellipses beside the numbers; the
  // history plots at the bottom.
  auto [content, outer] = newPanelColumn();
  outer->setSpacing(4);
  state_ = new QLabel;
  state_->setObjectName(QStringLiteral("covarianceState"));
  state_->setAlignment(Qt::AlignCenter);
  state_->setMargin(3);
  followBodyFont(state_, 1.0, true);
  outer->addWidget(state_);
  gauge_ = new ThresholdGauge;
  gauge_->setObjectName(QStringLiteral("thresholdGauge"));
  gauge_->setOnChosen([this](double threshold) {
    Q_EMIT parameterChosen(QString::fromLatin1(sl::rtw::kHoldThresholdKey), threshold);
  });
  outer->addWidget(gauge_);
  auto* middle = new QHBoxLayout;
  middle->setSpacing(kMiddleSpacing);
  imageColumn_ = new QVBoxLayout;
  numbersColumn_ = new QVBoxLayout;
  middle->addLayout(imageColumn_, 1);
  middle->addLayout(numbersColumn_);
  view_ = new ImageView;
  view_->setObjectName(QStringLiteral("covarianceView"));
  imageColumn_->addWidget(view_, 1);
  // The numbers, each defined in its tooltip (the same text on its name and its value): in two
  // columns where the panel is wide (arrangeNumbers), the image taking the rest of the width.
  numbers_ = new ReadoutGrid;
  numbers_->setObjectName(QStringLiteral("covarianceNumbers"));
  const struct {
    const char* key;
    const char* name;
    const char* help;
  } rows[] = {
      {"lambda1", "λ1",
       "The larger eigenvalue of the importance's covariance Σ: the variance along the principal "
       "axis (m², or IM units² with pca.metric im-units). Computed here from the published moment "
       "sums of the last frame's importance, the ones that chose this frame's turn."},
      {"lambda2", "λ2", "The smaller eigenvalue of Σ: the variance across the principal axis."},
      {"anisotropy", "anisotropy",
       "(λ1 − λ2) / (λ1 + λ2), as the renderer's gate read it: 0 round, 1 a line. Below "
       "pca.min_anisotropy the importance is too round to turn for."},
      {"spread", "spread",
       "The wider of the half-mass widths of the last frame's two 1D importance maps (share of "
       "the map: the shortest run of texels holding half the importance). Below pca.min_spread "
       "the importance is too concentrated to turn for: the separable warp already gives it "
       "its texels."},
      {"e_x", "e_x",
       "x component of the unit principal axis e the renderer used this frame, in the last "
       "frame's rotated light frame. e_x > threshold: the axis already lies along the map's x "
       "axis and R is held."},
      {"e_y", "e_y", "y component of e (its sign gives the turn's direction)."},
      {"axis_panel", "axis (panel)",
       "atan2(e_y, e_x) of the axis this panel computed from the published moment sums: the "
       "orange line. Equal to the renderer's unless the sums and the renderer disagree."},
      {"axis_renderer", "axis (used)",
       "atan2(e_y, e_x) of the axis the renderer used this frame: the turn it makes when it turns "
       "(R' = [[e_x, −e_y], [e_y, e_x]])."},
      {"turn", "this turn",
       "By how much R turned this frame: the renderer's axis angle when it turned, 0 when it was "
       "held, not turned by a gate, or there was no axis."},
      {"r_total", "R turned",
       "The angle of R, the rotation of the light's image plane from the unrotated light frame, "
       "after this frame's turn: R_k = R' R_k−1, summed over every turn since the last reset "
       "(Ctrl+T)."},
      {"changes", "R changed", "How many frames turned R since the last reset."},
      {"area", "frustum area",
       "The area of the light frustum this frame's map covers, in m² (light.fit: tight re-fits it "
       "in the rotated frame, so it changes with the angle; rotation-invariant keeps it)."},
  };
  for (const auto& r : rows) {
    Row row{new QLabel(tr(r.name)), new QLabel};
    row.value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    row.value->setTextInteractionFlags(Qt::TextSelectableByMouse);
    row.value->setObjectName(QStringLiteral("covariance_%1").arg(QLatin1String(r.key)));
    for (QLabel* l : {row.name, row.value}) l->setToolTip(tr(r.help));
    numbers_->addRow(row.name, row.value);
    rows_[QLatin1String(r.key)] = row;
  }
  numbersColumn_->addWidget(numbers_, 1);
  outer->addLayout(middle, 2);
  // The turn prediction: its curve, the marked angles, the measured sweep on request.
  predictionPlot_ = new PlotWidget;
  predictionPlot_->setObjectName(QStringLiteral("covariancePrediction"));
  predictionPlot_->setTitle(tr("Turn prediction: wrong pixels ÷ now (repeats every 90°)"));
  predictionPlot_->setAxisLabels(tr("turn (°)"), QString());
  predictionPlot_->setXRange(-90.0, 90.0);
  predictionPlot_->setLogY(true);  // ratios: a turn 4x worse and one 4x better alike
  predictionPlot_->setToolTip(
      tr("For every turn of the light's image plane, the warp it would give is predicted from "
         "the last frame's importance map (resampled into the turned frame, collapsed, blurred "
         "and floored as the renderer does): each shadow-edge pixel of the last frame would be "
         "wrong in proportion to the texel's width across its edge. 1 = the current frame. "
         "rotation.mode = predicted turns to the lowest point when it is lower by more than "
         "rotation.margin."));
  // Under the image or under the numbers, whichever is shorter (arrangeNumbers).
  measureRow_ = new QWidget;
  auto* measureRow = new QHBoxLayout(measureRow_);
  measureRow->setContentsMargins(0, 0, 0, 0);
  measureButton_ = new QPushButton(tr("Measure the error at these turns"));
  measureButton_->setSizePolicy(QSizePolicy::Maximum, QSizePolicy::Fixed);
  measureButton_->setObjectName(QStringLiteral("covarianceMeasure"));
  measureButton_->setToolTip(
      tr("Renders this view with the turn fixed at every 15° from −90° to 90° and at the current "
         "angle, one frame each on the render thread, and draws each error against the exact "
         "reference, divided by the current angle's: the truth beside the prediction."));
  connect(measureButton_, &QPushButton::clicked, this, &CovariancePanel::measureTurns);
  measureStatus_ = new QLabel;
  measureStatus_->setObjectName(QStringLiteral("covarianceMeasureStatus"));
  measureStatus_->setWordWrap(true);
  measureRow->addWidget(measureButton_);
  measureRow->addWidget(measureStatus_, 1);
  // The prediction beside the rotation's history, one row: the panel stays as tall as before.
  auto* plots = new QHBoxLayout;
  plots->addWidget(predictionPlot_, 2);
  anglePlot_ = new PlotWidget;
  anglePlot_->setTitle(tr("Rotation of R (°)"));
  anglePlot_->setAxisLabels(tr("frame"), QString());
  exPlot_ = new PlotWidget;
  exPlot_->setTitle(tr("1 − e_x (log)"));
  exPlot_->setAxisLabels(tr("frame"), QString());
  exPlot_->setLogY(true);
  plots->addWidget(anglePlot_, 1);
  plots->addWidget(exPlot_, 1);
  outer->addLayout(plots, 3);
  numbersColumn_->addWidget(measureRow_);
  setContent(content);
}

void CovariancePanel::resizeEvent(QResizeEvent* event) {
  PublicationPanel::resizeEvent(event);
  arrangeNumbers();
}

void CovariancePanel::readableMinimumsChanged() {
  arrangeNumbers();
}

void CovariancePanel::arrangeNumbers() {
  // Two columns of numbers where the image keeps at least its usual width (or its readable
  // one, the larger) beside them: the middle row half as tall, for the plots below it.
  const int image = std::max(view_->sizeHint().width(), view_->minimumSizeHint().width());
  numbers_->fitColumns(width() - 2 * kPanelColumnMargin - image - kMiddleSpacing);
  // The measure button under the shorter of the two (at their least), in the room the taller
  // one leaves beside it: a wide image is short, two columns of numbers are.
  QVBoxLayout* under = view_->minimumSizeHint().height() < numbers_->minimumSizeHint().height()
                           ? imageColumn_
                           : numbersColumn_;
  if (under->indexOf(measureRow_) >= 0) return;
  (under == imageColumn_ ? numbersColumn_ : imageColumn_)->removeWidget(measureRow_);
  under->addWidget(measureRow_);
}

void CovariancePanel::resetHistory() {
  history_.clear();
  updateHistoryPlots();
  measured_ = {};
  measureStatus_->clear();
  updatePredictionPlot();
}

void CovariancePanel::showPublication(const sl::Publication& pub) {
  const auto& n = pub.numbers;
  auto imIt = pub.images.find("importance");
  const sl::FloatImage* im =
      imIt != pub.images.end() && imIt->second.width > 0 ? &imIt->second : nullptr;
  // The six sums: published numbers, else the chain's 1x1 level, else the IM on the CPU.
  sl::rtw::MomentTexel sums{};
  QString source;
  bool haveSums = true;
  for (int c = 0; c < sl::rtw::kMomCount; ++c) {
    static const char* keys[] = {"I", "xI", "yI", "xxI", "yyI", "xyI"};
    auto it = n.find(std::string("moment.") + keys[c]);
    if (it == n.end()) {
      haveSums = false;
      break;
    }
    sums[c] = static_cast<float>(it->second);
  }
  if (haveSums) {
    source = QStringLiteral("published moment sums");
  } else if (im) {
    sl::rtw::ImportanceMap map(im->width, im->height);
    for (int y = 0; y < im->height; ++y)
      for (int x = 0; x < im->width; ++x)
        map.at(x, y) = im->values[(size_t(y) * im->width + x) * im->channels];
    sums = sl::rtw::buildMomentChain(map).back().texels[0];
    source = QStringLiteral("importance map (CPU)");
  } else {
    drawn_ = {};
    showContent(false, noDataText(QString::fromStdString(pub.techniqueId),
                                  tr("importance map or moments"), observedKeys()));
    return;
  }
  showContent(true);
  // The scale the renderer's PCA used (pca.scale.*: the half extents of the frustum the
  // moments were taken in, or 1 in IM units); without it, this frame's half extents.
  const double sx = numberOr(n, "pca.scale.x", 0.5 * numberOr(n, "light.extent.x", 2.0)),
               sy = numberOr(n, "pca.scale.y", 0.5 * numberOr(n, "light.extent.y", 2.0));
  const bool metres = !(n.count("pca.scale.x") && sx == 1.0 && sy == 1.0);
  const sl::rtw::MomentStats s =
      sl::rtw::momentsFromTop(sums, glm::vec2(static_cast<float>(sx), static_cast<float>(sy)));
  threshold_ = numberOr(n, sl::rtw::kHoldThresholdKey, threshold_);

  // The axis in metres and as drawn on the IM's texel grid.
  const double axisDeg = std::atan2(s.ey, s.ex) * 180.0 / kPi;
  const double ix = s.ex / std::max(sx, 1e-12), iy = s.ey / std::max(sy, 1e-12);
  const double imageDeg = std::atan2(iy, ix) * 180.0 / kPi;
  const bool havePublished = n.count("e_x") && n.count("e_y");
  const double pubEx = numberOr(n, "e_x", 1.0), pubEy = numberOr(n, "e_y", 0.0);
  const double publishedDeg = std::atan2(pubEy, pubEx) * 180.0 / kPi;
  const bool held = numberOr(n, "rotation.held", 0.0) != 0.0;
  const bool pcaValid = n.count("pca.valid") ? n.at("pca.valid") != 0.0 : s.valid;
  drawn_ = {{QStringLiteral("frame"), double(pub.frameIndex)},
            {QStringLiteral("source"), source},
            {QStringLiteral("valid"), s.valid},
            {QStringLiteral("axis_deg"), axisDeg},
            {QStringLiteral("axis_image_deg"), imageDeg},
            {QStringLiteral("e_x"), s.ex},
            {QStringLiteral("e_y"), s.ey},
            {QStringLiteral("eigen.1"), s.lambda1},
            {QStringLiteral("eigen.2"), s.lambda2},
            {QStringLiteral("mean.x"), s.meanX},
            {QStringLiteral("mean.y"), s.meanY},
            {QStringLiteral("threshold_shown"), thresholdText(threshold_)}};
  if (havePublished)
    drawn_[QStringLiteral("axis_minus_published_deg")] = axisDifferenceDeg(axisDeg, publishedDeg);

  // Image with the ellipses.
  if (im) {
    const ValueRange range = finiteRange(im->values, im->channels);
    view_->setImage(colorize(*im, 0, {0.0f, std::max(range.hi, 1e-30f), false}, ColorMap::Viridis),
                    im->width, im->height);
    view_->setLegend({0.0f, std::max(range.hi, 1e-30f), false}, ColorMap::Viridis,
                     tr("importance"));
    const sl::FloatImage copy = *im;
    view_->setValueReader([copy](int x, int y) {
      return QStringLiteral("I = %1").arg(
          formatValue(copy.values[(size_t(y) * copy.width + x) * copy.channels]));
    });
  } else {
    view_->clearImage(tr("No importance image published; the numbers come from the sums."));
  }
  const bool valid = s.valid;
  view_->setOverlay([s, sx, sy, valid](QPainter& p, const QRectF& r) {
    auto toWidget = [&r](double x, double y) {  // centred IM coordinates -> widget
      return QPointF(r.left() + (x + 1.0) * 0.5 * r.width(),
                     r.bottom() - (y + 1.0) * 0.5 * r.height());
    };
    const double mx = s.meanX, my = s.meanY;
    const double l1 = std::sqrt(std::max(0.0f, s.lambda1)),
                 l2 = std::sqrt(std::max(0.0f, s.lambda2));
    const double e1x = s.ex, e1y = s.ey, e2x = -s.ey, e2y = s.ex;
    for (int k = 1; k <= 2; ++k) {
      QPainterPath path;
      for (int i = 0; i <= 96; ++i) {
        const double t = 2.0 * kPi * i / 96;
        const double px = k * (l1 * std::cos(t) * e1x + l2 * std::sin(t) * e2x);
        const double py = k * (l1 * std::cos(t) * e1y + l2 * std::sin(t) * e2y);
        const QPointF q = toWidget(mx + px / sx, my + py / sy);
        if (i == 0)
          path.moveTo(q);
        else
          path.lineTo(q);
      }
      p.setPen(QPen(QColor(255, 255, 255, k == 1 ? 240 : 170), k == 1 ? 2.0 : 1.4,
                    k == 1 ? Qt::SolidLine : Qt::DashLine));
      p.setBrush(Qt::NoBrush);
      p.drawPath(path);
    }
    p.setPen(QPen(QColor(255, 160, 40), 2.4));
    if (valid) {
      const double len = 2.6 * l1;  // principal axis, past the 2σ ellipse
      p.drawLine(toWidget(mx - len * e1x / sx, my - len * e1y / sy),
                 toWidget(mx + len * e1x / sx, my + len * e1y / sy));
      p.setPen(QPen(QColor(120, 200, 255), 1.6, Qt::DashLine));
      const double len2 = 2.6 * l2;
      p.drawLine(toWidget(mx - len2 * e2x / sx, my - len2 * e2y / sy),
                 toWidget(mx + len2 * e2x / sx, my + len2 * e2y / sy));
    }
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(255, 160, 40));
    p.drawEllipse(toWidget(mx, my), 3.5, 3.5);
  });
  // In metres the map is drawn at the frustum's shape, so the ellipse and the axis look as
  // they lie in the world (and as λ1, λ2 and the angle say); in IM units as the square IM.
  view_->setDisplayAspect(metres ? sx / std::max(sy, 1e-12) : 0.0);
  view_->setCaption(
      metres ? tr("1σ, 2σ, axis; %1 × %2 m").arg(2.0 * sx, 0, 'f', 1).arg(2.0 * sy, 0, 'f', 1)
             : tr("1σ, 2σ, axis; IM units"));
  view_->setToolTip(
      tr("Computed from the %1: the moments' mean and covariance (Tokuyoshi et al. 2014)")
          .arg(source));

  // State, gauge and numbers. The state names what the renderer did with R this frame and,
  // when it left R as it was, which rule stopped it.
  QString stateText, stateKey;
  QColor stateColor;
  const double stepDeg = numberOr(n, "rotation.step_deg", 0.0);
  const int mode = int(numberOr(n, "rotation.mode", 0.0));  // pca | predicted | fixed
  const double rDeg = numberOr(n, "rotation.deg", 0.0);
  const QString angle = QStringLiteral("%1°").arg(rDeg, 0, 'f', 1);
  if (!n.count("rotation.held")) {
    stateKey = QStringLiteral("none");
    stateText = tr("no rotation published (not DA-RTW)");
    stateColor = QColor(90, 94, 100);
  } else if (mode == 2) {
    stateKey = QStringLiteral("fixed");
    stateText = tr("FIXED at %1 (rotation.fixed_deg)").arg(angle);
    stateColor = QColor(90, 94, 100);
  } else if (mode == 1) {
    using sl::rtw::TurnReason;
    const auto reason = n.count("prediction.reason")
                            ? TurnReason(int(numberOr(n, "prediction.reason", 0.0)))
                            : TurnReason::NoPrediction;
    const double gainPct = 100.0 * numberOr(n, "prediction.gain", 0.0);
    const double bestDeg = numberOr(n, "prediction.best_deg", 0.0);
    const double marginPct = 100.0 * numberOr(n, "prediction.margin", 0.0);
    switch (reason) {
      case TurnReason::Turned:
        stateKey = QStringLiteral("turned");
        stateText = tr("TURNED to %1: predicted %2 % fewer wrong pixels than at %3°")
                        .arg(angle)
                        .arg(gainPct, 0, 'f', 0)
                        .arg(numberOr(n, "prediction.current_deg", 0.0), 0, 'f', 1);
        stateColor = QColor(200, 110, 30);
        break;
      case TurnReason::WithinMargin:
        stateKey = QStringLiteral("held_margin");
        stateText = tr("HELD at %1: the best turn, %2°, is predicted only %3 % better "
                       "(margin %4 %)")
                        .arg(angle)
                        .arg(bestDeg, 0, 'f', 1)
                        .arg(gainPct, 0, 'f', 0)
                        .arg(marginPct, 0, 'f', 0);
        stateColor = QColor(60, 150, 80);
        break;
      case TurnReason::CurrentIsBest:
        stateKey = QStringLiteral("held_best");
        stateText = tr("HELD at %1: no turn is predicted better").arg(angle);
        stateColor = QColor(60, 150, 80);
        break;
      case TurnReason::WithinVibration:
        stateKey = QStringLiteral("held_vibration");
        stateText = tr("HELD at %1: the best turn, %2°, is within the vibration threshold")
                        .arg(angle)
                        .arg(bestDeg, 0, 'f', 1);
        stateColor = QColor(60, 150, 80);
        break;
      case TurnReason::ViewMoved:
        stateKey = QStringLiteral("view_moved");
        stateText = tr("HELD at %1: the view moved since the last frame (its importance lies "
                       "outside this frame)")
                        .arg(angle);
        stateColor = QColor(128, 131, 136);
        break;
      case TurnReason::NoPrediction:
        stateKey = QStringLiteral("no_prediction");
        stateText =
            n.count("prediction.weight") && numberOr(n, "prediction.weight", 0.0) == 0.0
                ? tr("NO PREDICTION — no shadow edge in the last frame: R kept at %1").arg(angle)
                : tr("NO PREDICTION yet (no last frame): R kept at %1").arg(angle);
        stateColor = QColor(128, 131, 136);
        break;
    }
  } else if (!pcaValid) {
    stateKey = QStringLiteral("no_axis");
    stateText = tr("NO AXIS — isotropic or empty importance: R kept");
    stateColor = QColor(128, 131, 136);
  } else if (numberOr(n, "rotation.too_round", 0.0) != 0.0) {
    stateKey = QStringLiteral("too_round");
    stateText = tr("NOT TURNED — too round: anisotropy %1 < %2")
                    .arg(numberOr(n, "pca.anisotropy", 0.0), 0, 'f', 3)
                    .arg(numberOr(n, "pca.min_anisotropy", 0.0), 0, 'f', 2);
    stateColor = QColor(110, 110, 150);
  } else if (numberOr(n, "rotation.too_concentrated", 0.0) != 0.0) {
    stateKey = QStringLiteral("too_concentrated");
    stateText = tr("NOT TURNED — too concentrated: spread %1 < %2")
                    .arg(numberOr(n, "pca.spread", 0.0), 0, 'f', 3)
                    .arg(numberOr(n, "pca.min_spread", 0.0), 0, 'f', 2);
    stateColor = QColor(110, 110, 150);
  } else if (held) {
    stateKey = QStringLiteral("held");
    stateText = tr("HELD — e_x > threshold: R_k = R_k−1");
    stateColor = QColor(60, 150, 80);
  } else if (stepDeg != 0.0) {
    stateKey = QStringLiteral("turned");
    stateText = tr("TURNED by %1° this frame").arg(stepDeg, 0, 'f', 3);
    stateColor = QColor(200, 110, 30);
  } else {
    stateKey = QStringLiteral("unchanged");
    stateText = tr("UNCHANGED — the axis is exactly x (e_y = 0)");
    stateColor = QColor(90, 94, 100);
  }
  drawn_[QStringLiteral("mode")] = mode;
  drawn_[QStringLiteral("state_text")] = stateText;
  drawn_[QStringLiteral("state")] = stateKey;
  drawn_[QStringLiteral("step_deg")] = stepDeg;
  drawn_[QStringLiteral("published_axis_deg")] = havePublished ? publishedDeg : axisDeg;
  state_->setText(stateText);
  state_->setStyleSheet(
      QStringLiteral("background:%1;color:white;border-radius:4px;").arg(stateColor.name()));
  const double ex = havePublished ? pubEx : s.ex;

  const QString unit2 = metres ? QStringLiteral(" m²") : QStringLiteral(" (IM units)²");
  const double anisotropy = numberOr(n, "pca.anisotropy", s.anisotropy);
  setRow(QStringLiteral("lambda1"), formatValue(s.lambda1) + unit2);
  setRow(QStringLiteral("lambda2"), formatValue(s.lambda2) + unit2);
  setRow(QStringLiteral("anisotropy"), QString::number(anisotropy, 'f', 3));
  setRow(QStringLiteral("spread"), n.count("pca.spread")
                                       ? QString::number(numberOr(n, "pca.spread", 0.0), 'f', 3)
                                       : QString());
  setRow(QStringLiteral("e_x"), QString::number(ex, 'f', 7));
  setRow(QStringLiteral("e_y"), QString::number(havePublished ? pubEy : s.ey, 'f', 7));
  setRow(QStringLiteral("axis_panel"), QStringLiteral("%1°").arg(axisDeg, 0, 'f', 3));
  setRow(QStringLiteral("axis_renderer"),
         havePublished ? QStringLiteral("%1°").arg(publishedDeg, 0, 'f', 3) : QString());
  setRow(QStringLiteral("turn"),
         n.count("rotation.step_deg") ? QStringLiteral("%1°").arg(stepDeg, 0, 'f', 3) : QString());
  setRow(QStringLiteral("r_total"),
         n.count("rotation.deg")
             ? QStringLiteral("%1°").arg(numberOr(n, "rotation.deg", 0.0), 0, 'f', 3)
             : QString());
  setRow(QStringLiteral("changes"), n.count("rotation.changes")
                                        ? tr("%1×").arg(numberOr(n, "rotation.changes", 0.0))
                                        : QString());
  setRow(QStringLiteral("area"),
         n.count("light.area") ? formatValue(numberOr(n, "light.area", 0.0)) + QStringLiteral(" m²")
                               : QString());
  arrangeNumbers();  // once the rows are set: a wider value may need one column again

  // History.
  // A frame shown again (e.g. while paused) replaces its sample; an older one (a new
  // renderer) starts a new history.
  if (!history_.empty() && pub.frameIndex < history_.back().frame) history_.clear();
  if (!history_.empty() && pub.frameIndex == history_.back().frame) history_.pop_back();
  history_.push_back({pub.frameIndex, numberOr(n, "rotation.deg", axisDeg), ex, held});
  while (history_.size() > kHistoryFrames) history_.pop_front();
  double lo = history_.front().angleDeg, hi = lo;
  for (const Sample& h : history_) lo = std::min(lo, h.angleDeg), hi = std::max(hi, h.angleDeg);
  // The gauge's band: 1 - e_x over the last kGaugeBandFrames frames (the estimate's noise).
  double bandLo = 1.0, bandHi = 0.0;
  int bandFrames = 0;
  for (auto it = history_.rbegin(); it != history_.rend() && bandFrames < kGaugeBandFrames; ++it)
    if (std::isfinite(it->ex)) {
      bandLo = std::min(bandLo, 1.0 - it->ex);
      bandHi = std::max(bandHi, 1.0 - it->ex);
      ++bandFrames;
    }
  gauge_->set(ex, threshold_, pcaValid, bandLo, bandHi, bandFrames);
  drawn_[QStringLiteral("gauge.band_frames")] = bandFrames;
  drawn_[QStringLiteral("gauge.band_lo")] = bandLo;
  drawn_[QStringLiteral("gauge.band_hi")] = bandHi;
  drawn_[QStringLiteral("history.frames")] = int(history_.size());
  drawn_[QStringLiteral("history.angle_min_deg")] = lo;
  drawn_[QStringLiteral("history.angle_max_deg")] = hi;
  updateHistoryPlots();

  // The turn prediction of this frame.
  prediction_ = {};
  prediction_.frame = pub.frameIndex;
  prediction_.valid = numberOr(n, "prediction.valid", 0.0) != 0.0;
  prediction_.current = numberOr(n, "prediction.score.current", 0.0);
  prediction_.currentDeg = numberOr(n, "prediction.current_deg", rDeg);
  prediction_.chosenDeg = rDeg;
  if (n.count("pca.axis_deg")) prediction_.pcaDeg = numberOr(n, "pca.axis_deg", 0.0);
  if (auto c = pub.curves.find("prediction.curve"); c != pub.curves.end())
    prediction_.curve.assign(c->second.begin(), c->second.end());
  measureButton_->setEnabled(n.count("rotation.mode") > 0);
  updatePredictionPlot();
}

namespace {
/// Every angle in [-90, 90] equivalent to `deg` under the quarter-turn symmetry.
std::vector<double> quarterTurnCopies(double deg) {
  std::vector<double> out;
  const double f = sl::rtw::foldQuarterTurn(deg);
  for (double a : {f - 90.0, f, f + 90.0})
    if (a >= -90.0 - 1e-9 && a <= 90.0 + 1e-9) out.push_back(a);
  return out;
}
}  // namespace

void CovariancePanel::updatePredictionPlot() {
  std::vector<PlotWidget::Series> series;
  std::vector<PlotWidget::Marker> markers;
  const Prediction& p = prediction_;
  QJsonArray ratios;
  if (p.valid && p.current > 0.0 && !p.curve.empty()) {
    PlotWidget::Series curve{tr("predicted"), {}, QColor(255, 210, 40)};
    curve.width = 2.0;
    for (std::size_t i = 0; i < p.curve.size(); ++i) {
      const double a = -90.0 + sl::rtw::kTurnCurveStepDeg * double(i);
      const double ratio = p.curve[i] > 0.0 ? p.curve[i] / p.current : std::nan("");
      curve.points.emplace_back(a, ratio);
      ratios.append(ratio);
    }
    series.push_back(std::move(curve));
  }
  // Measured: each angle's error over the current angle's (the sweep's last variant).
  const Measured& m = measured_;
  const double base = m.errorPct.empty() ? std::nan("") : m.errorPct.back();
  QJsonArray measuredRatios;
  if (m.done > 0 && std::isfinite(base) && base > 0.0) {
    PlotWidget::Series truth{tr("measured"), {}, QColor(120, 200, 255), Qt::DashLine};
    truth.dots = true;
    for (std::size_t i = 0; i + 1 < m.anglesDeg.size(); ++i) {
      const double r = m.errorPct[i] / base;
      truth.points.emplace_back(m.anglesDeg[i], r);
      measuredRatios.append(std::isfinite(r) ? QJsonValue(r) : QJsonValue());
    }
    series.push_back(std::move(truth));
  }
  auto mark = [&markers](double deg, const QColor& c, const QString& label, Qt::PenStyle style) {
    bool first = true;
    for (double a : quarterTurnCopies(deg)) {
      markers.push_back({a, c, first ? label : QString(), style});
      first = false;
    }
  };
  if (p.valid || !p.curve.empty()) {
    if (p.pcaDeg) mark(*p.pcaDeg, QColor(255, 160, 40), tr("PCA axis"), Qt::DashLine);
    mark(p.currentDeg, QColor(230, 230, 230), tr("was"), Qt::DotLine);
    mark(p.chosenDeg, QColor(90, 200, 110), tr("now"), Qt::SolidLine);
  }
  predictionPlot_->setSeries(std::move(series));
  predictionPlot_->setMarkers(std::move(markers));
  predictionPlot_->setLines({{1.0, QColor(200, 200, 200), QString()}});
  predictionPlot_->setPlaceholder(
      p.valid ? tr("Open this panel on DA-RTW for the predicted curve.")
              : tr("No prediction in this frame (DA-RTW predicts from the last frame's "
                   "importance and shadow edges)."));
  drawn_[QStringLiteral("prediction.frame")] = double(p.frame);
  drawn_[QStringLiteral("prediction.valid")] = p.valid;
  drawn_[QStringLiteral("prediction.ratios")] = ratios;
  drawn_[QStringLiteral("prediction.chosen_deg")] = p.chosenDeg;
  drawn_[QStringLiteral("prediction.markers")] = int(predictionPlot_->markers().size());
  drawn_[QStringLiteral("measured.frame")] = double(m.frame);
  drawn_[QStringLiteral("measured.done")] = m.done;
  drawn_[QStringLiteral("measured.total")] = int(m.anglesDeg.size());
  drawn_[QStringLiteral("measured.ratios")] = measuredRatios;
}

void CovariancePanel::measureTurns() {
  measured_ = {};
  measured_.frame = prediction_.frame;
  // The current angle last: the sweep's errors are drawn relative to it.
  measured_.currentDeg = prediction_.chosenDeg;
  for (double a = -90.0; a <= 90.0 + 1e-9; a += kMeasureStepDeg) measured_.anglesDeg.push_back(a);
  double current = std::fmod(prediction_.chosenDeg, 180.0);
  if (current > 90.0) current -= 180.0;
  if (current < -90.0) current += 180.0;
  measured_.anglesDeg.push_back(current);
  measured_.errorPct.assign(measured_.anglesDeg.size(), std::nan(""));
  QList<QStringList> variants;
  for (double a : measured_.anglesDeg)
    variants.push_back({QStringLiteral("rotation.mode=fixed"),
                        QStringLiteral("rotation.fixed_deg=%1").arg(a, 0, 'g', 10)});
  measureStatus_->setText(
      tr("Measuring %1 turns of frame %2's view…").arg(variants.size()).arg(measured_.frame));
  updatePredictionPlot();
  Q_EMIT variantErrorsRequested(QStringLiteral("turns"), variants);
}

void CovariancePanel::showVariantError(const QString& tag, int index, double errorPct,
                                       std::uint64_t frame, const QString& problem) {
  if (tag != QLatin1String("turns") || index < 0 || index >= int(measured_.errorPct.size())) return;
  measured_.errorPct[std::size_t(index)] = errorPct;
  measured_.done = index + 1;
  measured_.frame = frame;
  if (!problem.isEmpty()) measured_.problem = problem;
  const int total = int(measured_.anglesDeg.size());
  QString text =
      measured_.done < total
          ? tr("Measured %1 of %2 turns of frame %3's view…")
                .arg(measured_.done)
                .arg(total)
                .arg(frame)
          : tr("Measured: the error of frame %1's view at every turn ÷ its error at %2° (%3 %).")
                .arg(frame)
                .arg(measured_.anglesDeg.back(), 0, 'f', 1)
                .arg(measured_.errorPct.back(), 0, 'f', 3);
  if (!measured_.problem.isEmpty()) text += QStringLiteral(" ") + measured_.problem;
  measureStatus_->setText(text);
  updatePredictionPlot();
}

void CovariancePanel::setRow(const QString& key, const QString& value) {
  const auto it = rows_.find(key);
  if (it == rows_.end()) return;
  it->second.value->setText(value);
  it->second.name->setVisible(!value.isEmpty());
  it->second.value->setVisible(!value.isEmpty());
  drawn_[QStringLiteral("shown.") + key] = value;
}

void CovariancePanel::updateHistoryPlots() {
  PlotWidget::Series angle{tr("angle"), {}, QColor(255, 160, 40)};
  PlotWidget::Series oneMinus{tr("1 − e_x"), {}, QColor(255, 210, 40)};
  for (const Sample& s : history_) {
    angle.points.emplace_back(double(s.frame), s.angleDeg);
    oneMinus.points.emplace_back(double(s.frame), std::max(1.0 - s.ex, kMinOneMinusEx));
  }
  anglePlot_->setSeries({angle});
  exPlot_->setSeries({oneMinus});
  exPlot_->setLines({{1.0 - threshold_, QColor(255, 255, 255), tr("threshold (hold below)")}});
  anglePlot_->setPlaceholder(tr("No frames yet."));
  exPlot_->setPlaceholder(tr("No frames yet."));
}

void CovariancePanel::highlightPass(const QString& passId) {
  const bool on = passId == QLatin1String("rotation estimate");
  view_->setHighlighted(on);
  exPlot_->setHighlighted(on);
}

QStringList CovariancePanel::readoutProblems(const QJsonObject& drawn, const sl::Publication& pub) {
  QStringList out;
  const auto& n = pub.numbers;
  auto num = [&n](const char* key) { return numberOr(n, key, std::nan("")); };
  auto shown = [&drawn](const char* key) {
    return drawn.value(QStringLiteral("shown.") + QLatin1String(key)).toString();
  };
  auto expect = [&out](bool ok, const QString& what) {
    if (!ok) out << what;
  };
  const double frame = drawn.value(QStringLiteral("frame")).toDouble(-1);
  expect(frame == double(pub.frameIndex),
         QStringLiteral("shows frame %1, published %2").arg(frame).arg(pub.frameIndex));
  const QString rTotal = QStringLiteral("%1°").arg(num("rotation.deg"), 0, 'f', 3);
  expect(shown("r_total") == rTotal,
         QStringLiteral("R turned %1, published %2").arg(shown("r_total"), rTotal));
  const QString turn = QStringLiteral("%1°").arg(num("rotation.step_deg"), 0, 'f', 3);
  expect(shown("turn") == turn,
         QStringLiteral("turn this frame %1, published %2").arg(shown("turn"), turn));
  const QString ex = QString::number(num("e_x"), 'f', 7);
  expect(shown("e_x") == ex, QStringLiteral("e_x %1, published %2").arg(shown("e_x"), ex));
  const double axisDiff =
      drawn.value(QStringLiteral("axis_minus_published_deg")).toDouble(std::nan(""));
  expect(std::abs(axisDiff) < 0.05,
         QStringLiteral("the axis drawn is %1° from the renderer's").arg(axisDiff));
  const double eig = drawn.value(QStringLiteral("eigen.1")).toDouble(std::nan(""));
  expect(std::abs(eig - num("eigen.1")) <= 1e-3 * std::abs(eig),
         QStringLiteral("λ1 %1, published %2").arg(eig).arg(num("eigen.1")));
  // The state names what the renderer did: its flags, and the turn it made.
  const QString state = drawn.value(QStringLiteral("state")).toString();
  const int mode = int(num("rotation.mode"));
  static const char* reasons[] = {"no_prediction", "turned",         "held_margin",
                                  "held_best",     "held_vibration", "view_moved"};
  const int reason = std::isfinite(num("prediction.reason")) ? int(num("prediction.reason")) : 0;
  if (mode == 1 || mode == 2) {
    const QString want =
        mode == 2 ? QStringLiteral("fixed") : QLatin1String(reasons[std::clamp(reason, 0, 5)]);
    expect(state == want, QStringLiteral("state %1, the renderer's %2").arg(state, want));
    return out;
  }
  const QString expected = num("pca.valid") == 0            ? QStringLiteral("no_axis")
                           : num("rotation.too_round") != 0 ? QStringLiteral("too_round")
                           : num("rotation.too_concentrated") != 0
                               ? QStringLiteral("too_concentrated")
                           : num("rotation.held") != 0     ? QStringLiteral("held")
                           : num("rotation.step_deg") != 0 ? QStringLiteral("turned")
                                                           : QStringLiteral("unchanged");
  expect(state == expected, QStringLiteral("state %1, the renderer's %2").arg(state, expected));
  const double axis = drawn.value(QStringLiteral("published_axis_deg")).toDouble();
  expect(state != QLatin1String("turned") || std::abs(num("rotation.step_deg") - axis) < 1e-3,
         QStringLiteral("turned %1° along an axis at %2°").arg(num("rotation.step_deg")).arg(axis));
  return out;
}

QJsonObject CovariancePanel::drawnValues() const {
  return drawn_;
}

}  // namespace sl::ui
