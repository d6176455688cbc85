// The Partitions panel (see PartitionsPanel.h).
#include "PartitionsPanel.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <QGridLayout>
#include <QJsonArray>
#include <QLabel>
#include <QPainter>
#include <QVBoxLayout>

#include "algo/PartitionColours.h"
#include "algo/warp/PerspectiveWarp.h"

namespace sl::ui {

namespace {
/// A map's texel count as its side squared ("1024²") when it is a square, else the number
/// (a table cell that never wraps inside a number).
QString texelCount(double texels) {
  const double side = std::round(std::sqrt(std::max(0.0, texels)));
  // (Not "%1²".arg(): QString::arg reads the superscript two as a digit of "%12".)
  if (side > 0 && side * side == texels) return QString::number(qint64(side)) + QChar(0x00b2);
  return formatValue(texels);
}

/// A table cell's number: three significant digits, never an exponent below 10^5 (the
/// table must fit a presenter's dock without wrapping inside a number).
QString cell(double v) {
  const double a = std::abs(v);
  if (!std::isfinite(v) || v == 0.0 || a >= 1e5 || a < 1e-3) return formatValue(v);
  const int decimals = a >= 100 ? 0 : a >= 10 ? 1 : a >= 1 ? 2 : 2 - int(std::floor(std::log10(a)));
  return QString::number(v, 'f', decimals);
}

constexpr int kMaxDisplayTexels = 512;  ///< larger maps are point-sampled for display
constexpr int kMapSpacing = 2;          ///< px between two maps (each is framed in its colour)
constexpr int kPanelMargins = 16;       ///< px: the content's margins and the dock's frame

/// The partition overlay's colour of map `i` (algo/PartitionColours).
QColor partitionQColor(int i) {
  const glm::vec3 c = partitionColour(i);
  return QColor::fromRgbF(c.r, c.g, c.b);
}

/// The numbered causes of the warp column's fallbacks, one line each ("" without any).
QString notesText(const QStringList& notes) {
  QString text;
  for (qsizetype i = 0; i < notes.size(); ++i)
    text += QObject::tr("(%1) uniform: %2<br>").arg(i + 1).arg(notes[i]);
  return text;
}

double number(const sl::Publication& pub, const std::string& key, double fallback = -1.0) {
  return pub.number(key, fallback);
}
}  // namespace

PartitionsPanel::PartitionsPanel(QWidget* parent) : PublicationPanel(parent) {
  auto [content, layout] = newPanelColumn();
  maps_ = new QGridLayout;
  maps_->setSpacing(kMapSpacing);
  layout->addLayout(maps_, 1);
  table_ = new WrappedLabel;
  table_->setObjectName(QStringLiteral("partitionTable"));
  table_->setTextFormat(Qt::RichText);
  table_->setWordWrap(true);
  table_->setToolTip(
      tr("m: texels per pixel over last frame's pixels that selected the map (p95 to 1/8 "
         "octave). Dashed (cyan) on each map: its slice of the view frustum. Colours as the "
         "view's partition overlay. partition.warp: warped maps are fitted tightly, not "
         "stabilised (their texels change size along the warp); only uniform partitions are "
         "stabilised."));
  layout->addWidget(table_);
  setContent(content);
}

void PartitionsPanel::showPublication(const sl::Publication& pub) {
  const int k = int(number(pub, "partition.count", 0.0));
  if (k <= 0) {
    drawn_ = {};
    showContent(false, noDataText(QString::fromStdString(pub.techniqueId), tr("partitions"),
                                  observedKeys()));
    return;
  }
  showContent(true);
  while (int(views_.size()) < k) {
    auto* v = new ImageView;
    v->setObjectName(QStringLiteral("partitionMap%1").arg(views_.size()));
    // Its width follows the panel's (arrangeMaps puts as many in a row as the width holds at
    // their minimum): a row of maps never holds the panel at the width it was arranged for.
    v->setMinimumWidth(1);
    views_.push_back(v);
  }
  shown_ = k;
  arrangeMaps();
  QJsonArray parts;
  QString rows;
  QStringList notes;     // the fallbacks' causes, numbered in the warp column
  bool anyWarp = false;  // a partition asked for a warp (warped or fell back)
  for (int i = 0; i < int(views_.size()); ++i) {
    ImageView* v = views_[size_t(i)];
    v->setVisible(i < k);
    if (i >= k) continue;
    const std::string key = "partition." + std::to_string(i);
    const double nearM = number(pub, key + ".near"), farM = number(pub, key + ".far");
    const double perM = number(pub, key + ".texels_per_m");
    const double texels = number(pub, key + ".texels");
    const double extent = number(pub, key + ".extent_m");
    const double mP95 = number(pub, key + ".m.p95"), mMax = number(pub, key + ".m.max");
    const double mPixels = number(pub, key + ".m.pixels");
    const QString caption = tr("%1: %2 – %3 m").arg(i).arg(formatValue(nearM), formatValue(farM));
    auto img = pub.images.find(key + ".map");
    if (img != pub.images.end() && img->second.width > 0) {
      const auto full = std::make_shared<const sl::FloatImage>(img->second);
      const sl::FloatImage shown = displayCopy(img->second, kMaxDisplayTexels);
      const ValueRange range = finiteRange(shown.values, 1, 0, 1.0f);  // 1 = empty
      v->setImage(colorize(shown, 0, range, ColorMap::Grey), full->width, full->height);
      v->setLegend(range, ColorMap::Grey, QString(), false);
      v->setValueReader([full](int x, int y) {
        const float d = full->values[(size_t(y) * size_t(full->width) + size_t(x))];
        return QStringLiteral("depth = %1")
            .arg(d >= 1.0f ? QObject::tr("1 (empty)") : formatValue(d));
      });
    } else {
      v->clearImage(tr("map not published"));
    }
    v->setCaption(caption);
    const QColor colour = partitionQColor(i);
    // The partition's slice of the view frustum in its map's uv (u right, v up): where the
    // map's texels go; the scene's depth inside it is what the slice sees.
    std::vector<float> slice;
    if (auto c = pub.curves.find(key + ".slice_uv"); c != pub.curves.end()) slice = c->second;
    v->setOverlay([colour, slice](QPainter& p, const QRectF& r) {
      p.setPen(QPen(colour, 4.0));
      p.setBrush(Qt::NoBrush);
      p.drawRect(r.adjusted(2, 2, -2, -2));
      p.save();
      p.setClipRect(r);
      auto at = [&r](float u, float w) {
        return QPointF(r.left() + double(u) * r.width(), r.bottom() - double(w) * r.height());
      };
      // Dark under light dashes: visible on the empty (white) and the filled (grey) map.
      for (const QPen& pen :
           {QPen(QColor(0, 0, 0, 200), 3.0), QPen(QColor(0, 255, 255), 1.5, Qt::DashLine)}) {
        p.setPen(pen);
        for (std::size_t s = 0; s + 3 < slice.size(); s += 4)
          p.drawLine(at(slice[s], slice[s + 1]), at(slice[s + 2], slice[s + 3]));
      }
      p.restore();
    });
    // The warp of this partition: warped (n'), the uniform fallback and why, or not asked.
    const double warped = number(pub, key + ".warped", 0.0);
    const int cause = int(number(pub, key + ".warp.fallback_cause", 0.0));
    QString warpText = QStringLiteral("–");
    if (warped > 0.5) {
      // Lloyd et al.'s eta: 0 is LiSPSM's n'; any other eta is the generalised warp.
      const double eta = number(pub, key + ".warp.eta", 0.0);
      const QString kind =
          std::abs(eta) < 1e-9 ? tr("LiSPSM") : tr("warp η = %1").arg(formatValue(eta));
      warpText = tr("%1, n' %2 m").arg(kind, formatValue(number(pub, key + ".warp.n_prime", 0.0)));
      anyWarp = true;
    } else if (cause > 0) {
      const auto c =
          sl::warp::FallbackCause(std::clamp(cause, 0, int(sl::warp::FallbackCause::Degenerate)));
      // A cause is a sentence: numbered here, written out under the table (a column of
      // sentences makes every row as tall as its cause).
      const QString because = QString::fromUtf8(sl::warp::fallbackCauseText(c)).toHtmlEscaped();
      qsizetype note = notes.indexOf(because);
      if (note < 0) note = (notes << because, notes.size() - 1);
      warpText = tr("uniform (%1)").arg(note + 1);
      anyWarp = true;
    }
    rows += QStringLiteral(
                "<tr><td style='white-space:pre'><span style='color:%1'>&#9632;</span> %2</td><td "
                "style='white-space:pre'>%3</td>"
                "<td style='white-space:pre'>%4</td><td style='white-space:pre'>%5</td><td "
                "style='white-space:pre'>%6</td><td style='white-space:pre'>%7</td>"
                "<td style='white-space:pre'>%8</td><td style='white-space:pre'>%9</td></tr>")
                .arg(colour.name())
                .arg(i)
                .arg(cell(nearM) + QStringLiteral("–") + cell(farM), cell(extent),
                     texelCount(texels), cell(perM), mPixels > 0 ? cell(mP95) : QStringLiteral("–"),
                     mPixels > 0 ? cell(mMax) : QStringLiteral("–"), warpText);
    parts.append(QJsonObject{{QStringLiteral("near_m"), nearM},
                             {QStringLiteral("far_m"), farM},
                             {QStringLiteral("extent_m"), extent},
                             {QStringLiteral("texels"), texels},
                             {QStringLiteral("texels_per_m"), perM},
                             {QStringLiteral("m_p95"), mP95},
                             {QStringLiteral("m_max"), mMax},
                             {QStringLiteral("m_pixels"), mPixels},
                             {QStringLiteral("warped"), warped > 0.5},
                             {QStringLiteral("warp_fallback_cause"), cause},
                             {QStringLiteral("slice_segments"), int(slice.size() / 4)},
                             {QStringLiteral("map_published"), img != pub.images.end()}});
  }
  const double dn = number(pub, "depth.near"), df = number(pub, "depth.far");
  const bool fitted = number(pub, "depth.fitted", 0.0) > 0.5;
  table_->setText(
      tr("<table cellspacing=2 cellpadding=2><tr><th>map</th><th>depth (m)</th>"
         "<th>width (m)</th><th>texels</th><th>texels/m</th><th>m p95</th>"
         "<th>m max</th><th>warp</th></tr>%1</table>%6Split range %2 – %3 m (%4).%5")
          .arg(rows, formatValue(dn), formatValue(df),
               fitted ? tr("fitted to last frame's G-buffer depths")
                      : tr("view frustum ∩ scene bounds"),
               anyWarp ? tr(" Warped maps are fitted tightly, not stabilised.") : QString(),
               notesText(notes)));
  drawn_ = {{QStringLiteral("partitions"), k},       {QStringLiteral("depth_near_m"), dn},
            {QStringLiteral("depth_far_m"), df},     {QStringLiteral("depth_fitted"), fitted},
            {QStringLiteral("warp_asked"), anyWarp}, {QStringLiteral("parts"), parts}};
}

void PartitionsPanel::resizeEvent(QResizeEvent* event) {
  PublicationPanel::resizeEvent(event);
  arrangeMaps();
}

void PartitionsPanel::arrangeMaps() {
  if (views_.empty()) return;
  const int spacing = std::max(0, maps_->horizontalSpacing());
  const int each = views_.front()->minimumSizeHint().width() + spacing;
  const int room = std::max(1, width() - kPanelMargins + spacing);
  const int columns = std::clamp(room / std::max(1, each), 1, std::max(1, shown_));
  if (columns == columns_ && maps_->count() == shown_) return;
  columns_ = columns;
  for (ImageView* v : views_) maps_->removeWidget(v);
  for (int c = 0; c < maps_->columnCount(); ++c) maps_->setColumnStretch(c, 0);
  for (int i = 0; i < shown_ && i < int(views_.size()); ++i)
    maps_->addWidget(views_[size_t(i)], i / columns, i % columns);
  for (int c = 0; c < columns; ++c) maps_->setColumnStretch(c, 1);
}

void PartitionsPanel::highlightPass(const QString& passId) {
  const bool on = passId == QLatin1String("partition maps");
  for (ImageView* v : views_) v->setHighlighted(on);
}

QJsonObject PartitionsPanel::drawnValues() const {
  return drawn_;
}

}  // namespace sl::ui
