// Shared panel pieces (see PanelKit.h).
#include "PanelKit.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <QLabel>
#include <QBoxLayout>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QResizeEvent>
#include <QStackedWidget>
#include <QVariant>
#include <QVBoxLayout>
#include <QWheelEvent>

namespace sl::ui {

namespace {

struct Stop {
  float t;
  int r, g, b;
};

// Viridis (matplotlib, van der Walt & Smith 2015) sampled at nine points.
constexpr std::array<Stop, 9> kViridis = {{{0.000f, 68, 1, 84},
                                           {0.125f, 71, 44, 122},
                                           {0.250f, 59, 81, 139},
                                           {0.375f, 44, 113, 142},
                                           {0.500f, 33, 145, 140},
                                           {0.625f, 40, 174, 128},
                                           {0.750f, 94, 201, 98},
                                           {0.875f, 173, 220, 48},
                                           {1.000f, 253, 231, 37}}};
// ColorBrewer RdBu, reversed: negative blue, zero near-white, positive red.
constexpr std::array<Stop, 5> kDiverging = {{{0.00f, 33, 102, 172},
                                             {0.25f, 146, 197, 222},
                                             {0.50f, 247, 247, 247},
                                             {0.75f, 244, 165, 130},
                                             {1.00f, 178, 24, 43}}};

template <std::size_t N>
QRgb interpolate(const std::array<Stop, N>& stops, float t) {
  for (std::size_t i = 1; i < N; ++i) {
    if (t <= stops[i].t) {
      const Stop& a = stops[i - 1];
      const Stop& b = stops[i];
      const float f = (t - a.t) / (b.t - a.t);
      auto mix = [f](int x, int y) { return static_cast<int>(std::lround(x + (y - x) * f)); };
      return qRgb(mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b));
    }
  }
  return qRgb(stops[N - 1].r, stops[N - 1].g, stops[N - 1].b);
}

constexpr int kMaxLegendWidth = 96;
constexpr int kMargin = 6;
constexpr double kMinZoom = 0.25;
constexpr double kMaxZoom = 64.0;

/// 1, 2 or 5 times a power of ten, about span / targetTicks.
double niceStep(double span, int targetTicks) {
  const double raw = span / std::max(1, targetTicks);
  if (!(raw > 0) || !std::isfinite(raw)) return 1.0;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (raw <= m * p) return m * p;
  return 10.0 * p;
}

}  // namespace

QRgb mapColor(ColorMap map, float t) {
  if (std::isnan(t)) return qRgb(0, 0, 0);
  t = std::clamp(t, 0.0f, 1.0f);
  switch (map) {
    case ColorMap::Viridis:
      return interpolate(kViridis, t);
    case ColorMap::Diverging:
      return interpolate(kDiverging, t);
    case ColorMap::Grey:
      break;
  }
  const int g = static_cast<int>(std::lround(t * 255.0f));
  return qRgb(g, g, g);
}

float ValueRange::normalize(float v) const {
  if (log) {
    const float l0 = std::log10(std::max(lo, 1e-30f)), l1 = std::log10(std::max(hi, 1e-30f));
    if (!(v > 0)) return 0.0f;
    return l1 > l0 ? (std::log10(v) - l0) / (l1 - l0) : 0.5f;
  }
  return hi > lo ? (v - lo) / (hi - lo) : 0.5f;
}

float ValueRange::denormalize(float t) const {
  if (log) {
    const float l0 = std::log10(std::max(lo, 1e-30f)), l1 = std::log10(std::max(hi, 1e-30f));
    return std::pow(10.0f, l0 + t * (l1 - l0));
  }
  return lo + t * (hi - lo);
}

ValueRange finiteRange(std::span<const float> values, int channels, int channel, float ignoreFrom) {
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  const std::size_t step = static_cast<std::size_t>(std::max(1, channels));
  for (std::size_t i = static_cast<std::size_t>(channel); i < values.size(); i += step) {
    const float v = values[i];
    if (!std::isfinite(v) || v >= ignoreFrom) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (!(lo <= hi)) return {0.0f, 1.0f, false};
  if (hi - lo <= 1e-12f * std::max(1.0f, std::abs(hi))) {
    const float pad = std::max(1e-6f, std::abs(hi) * 1e-3f);
    lo -= pad;
    hi += pad;
  }
  return {lo, hi, false};
}

ValueRange symmetricRange(std::span<const float> values, int channels, int channel) {
  const ValueRange r = finiteRange(values, channels, channel);
  const float m = std::max({std::abs(r.lo), std::abs(r.hi), 1e-30f});
  return {-m, m, false};
}

QImage colorize(const sl::FloatImage& image, int channel, const ValueRange& range, ColorMap map) {
  if (image.width <= 0 || image.height <= 0 || image.channels <= 0) return {};
  const std::size_t needed = static_cast<std::size_t>(image.width) * image.height * image.channels;
  if (image.values.size() < needed) return {};
  QImage out(image.width, image.height, QImage::Format_RGB32);
  const int c = std::clamp(channel, 0, image.channels - 1);
  // The map's colours at 4096 steps of the range, looked up per texel (a panel colours a
  // megatexel map every frame): the 256 grey levels and the colour maps' steps are far coarser.
  constexpr int kSteps = 4096;
  std::array<QRgb, kSteps> colors;
  for (int i = 0; i < kSteps; ++i) colors[std::size_t(i)] = mapColor(map, float(i) / (kSteps - 1));
  const QRgb nanColor = mapColor(map, std::numeric_limits<float>::quiet_NaN());
  for (int y = 0; y < image.height; ++y) {
    const int srcRow = image.height - 1 - y;  // FloatImage row 0 = bottom
    auto* line = reinterpret_cast<QRgb*>(out.scanLine(y));
    const float* src = image.values.data() + static_cast<std::size_t>(srcRow) * image.width *
                                                 static_cast<std::size_t>(image.channels);
    for (int x = 0; x < image.width; ++x) {
      const float t = range.normalize(src[x * image.channels + c]);
      line[x] = std::isnan(t)
                    ? nanColor
                    : colors[std::size_t(std::clamp(t, 0.0f, 1.0f) * (kSteps - 1) + 0.5f)];
    }
  }
  return out;
}

QString formatValue(double v) {
  if (!std::isfinite(v)) return QStringLiteral("%1").arg(v);
  if (v == 0.0) return QStringLiteral("0");
  const double a = std::abs(v);
  if (a >= 1e5 || a < 1e-3) return QString::number(v, 'e', 3);
  return QString::number(v, 'g', 4);
}

QString formatTick(double v, double span) {
  if (!std::isfinite(v)) return QStringLiteral("%1").arg(v);
  span = std::abs(span);
  if (span > 0.0 && std::abs(v) < span * 1e-3) return QStringLiteral("0");
  QString text;
  const double a = std::abs(v);
  if (a >= 1e5 || (a < 1e-3 && a > 0.0)) {
    text = QString::number(v, 'e', 2);
  } else {
    // Enough decimals to tell neighbouring ticks (span / 4 apart) by two digits.
    const double step = span > 0.0 ? span / 4.0 : a;
    const int decimals = step > 0.0 ? std::clamp(1 - int(std::floor(std::log10(step))), 0, 6) : 3;
    text = QString::number(v, 'f', decimals);
    if (text.contains(QLatin1Char('.'))) {  // no trailing zeros: "0.5", not "0.500"
      while (text.endsWith(QLatin1Char('0'))) text.chop(1);
      if (text.endsWith(QLatin1Char('.'))) text.chop(1);
    }
    if (text == QLatin1String("-0")) text = QStringLiteral("0");
  }
  text.replace(QLatin1Char('-'), QChar(0x2212));
  return text;
}

sl::FloatImage displayCopy(const sl::FloatImage& image, int maxTexels) {
  const int step =
      std::max(1, (std::max(image.width, image.height) + maxTexels - 1) / std::max(1, maxTexels));
  if (step == 1) return image;
  sl::FloatImage out;
  out.width = (image.width + step - 1) / step;
  out.height = (image.height + step - 1) / step;
  out.channels = 1;
  out.values.resize(size_t(out.width) * size_t(out.height));
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      out.values[size_t(y) * size_t(out.width) + size_t(x)] =
          image.values[(size_t(y * step) * size_t(image.width) + size_t(x * step)) *
                       size_t(image.channels)];
  return out;
}

QString noDataText(const QString& techniqueId, const QString& what,
                   const std::set<std::string>& keys) {
  const QString id = techniqueId.isEmpty() ? QObject::tr("this technique") : techniqueId;
  // The techniques that do publish it, from their declarations.
  QStringList publishers;
  for (const sl::TechniqueInfo& t : sl::Renderer::techniques())
    for (const std::string& key : keys)
      if (t.findPublication(key) && !publishers.contains(QString::fromStdString(t.id))) {
        publishers << QString::fromStdString(t.id);
        break;
      }
  if (publishers.isEmpty())
    return QObject::tr("The technique \u201c%1\u201d publishes no %2.").arg(id, what);
  return QObject::tr(
             "The technique \u201c%1\u201d publishes no %2.\n\nChoose one that does (%3) in "
             "the toolbar to see it.")
      .arg(id, what, publishers.join(QStringLiteral(", ")));
}

// --- ImageView -----------------------------------------------------------------------------

ImageView::ImageView(QWidget* parent) : QWidget(parent) {
  setMouseTracking(true);
  setFocusPolicy(Qt::ClickFocus);
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void ImageView::setImage(const QImage& image, int texelsW, int texelsH) {
  const bool sizeChanged = texelsW != texelsW_ || texelsH != texelsH_;
  image_ = image;
  texelsW_ = texelsW;
  texelsH_ = texelsH;
  if (sizeChanged) resetZoom();
  if (sizeChanged) updateReadableMinimum();
  update();
}

void ImageView::setDisplayAspect(double aspect) {
  const double a = std::isfinite(aspect) && aspect > 0.0 ? aspect : 0.0;
  if (a == displayAspect_) return;
  displayAspect_ = a;
  resetZoom();
  updateReadableMinimum();
  update();
}

void ImageView::clearImage(const QString& placeholder) {
  image_ = QImage();
  texelsW_ = texelsH_ = 0;
  placeholder_ = placeholder;
  updateReadableMinimum();
  update();
}

void ImageView::setValueReader(std::function<QString(int, int)> reader) {
  reader_ = std::move(reader);
}

void ImageView::setLegend(const ValueRange& range, ColorMap map, const QString& title, bool show) {
  legendRange_ = range;
  legendMap_ = map;
  legendTitle_ = title;
  legend_ = show;
  updateReadableMinimum();
  update();
}

void ImageView::setOverlay(std::function<void(QPainter&, const QRectF&)> overlay) {
  overlay_ = std::move(overlay);
  update();
}

void ImageView::setCaption(const QString& caption) {
  caption_ = caption;
  updateReadableMinimum();
  update();
}

void ImageView::setHighlighted(bool on) {
  if (highlighted_ == on) return;
  highlighted_ = on;
  update();
}

void ImageView::resetZoom() {
  zoom_ = 1.0;
  pan_ = {};
  update();
}

QString ImageView::legendTick(float t) const {
  // A log scale's ticks are rounded by their own size (span 0), a linear one's by the span.
  const double span = legendRange_.log
                          ? 0.0
                          : double(legendRange_.denormalize(1.0f) - legendRange_.denormalize(0.0f));
  return formatTick(legendRange_.denormalize(t), span);
}

int ImageView::legendWidth() const {
  if (!legend_) return 0;
  const QFontMetrics fm = fontMetrics();
  int w = fm.horizontalAdvance(legendTitle_);
  for (int i = 0; i < 5; ++i)  // bar (26 px) + tick label
    w = std::max(w, 26 + fm.horizontalAdvance(legendTick(i / 4.0f)));
  // Past the limit the title wraps at its spaces: never narrower than its longest word.
  int longestWord = 0;
  for (const QString& word : legendTitle_.split(QLatin1Char(' '), Qt::SkipEmptyParts))
    longestWord = std::max(longestWord, fm.horizontalAdvance(word));
  return std::max(std::min(w + 6, kMaxLegendWidth), longestWord + 8);
}

int ImageView::wrappedHeight(const QString& text, int width) const {
  const int w = width < 0 ? this->width() : width;
  return fontMetrics()
             .boundingRect(QRect(0, 0, std::max(1, w - 2 * kMargin), 100000),
                           Qt::TextWordWrap | Qt::AlignLeft, text)
             .height() +
         4;
}

int ImageView::captionHeight(int width) const {
  // Wrapped to the widget's width, however many lines: its numbers are what a lesson shows.
  return caption_.isEmpty() ? 0 : wrappedHeight(caption_, width);
}

QSize ImageView::minimumSizeHint() const {
  if (!asksReadableMinimum(*this)) return {120, 110};
  if (!readableMinimumSize_.isValid()) readableMinimumSize_ = readableMinimumSize();
  return readableMinimumSize_;
}

QSize ImageView::readableMinimumSize() const {
  // The image's longer side kReadableSide px (viewArea and imageRect in reverse): a wide image
  // needs that much width and less height, a tall one the other way round. Without an image,
  // a square one.
  const int w = testAttribute(Qt::WA_Resized) ? width() : sizeHint().width();
  const double aspect = displayAspect_ > 0.0           ? displayAspect_
                        : texelsW_ > 0 && texelsH_ > 0 ? double(texelsW_) / double(texelsH_)
                                                       : 1.0;
  const int line = fontMetrics().height() + 4;
  const int imageW = int(std::ceil(kReadableSide * std::min(aspect, 1.0)));
  const int imageH = int(std::ceil(kReadableSide / std::max(aspect, 1.0)));
  return {std::max(120, 2 * kMargin + legendWidth() + imageW),
          std::max(110, 2 * kMargin + line + captionHeight(w) + imageH)};
}

void ImageView::updateReadableMinimum() {
  const QSize size = asksReadableMinimum(*this) ? readableMinimumSize() : QSize();
  if (size == readableMinimumSize_) return;
  readableMinimumSize_ = size;
  updateGeometry();
}

void ImageView::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  updateReadableMinimum();  // the caption wraps to the new width
}

void ImageView::changeEvent(QEvent* event) {
  QWidget::changeEvent(event);
  if (event->type() == QEvent::FontChange) updateReadableMinimum();
}

int ImageView::readoutHeight(const QString& readout) const {
  const int line = fontMetrics().height() + 4;
  return readout.isEmpty() ? line : std::max(line, wrappedHeight(readout));
}

QRectF ImageView::viewArea() const {
  // One line for the readout: a longer one wraps upwards over the image (it never moves it).
  const int line = fontMetrics().height() + 4;
  QRectF area = QRectF(rect()).adjusted(kMargin, kMargin, -kMargin, -kMargin - line);
  area.setTop(area.top() + captionHeight());
  area.setRight(area.right() - legendWidth());
  return area;
}

QRectF ImageView::imageRect() const {
  const QRectF area = viewArea();
  if (texelsW_ <= 0 || texelsH_ <= 0 || area.width() <= 0 || area.height() <= 0) return {};
  const double aspect = displayAspect_ > 0.0 ? displayAspect_ : double(texelsW_) / double(texelsH_);
  double w = area.width(), h = w / aspect;
  if (h > area.height()) h = area.height(), w = h * aspect;
  w *= zoom_;
  h *= zoom_;
  const QPointF c = area.center() + pan_;
  return {c.x() - w / 2, c.y() - h / 2, w, h};
}

void ImageView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  const QPalette& pal = palette();
  p.fillRect(rect(), pal.color(QPalette::Base));
  const QFontMetrics fm = fontMetrics();
  const int line = fm.height() + 4;
  if (!caption_.isEmpty()) {  // wrapped, never cut: the numbers in it are what a lesson shows
    p.setPen(pal.color(QPalette::Text));
    p.drawText(QRect(kMargin, kMargin, width() - 2 * kMargin, captionHeight()),
               Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap, caption_);
  }
  const QRectF area = viewArea();
  if (image_.isNull()) {
    p.setPen(pal.color(QPalette::PlaceholderText));
    p.drawText(area, Qt::AlignCenter | Qt::TextWordWrap, placeholder_);
  } else {
    const QRectF r = imageRect();
    p.save();
    p.setClipRect(area);
    p.drawImage(r, image_);  // nearest neighbour: texels stay visible when zoomed in
    if (overlay_) {
      p.setRenderHint(QPainter::Antialiasing);
      overlay_(p, r);
    }
    p.restore();
  }

  if (legend_) {
    const int legendW = legendWidth();
    // The title wraps within the legend's width (never elided); the bar starts under it.
    const int titleH =
        std::max(line, fm.boundingRect(QRect(0, 0, std::max(1, legendW - 4), 100000),
                                       Qt::TextWordWrap | Qt::AlignLeft, legendTitle_)
                           .height());
    const QRectF bar(area.right() + 8, area.top() + titleH, 12, area.height() - titleH - line);
    if (bar.height() > 20) {
      const int steps = static_cast<int>(bar.height());
      for (int i = 0; i < steps; ++i) {
        const float t = 1.0f - (i + 0.5f) / steps;
        p.fillRect(QRectF(bar.left(), bar.top() + i, bar.width(), 1.0),
                   QColor(mapColor(legendMap_, t)));
      }
      p.setPen(pal.color(QPalette::Mid));
      p.drawRect(bar);
      p.setPen(pal.color(QPalette::Text));
      constexpr int kTicks = 5;
      for (int i = 0; i < kTicks; ++i) {
        const float t = float(i) / (kTicks - 1);
        const double y = bar.bottom() - t * bar.height();
        p.drawLine(QPointF(bar.right(), y), QPointF(bar.right() + 3, y));
        p.drawText(QRectF(bar.right() + 5, y - line / 2.0, legendW - 26, line),
                   Qt::AlignLeft | Qt::AlignVCenter, legendTick(t));
      }
      p.drawText(QRectF(area.right() + 4, area.top(), legendW - 4, titleH),
                 Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap, legendTitle_);
    }
  }

  // Readout of the texel under the cursor; a usage hint when the view has room for it.
  QString readout = hoverText();
  const int readoutH = readoutHeight(readout);  // wrapped: a texel's numbers are never cut
  if (readout.isEmpty() && height() > 220 &&
      fm.horizontalAdvance(tr("wheel: zoom · drag: pan · double-click: fit")) <=
          width() - 2 * kMargin)
    readout = tr("wheel: zoom · drag: pan · double-click: fit");  // a hint only where it fits
  const QRect readoutRect(kMargin, height() - readoutH - kMargin / 2, width() - 2 * kMargin,
                          readoutH);
  if (readoutH > line) {
    QColor back = pal.color(QPalette::Base);
    back.setAlpha(225);
    p.fillRect(readoutRect, back);
  }
  p.setPen(pal.color(QPalette::PlaceholderText));
  p.drawText(readoutRect, Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap, readout);

  if (highlighted_) {
    p.setPen(QPen(QColor(255, 196, 0), 3));
    p.setBrush(Qt::NoBrush);
    p.drawRect(QRectF(rect()).adjusted(1.5, 1.5, -1.5, -1.5));
  }
}

QString ImageView::hoverText() const {
  const QRectF r = imageRect();
  if (image_.isNull() || hover_.x() < 0 || !r.contains(hover_)) return {};
  const double u = (hover_.x() - r.left()) / r.width();
  const double v = (r.bottom() - hover_.y()) / r.height();
  const int tx = std::clamp(static_cast<int>(u * texelsW_), 0, texelsW_ - 1);
  const int ty = std::clamp(static_cast<int>(v * texelsH_), 0, texelsH_ - 1);
  QString text = QStringLiteral("texel (%1, %2)  uv (%3, %4)")
                     .arg(tx)
                     .arg(ty)
                     .arg(u, 0, 'f', 3)
                     .arg(v, 0, 'f', 3);
  if (reader_) text += QStringLiteral("  ") + reader_(tx, ty);
  return text;
}

void ImageView::wheelEvent(QWheelEvent* event) {
  if (image_.isNull()) return;
  const double steps = event->angleDelta().y() / 120.0;
  if (steps == 0.0) return;
  const double newZoom = std::clamp(zoom_ * std::pow(1.25, steps), kMinZoom, kMaxZoom);
  // Keep the point under the cursor where it is.
  const QPointF c = viewArea().center() + pan_;
  const QPointF rel = event->position() - c;
  pan_ += rel - rel * (newZoom / zoom_);
  zoom_ = newZoom;
  update();
  event->accept();
}

void ImageView::mousePressEvent(QMouseEvent* event) {
  dragging_ = true;
  lastMouse_ = event->position().toPoint();
}

void ImageView::mouseMoveEvent(QMouseEvent* event) {
  const QPoint pos = event->position().toPoint();
  if (dragging_) {
    pan_ += QPointF(pos - lastMouse_);
    lastMouse_ = pos;
  }
  hover_ = pos;
  update();
}

void ImageView::mouseReleaseEvent(QMouseEvent*) {
  dragging_ = false;
}

void ImageView::mouseDoubleClickEvent(QMouseEvent*) {
  resetZoom();
}

void ImageView::leaveEvent(QEvent*) {
  hover_ = {-1, -1};
  update();
}

// --- PlotWidget ----------------------------------------------------------------------------

PlotWidget::PlotWidget(QWidget* parent) : QWidget(parent) {
  setMouseTracking(true);
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void PlotWidget::setAxisLabels(const QString& x, const QString& y) {
  xLabel_ = x;
  yLabel_ = y;
  updateReadableMinimum();  // the y label is part of the title
  update();
}

void PlotWidget::setTitle(const QString& title) {
  title_ = title;
  updateReadableMinimum();
  update();
}

void PlotWidget::setSeries(std::vector<Series> series) {
  series_ = std::move(series);
  updateReadableMinimum();  // the legend's band
  update();
}

void PlotWidget::setLines(std::vector<Line> lines) {
  lines_ = std::move(lines);
  update();
}

void PlotWidget::setMarkers(std::vector<Marker> markers) {
  markers_ = std::move(markers);
  update();
}

void PlotWidget::setXRange(double lo, double hi) {
  fixedX0_ = lo;
  fixedX1_ = hi;
  update();
}

void PlotWidget::setYRange(double lo, double hi) {
  fixedY0_ = lo;
  fixedY1_ = hi;
  update();
}

void PlotWidget::setLogY(bool on) {
  logY_ = on;
  update();
}

void PlotWidget::setPlaceholder(const QString& text) {
  placeholder_ = text;
  update();
}

void PlotWidget::setHighlighted(bool on) {
  if (highlighted_ == on) return;
  highlighted_ = on;
  update();
}

QString PlotWidget::fullTitle() const {
  return yLabel_.isEmpty() ? title_ : QStringLiteral("%1  \u2014  y: %2").arg(title_, yLabel_);
}

int PlotWidget::titleHeight(int width) const {
  // Wrapped to the widget's width, however many lines: never elided (its numbers are read).
  const int w = width < 0 ? this->width() : width;
  const QRect bounds = fontMetrics().boundingRect(QRect(0, 0, std::max(1, w - 12), 100000),
                                                  Qt::TextWordWrap | Qt::AlignLeft, fullTitle());
  return std::max(fontMetrics().height(), bounds.height());
}

std::vector<QRectF> PlotWidget::legendLayout(double top, int* height, int width) const {
  const QFontMetrics fm = fontMetrics();
  const int line = fm.height();
  std::vector<QRectF> entries;
  double x = 6.0, y = top;
  const double right = (width < 0 ? this->width() : width) - 6.0;
  for (const Series& s : series_) {
    if (s.name.isEmpty()) continue;
    const double w = 24.0 + fm.horizontalAdvance(s.name) + 4.0;  // the sample line, the name
    if (x > 6.0 && x + w > right) x = 6.0, y += line;            // wrap
    entries.emplace_back(x, y, w, line);
    x += w + 12.0;
  }
  if (height) *height = entries.empty() ? 0 : static_cast<int>(y - top) + line + 2;
  return entries;
}

std::vector<QRectF> PlotWidget::legendEntries() const {
  return legendLayout(titleHeight() + 4, nullptr);
}

QRectF PlotWidget::plotArea() const {
  const int line = fontMetrics().height();
  const int left = fontMetrics().horizontalAdvance(QStringLiteral("-0.0000")) + 12;
  int legend = 0;
  legendLayout(titleHeight() + 4, &legend);
  return QRectF(rect()).adjusted(left, titleHeight() + 8 + legend, -10, -(2 * line + 8));
}

QSize PlotWidget::minimumSizeHint() const {
  if (!asksReadableMinimum(*this)) return {140, 100};
  if (readableMinimumHeight_ <= 0) readableMinimumHeight_ = readableMinimumHeight();
  return {140, readableMinimumHeight_};
}

int PlotWidget::readableMinimumHeight() const {
  // plotArea in reverse: title, legend band and axis labels around kReadableCurves of curves.
  const int w = testAttribute(Qt::WA_Resized) ? width() : sizeHint().width();
  const int title = titleHeight(w);
  int legend = 0;
  legendLayout(title + 4, &legend, w);
  const int line = fontMetrics().height();
  return std::max(kReadableHeight, title + 8 + legend + kReadableCurves + 2 * line + 8);
}

void PlotWidget::updateReadableMinimum() {
  const int height = asksReadableMinimum(*this) ? readableMinimumHeight() : 0;
  if (height == readableMinimumHeight_) return;
  readableMinimumHeight_ = height;
  updateGeometry();
}

void PlotWidget::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  updateReadableMinimum();  // the title and the legend wrap to the new width
}

void PlotWidget::changeEvent(QEvent* event) {
  QWidget::changeEvent(event);
  if (event->type() == QEvent::FontChange) updateReadableMinimum();
}

PlotWidget::Ranges PlotWidget::ranges() const {
  Ranges r{0, 1, 0, 1};
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const Series& s : series_)
    for (const QPointF& pt : s.points) {
      if (!std::isfinite(pt.x()) || !std::isfinite(pt.y())) continue;
      if (logY_ && !(pt.y() > 0)) continue;
      x0 = std::min(x0, pt.x());
      x1 = std::max(x1, pt.x());
      y0 = std::min(y0, pt.y());
      y1 = std::max(y1, pt.y());
    }
  for (const Line& l : lines_)
    if (std::isfinite(l.y) && (!logY_ || l.y > 0)) y0 = std::min(y0, l.y), y1 = std::max(y1, l.y);
  if (x0 <= x1) r.x0 = x0, r.x1 = x1;
  if (y0 <= y1) r.y0 = y0, r.y1 = y1;
  if (fixedX0_ < fixedX1_) r.x0 = fixedX0_, r.x1 = fixedX1_;
  if (fixedY0_ < fixedY1_) r.y0 = fixedY0_, r.y1 = fixedY1_;
  if (logY_) {
    r.y0 = std::pow(10.0, std::floor(std::log10(std::max(r.y0, 1e-30))));
    r.y1 = std::pow(10.0, std::ceil(std::log10(std::max(r.y1, r.y0 * 10))));
  } else if (!(fixedY0_ < fixedY1_)) {
    const double pad = (r.y1 - r.y0) * 0.06;
    if (pad > 0) {
      r.y1 += pad;
      if (r.y0 < 0 || r.y0 - pad >= 0) r.y0 -= pad;
    } else {
      r.y0 -= 0.5, r.y1 += 0.5;
    }
  }
  if (!(r.x1 > r.x0)) r.x1 = r.x0 + 1;
  return r;
}

double PlotWidget::yToT(double y, const Ranges& r) const {
  if (logY_) {
    const double l0 = std::log10(r.y0), l1 = std::log10(r.y1);
    return y > 0 ? (std::log10(y) - l0) / (l1 - l0) : -1.0;
  }
  return (y - r.y0) / (r.y1 - r.y0);
}

void PlotWidget::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const QPalette& pal = palette();
  p.fillRect(rect(), pal.color(QPalette::Base));
  const QFontMetrics fm = fontMetrics();
  const int line = fm.height();
  p.setPen(pal.color(QPalette::Text));
  p.drawText(QRect(6, 2, width() - 12, titleHeight() + 4),
             Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap, fullTitle());

  bool any = false;
  for (const Series& s : series_) any = any || !s.points.empty();
  const QRectF a = plotArea();
  if (!any || a.width() < 20 || a.height() < 20) {
    p.setPen(pal.color(QPalette::PlaceholderText));
    p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, placeholder_);
    return;
  }
  const Ranges r = ranges();
  auto toX = [&](double x) { return a.left() + (x - r.x0) / (r.x1 - r.x0) * a.width(); };
  auto toY = [&](double y) { return a.bottom() - yToT(y, r) * a.height(); };

  // Grid and ticks.
  const QColor grid = pal.color(QPalette::AlternateBase).lighter(120);
  p.setPen(grid);
  const double xs = niceStep(r.x1 - r.x0, std::max(2, int(a.width() / 70)));
  for (double x = std::ceil(r.x0 / xs) * xs; x <= r.x1 + xs * 1e-6; x += xs) {
    p.setPen(grid);
    p.drawLine(QPointF(toX(x), a.top()), QPointF(toX(x), a.bottom()));
    p.setPen(pal.color(QPalette::PlaceholderText));
    p.drawText(QRectF(toX(x) - 40, a.bottom() + 2, 80, line), Qt::AlignHCenter | Qt::AlignTop,
               formatTick(x, 4.0 * xs));
  }
  std::vector<double> yTicks;
  double ys = 0.0;  ///< linear y: the tick step
  if (logY_) {
    for (double y = r.y0; y <= r.y1 * 1.0001; y *= 10) yTicks.push_back(y);
  } else {
    ys = niceStep(r.y1 - r.y0, std::max(2, int(a.height() / 40)));
    for (double y = std::ceil(r.y0 / ys) * ys; y <= r.y1 + ys * 1e-6; y += ys)
      yTicks.push_back(std::abs(y) < ys * 1e-6 ? 0.0 : y);
  }
  for (double y : yTicks) {
    p.setPen(grid);
    p.drawLine(QPointF(a.left(), toY(y)), QPointF(a.right(), toY(y)));
    p.setPen(pal.color(QPalette::PlaceholderText));
    const QString label = logY_ ? QStringLiteral("1e%1")
                                      .arg(std::lround(std::log10(y)))
                                      .replace(QLatin1Char('-'), QChar(0x2212))
                                : formatTick(y, 4.0 * ys);
    p.drawText(QRectF(0, toY(y) - line / 2.0, a.left() - 4, line),
               Qt::AlignRight | Qt::AlignVCenter, label);
  }
  p.setPen(pal.color(QPalette::Mid).lighter(160));
  p.drawRect(a);
  p.setPen(pal.color(QPalette::PlaceholderText));
  p.drawText(QRectF(a.left(), a.bottom() + line + 2, a.width(), line + 4),
             Qt::AlignHCenter | Qt::AlignVCenter, xLabel_);

  p.save();
  p.setClipRect(a.adjusted(-2, -2, 2, 2));
  for (const Line& l : lines_) {
    p.setPen(QPen(l.color, 1.2, Qt::DashLine));
    const double y = toY(l.y);
    p.drawLine(QPointF(a.left(), y), QPointF(a.right(), y));
    p.drawText(QRectF(a.left() + 4, y - line - 1, a.width() - 8, line),
               Qt::AlignRight | Qt::AlignBottom, l.label);
  }
  // Markers: vertical lines, their labels stacked down from the top so none covers another.
  int markerRow = 0;
  for (const Marker& m : markers_) {
    if (!std::isfinite(m.x) || m.x < r.x0 || m.x > r.x1) continue;
    const double x = toX(m.x);
    p.setPen(QPen(m.color, 1.6, m.style));
    p.drawLine(QPointF(x, a.top()), QPointF(x, a.bottom()));
    if (m.label.isEmpty()) continue;
    const int tw = fm.horizontalAdvance(m.label) + 6;
    const double left = x + tw + 2 < a.right() ? x + 2 : x - tw - 2;
    const QRectF box(left, a.bottom() - (markerRow + 1) * (line + 1) - 2, tw, line);
    QColor bg = pal.color(QPalette::Base);
    bg.setAlpha(200);
    p.fillRect(box, bg);
    p.setPen(m.color);
    p.drawText(box, Qt::AlignCenter, m.label);
    ++markerRow;
  }
  for (const Series& s : series_) {
    if (s.points.empty()) continue;
    QPainterPath path;
    bool started = false;
    for (const QPointF& pt : s.points) {
      const double t = yToT(pt.y(), r);
      if (!std::isfinite(pt.y()) || t < -10 || (logY_ && !(pt.y() > 0))) {
        started = false;
        continue;
      }
      const QPointF q(toX(pt.x()), toY(pt.y()));
      if (started)
        path.lineTo(q);
      else
        path.moveTo(q);
      started = true;
    }
    if (s.highlighted) {
      QColor glow = QColor(255, 196, 0);
      glow.setAlpha(110);
      p.setPen(QPen(glow, s.width + 6, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
      p.drawPath(path);
    }
    p.setPen(
        QPen(s.color, s.highlighted ? s.width + 1 : s.width, s.style, Qt::RoundCap, Qt::RoundJoin));
    p.drawPath(path);
    if (s.dots) {
      p.setBrush(s.color);
      p.setPen(Qt::NoPen);
      for (const QPointF& pt : s.points)
        if (std::isfinite(pt.y()) && !(logY_ && !(pt.y() > 0)))
          p.drawEllipse(QPointF(toX(pt.x()), toY(pt.y())), 3.0, 3.0);
      p.setBrush(Qt::NoBrush);
    }
  }
  p.restore();

  // Legend (its own band under the title) and hover readout (top left of the curves).
  {
    const std::vector<QRectF> entries = legendEntries();
    std::size_t i = 0;
    for (const Series& s : series_) {
      if (s.name.isEmpty()) continue;
      const QRectF& e = entries[i++];
      const double y = e.center().y();
      p.setPen(QPen(s.color, 2, s.style));
      p.drawLine(QPointF(e.left(), y), QPointF(e.left() + 20, y));
      p.setPen(pal.color(QPalette::Text));
      p.drawText(e.adjusted(24, 0, 0, 0), Qt::AlignLeft | Qt::AlignVCenter, s.name);
    }
  }
  if (hoverX_ >= a.left() && hoverX_ <= a.right()) {
    const double x = r.x0 + (hoverX_ - a.left()) / a.width() * (r.x1 - r.x0);
    p.setPen(QPen(pal.color(QPalette::Text), 1, Qt::DotLine));
    p.drawLine(QPointF(hoverX_, a.top()), QPointF(hoverX_, a.bottom()));
    QStringList rows{
        QStringLiteral("%1 = %2").arg(xLabel_.section(QLatin1Char(' '), 0, 0), formatValue(x))};
    for (const Series& s : series_) {
      if (s.points.empty() || s.name.isEmpty()) continue;
      auto it = std::lower_bound(s.points.begin(), s.points.end(), x,
                                 [](const QPointF& pt, double v) { return pt.x() < v; });
      double y;
      if (it == s.points.begin())
        y = it->y();
      else if (it == s.points.end())
        y = s.points.back().y();
      else {
        const QPointF& b = *it;
        const QPointF& c = *(it - 1);
        y = b.x() > c.x() ? c.y() + (b.y() - c.y()) * (x - c.x()) / (b.x() - c.x()) : b.y();
      }
      rows << QStringLiteral("%1: %2").arg(s.name, formatValue(y));
    }
    int boxW = 0;
    for (const QString& row : rows) boxW = std::max(boxW, fm.horizontalAdvance(row));
    const QRectF box(a.left() + 6, a.top() + 4, boxW + 12, rows.size() * line + 8);
    QColor bg = pal.color(QPalette::Window);
    bg.setAlpha(225);
    p.setPen(pal.color(QPalette::Mid));
    p.setBrush(bg);
    p.drawRoundedRect(box, 4, 4);
    p.setPen(pal.color(QPalette::Text));
    for (int i = 0; i < rows.size(); ++i)
      p.drawText(QRectF(box.left() + 6, box.top() + 4 + i * line, boxW + 4, line),
                 Qt::AlignLeft | Qt::AlignVCenter, rows[i]);
  }
  if (highlighted_) {
    p.setPen(QPen(QColor(255, 196, 0), 3));
    p.setBrush(Qt::NoBrush);
    p.drawRect(QRectF(rect()).adjusted(1.5, 1.5, -1.5, -1.5));
  }
}

void PlotWidget::mouseMoveEvent(QMouseEvent* event) {
  hoverX_ = static_cast<int>(event->position().x());
  update();
}

void PlotWidget::leaveEvent(QEvent*) {
  hoverX_ = -1;
  update();
}

// --- PublicationPanel ----------------------------------------------------------------------

PublicationPanel::PublicationPanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  stack_ = new QStackedWidget(this);
  placeholder_ = new QLabel;
  placeholder_->setAlignment(Qt::AlignCenter);
  placeholder_->setWordWrap(true);
  placeholder_->setMargin(16);
  placeholder_->setForegroundRole(QPalette::PlaceholderText);
  placeholder_->setObjectName(QStringLiteral("placeholder"));
  stack_->addWidget(placeholder_);
  layout->addWidget(stack_);
  placeholder_->setText(tr("No frame yet."));
}

bool PublicationPanel::describes(const sl::TechniqueInfo& info) const {
  for (const std::string& key : observedKeys()) {
    if (info.findPublication(key)) return true;
    for (const sl::PublicationDecl& d : info.publications)  // a pattern against a pattern
      if (sl::publicationKeyMatches(key, d.key)) return true;
  }
  return false;
}

QString PublicationPanel::placeholderShown() const {
  return stack_->currentIndex() == 0 ? placeholder_->text() : QString();
}

WrappedLabel::WrappedLabel(QWidget* parent) : QLabel(parent) {
  setWordWrap(true);
}

QSize WrappedLabel::minimumSizeHint() const {
  // Its width as laid out (its size hint's before a layout set one): setText invalidates the
  // layout, which asks again.
  if (!asksReadableMinimum(*this)) return QLabel::minimumSizeHint();
  const int w = testAttribute(Qt::WA_Resized) ? width() : sizeHint().width();
  wrappedHeight_ = text().isEmpty() ? 0 : heightForWidth(w);
  return {QLabel::minimumSizeHint().width(), std::max(0, wrappedHeight_)};
}

void WrappedLabel::resizeEvent(QResizeEvent* event) {
  QLabel::resizeEvent(event);
  // Narrower: more lines (wider: fewer); the layout is told when the count changes.
  if (asksReadableMinimum(*this) && !text().isEmpty() && heightForWidth(width()) != wrappedHeight_)
    updateGeometry();
}

BesideWhenWide::BesideWhenWide(QWidget* first, QWidget* second, int secondEms, QWidget* parent)
    : QWidget(parent), first_(first), second_(second), secondEms_(secondEms) {
  auto* box = new QBoxLayout(QBoxLayout::TopToBottom, this);
  box->setContentsMargins(0, 0, 0, 0);
  box->addWidget(first, 1);
  box->addWidget(second, 0);
}

bool BesideWhenWide::beside() const {
  return static_cast<QBoxLayout*>(layout())->direction() == QBoxLayout::LeftToRight;
}

QSize BesideWhenWide::minimumSizeHint() const {
  const QSize least = QWidget::minimumSizeHint();
  const int under = std::max(first_->minimumSizeHint().width(), second_->minimumSizeHint().width());
  return {std::min(least.width(), under), least.height()};
}

void BesideWhenWide::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  auto* box = static_cast<QBoxLayout*>(layout());
  const int firstWidth = std::max(first_->sizeHint().width(), first_->minimumSizeHint().width());
  const bool wide = width() >= firstWidth + std::max(0, box->spacing()) +
                                   secondEms_ * fontMetrics().averageCharWidth();
  if (wide == beside()) return;
  box->setDirection(wide ? QBoxLayout::LeftToRight : QBoxLayout::TopToBottom);
  box->setStretchFactor(second_, wide ? 1 : 0);  // beside: the notes share the width
}

PanelColumn newPanelColumn() {
  auto* content = new QWidget;
  auto* layout = new QVBoxLayout(content);
  layout->setContentsMargins(kPanelColumnMargin, kPanelColumnMargin, kPanelColumnMargin,
                             kPanelColumnMargin);
  return {content, layout};
}

void PublicationPanel::setContent(QWidget* content) {
  stack_->addWidget(content);
}

void PublicationPanel::showContent(bool on, const QString& placeholder) {
  if (!on) placeholder_->setText(placeholder);
  stack_->setCurrentIndex(on && stack_->count() > 1 ? 1 : 0);
}

QStringList unreadableParts(const QWidget& panel) {
  QStringList small;
  for (const PlotWidget* plot : panel.findChildren<PlotWidget*>()) {
    if (!plot->isVisible() || plot->visibleRegion().isEmpty()) continue;
    bool over = false;
    for (const QRectF& entry : plot->legendEntries())
      over = over || entry.intersects(plot->curveArea());
    const int curves = static_cast<int>(plot->curveArea().height());
    if (plot->height() < PlotWidget::kReadableHeight || curves < PlotWidget::kReadableCurves ||
        over)
      small << QObject::tr("a plot %1 px tall, its curves %2 px%3")
                   .arg(plot->height())
                   .arg(curves)
                   .arg(over ? QObject::tr(", its legend over the curves") : QString());
  }
  for (const ImageView* image : panel.findChildren<ImageView*>()) {
    if (!image->isVisible() || image->visibleRegion().isEmpty() || !image->hasImage()) continue;
    const QRectF r = image->shownImageRect();
    if (std::max(r.width(), r.height()) < ImageView::kReadableSide)
      small << QObject::tr("an image drawn %1 x %2 px")
                   .arg(r.width(), 0, 'f', 0)
                   .arg(r.height(), 0, 'f', 0);
  }
  return small;
}

namespace {
constexpr char kReadableMinimumProperty[] = "slReadableMinimum";
}

void setReadableMinimums(QWidget& panel, bool on) {
  if (panel.property(kReadableMinimumProperty).toBool() == on) return;
  panel.setProperty(kReadableMinimumProperty, on);
  for (PlotWidget* plot : panel.findChildren<PlotWidget*>()) plot->updateReadableMinimum();
  for (ImageView* image : panel.findChildren<ImageView*>()) image->updateReadableMinimum();
  for (WrappedLabel* label : panel.findChildren<WrappedLabel*>()) label->updateGeometry();
  if (auto* p = qobject_cast<PublicationPanel*>(&panel)) p->readableMinimumsChanged();
  for (PublicationPanel* p : panel.findChildren<PublicationPanel*>()) p->readableMinimumsChanged();
}

bool asksReadableMinimum(const QWidget& widget) {
  for (const QWidget* w = widget.parentWidget(); w; w = w->parentWidget()) {
    const QVariant on = w->property(kReadableMinimumProperty);
    if (on.isValid()) return on.toBool();
  }
  return false;
}

}  // namespace sl::ui
