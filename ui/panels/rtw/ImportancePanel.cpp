// The Importance map panel (see ImportancePanel.h). In the 1D modes the image shows the
// separable density Ix(x) * Iy(y) that a rectilinear warp can give (normalised to 1), with
// the two 1D maps drawn along the bottom and left edges: where it differs from the raw IM,
// the separable warp cannot follow the importance (the diagonal case of DA-RTW).
#include "ImportancePanel.h"

#include <algorithm>
#include <cmath>

#include <QButtonGroup>
#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPainterPath>
#include <QRadioButton>
#include <QVBoxLayout>

namespace sl::ui {

namespace {
constexpr float kLogDecades = 4.0f;  ///< log scale shows max * 1e-4 .. max

float maxOf(const std::vector<float>& v) {
  float m = 0.0f;
  for (float x : v)
    if (std::isfinite(x)) m = std::max(m, x);
  return m;
}

/// Entry of a 1D map of n texels for texel i of an axis of `size` texels.
float curveAt(const std::vector<float>& curve, int i, int size) {
  if (curve.empty() || size <= 0) return 0.0f;
  const auto n = static_cast<long long>(curve.size());
  const long long k = std::clamp<long long>(static_cast<long long>(i) * n / size, 0, n - 1);
  return curve[static_cast<std::size_t>(k)];
}
}  // namespace

ImportancePanel::ImportancePanel(QWidget* parent) : PublicationPanel(parent) {
  auto [content, layout] = newPanelColumn();
  layout->setSpacing(4);
  auto* bar = new QHBoxLayout;
  modes_ = new QButtonGroup(this);
  const QString names[] = {tr("Raw IM"), tr("Collapsed 1D"), tr("Blurred 1D")};
  const QString tips[] = {
      tr("The importance map as rendered (light space, before collapse)"),
      tr("Max over each column (x map) and row (y map), and the separable density they give"),
      tr("The 1D maps after the Gaussian blur and the importance floor (what the warp uses)")};
  for (int i = 0; i < 3; ++i) {
    auto* b = new QRadioButton(names[i]);
    b->setToolTip(tips[i]);
    b->setObjectName(QStringLiteral("importanceMode%1").arg(i));
    modes_->addButton(b, i);
    bar->addWidget(b);
  }
  modes_->button(0)->setChecked(true);
  connect(modes_, &QButtonGroup::idClicked, this, [this](int id) {
    mode_ = static_cast<Mode>(id);
    rebuild();
  });
  bar->addStretch(1);
  log_ = new QCheckBox(tr("log scale"));
  log_->setToolTip(tr("Colour by log10 of the importance (4 decades below the maximum)"));
  connect(log_, &QCheckBox::toggled, this, [this] { rebuild(); });
  bar->addWidget(log_);
  layout->addLayout(bar);
  view_ = new ImageView;
  view_->setObjectName(QStringLiteral("importanceView"));
  layout->addWidget(view_, 1);
  info_ = new QLabel;
  info_->setWordWrap(true);
  info_->setForegroundRole(QPalette::PlaceholderText);
  layout->addWidget(info_);
  setContent(content);
}

void ImportancePanel::setMode(Mode mode) {
  mode_ = mode;
  modes_->button(static_cast<int>(mode))->setChecked(true);
  rebuild();
}

void ImportancePanel::showPublication(const sl::Publication& pub) {
  auto it = pub.images.find("importance");
  if (it == pub.images.end() || it->second.width <= 0) {
    im_ = {};
    showContent(false, noDataText(QString::fromStdString(pub.techniqueId), tr("importance map"),
                                  observedKeys()));
    return;
  }
  im_ = it->second;
  frame_ = pub.frameIndex;
  auto curve = [&pub](const char* key) {
    auto c = pub.curves.find(key);
    return c == pub.curves.end() ? std::vector<float>{} : c->second;
  };
  x_ = curve("importance.x");
  y_ = curve("importance.y");
  xBlurred_ = curve("importance.x.blurred");
  yBlurred_ = curve("importance.y.blurred");
  max_ = maxOf(im_.values);
  showContent(true);
  rebuild();
}

void ImportancePanel::rebuild() {
  if (im_.width <= 0) return;
  const bool log = log_->isChecked();
  const int w = im_.width, h = im_.height;
  const bool blurred = mode_ == Mode::Blurred;
  const std::vector<float>& cx = blurred ? xBlurred_ : x_;
  const std::vector<float>& cy = blurred ? yBlurred_ : y_;
  const bool oneD = mode_ != Mode::Raw;
  const bool haveCurves = !cx.empty() && !cy.empty();

  ValueRange range{0.0f, std::max(max_, 1e-30f), false};
  QImage image;
  float mx = 0.0f, my = 0.0f;
  if (oneD && haveCurves) {
    mx = std::max(maxOf(cx), 1e-30f);
    my = std::max(maxOf(cy), 1e-30f);
    range = {0.0f, 1.0f, false};
    if (log) range = {std::pow(10.0f, -kLogDecades), 1.0f, true};
    image = QImage(w, h, QImage::Format_RGB32);
    for (int y = 0; y < h; ++y) {
      auto* line = reinterpret_cast<QRgb*>(image.scanLine(h - 1 - y));
      const float fy = curveAt(cy, y, h) / my;
      for (int x = 0; x < w; ++x)
        line[x] = mapColor(ColorMap::Viridis, range.normalize(curveAt(cx, x, w) / mx * fy));
    }
  } else {
    if (log) range = {range.hi * std::pow(10.0f, -kLogDecades), range.hi, true};
    image = colorize(im_, 0, range, ColorMap::Viridis);
  }
  view_->setImage(image, w, h);
  view_->setLegend(range, ColorMap::Viridis, oneD ? tr("Ix·Iy / max") : tr("importance"));

  if (oneD && haveCurves) {
    // The 1D maps as filled profiles along the bottom (x) and left (y) edges.
    view_->setOverlay([cx, cy, mx, my](QPainter& p, const QRectF& r) {
      const double band = 0.22;
      QPainterPath px, py;
      const int nx = static_cast<int>(cx.size()), ny = static_cast<int>(cy.size());
      px.moveTo(r.left(), r.bottom());
      for (int i = 0; i < nx; ++i) {
        const double y = r.bottom() - band * r.height() * cx[i] / mx;
        px.lineTo(r.left() + r.width() * i / nx, y);
        px.lineTo(r.left() + r.width() * (i + 1) / nx, y);
      }
      px.lineTo(r.right(), r.bottom());
      py.moveTo(r.left(), r.bottom());
      for (int j = 0; j < ny; ++j) {
        const double x = r.left() + band * r.width() * cy[j] / my;
        py.lineTo(x, r.bottom() - r.height() * j / ny);
        py.lineTo(x, r.bottom() - r.height() * (j + 1) / ny);
      }
      py.lineTo(r.left(), r.top());
      for (const QPainterPath* path : {&px, &py}) {
        p.setPen(QPen(QColor(255, 255, 255, 230), 1.2));
        p.setBrush(QColor(255, 255, 255, 70));
        p.drawPath(*path);
      }
      p.setPen(Qt::white);
      p.drawText(QRectF(r.left() + 4, r.bottom() - 18, 60, 16), Qt::AlignLeft, QStringLiteral("x"));
      p.drawText(QRectF(r.left() + 4, r.top() + 2, 60, 16), Qt::AlignLeft, QStringLiteral("y"));
    });
  } else {
    view_->setOverlay({});
  }

  const sl::FloatImage im = im_;
  view_->setValueReader([im, cx, cy, oneD](int x, int y) {
    QString s = QStringLiteral("I = %1").arg(formatValue(im.values[size_t(y) * im.width + x]));
    if (oneD && !cx.empty() && !cy.empty())
      s += QStringLiteral("  Ix = %1  Iy = %2")
               .arg(formatValue(curveAt(cx, x, im.width)), formatValue(curveAt(cy, y, im.height)));
    return s;
  });

  QString text;
  switch (mode_) {
    case Mode::Raw:
      text = tr("Importance map %1×%2 (frame %3), max %4. Bright = the camera needs more "
                "shadow-map resolution there.")
                 .arg(w)
                 .arg(h)
                 .arg(frame_)
                 .arg(formatValue(max_));
      break;
    case Mode::Collapsed:
    case Mode::Blurred:
      text = haveCurves
                 ? tr("%1 1D maps (profiles on the edges) and the separable density Ix·Iy they "
                      "give: a rectilinear warp can only follow importance of this form.")
                       .arg(blurred ? tr("Blurred and floored") : tr("Collapsed (max)"))
                 : tr("This technique publishes no 1D importance maps.");
      break;
  }
  info_->setText(text);
}

void ImportancePanel::highlightPass(const QString& passId) {
  if (passId == QLatin1String("importance"))
    setMode(Mode::Raw);
  else if (passId == QLatin1String("collapse"))
    setMode(Mode::Collapsed);
  else if (passId == QLatin1String("blur"))
    setMode(Mode::Blurred);
  view_->setHighlighted(passId == QLatin1String("importance") ||
                        passId == QLatin1String("collapse") || passId == QLatin1String("blur"));
}

QJsonObject ImportancePanel::drawnValues() const {
  if (im_.width <= 0) return {};
  return {{QStringLiteral("width"), im_.width},
          {QStringLiteral("height"), im_.height},
          {QStringLiteral("max"), max_},
          {QStringLiteral("mode"), static_cast<int>(mode_)}};
}

}  // namespace sl::ui
