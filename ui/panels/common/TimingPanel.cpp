// The Timing panel (see TimingPanel.h): painted bars and a sparkline, no charts library,
// so that it stays cheap to update every frame.
#include "TimingPanel.h"

#include <algorithm>
#include <deque>
#include <numeric>
#include <vector>

#include <QEvent>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPainter>
#include <QPainterPath>
#include <QTextLayout>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace sl::ui {

namespace {
QString formatMs(double ms) {
  return QStringLiteral("%1 ms").arg(ms, 0, 'f', ms < 10 ? 2 : 1);
}

QString formatBytes(std::uint64_t bytes) {
  const double mib = static_cast<double>(bytes) / (1024.0 * 1024.0);
  if (mib >= 1.0) return QStringLiteral("%1 MiB").arg(mib, 0, 'f', 2);
  return QStringLiteral("%1 KiB").arg(static_cast<double>(bytes) / 1024.0, 0, 'f', 1);
}

QString formatCount(std::uint64_t n) {
  return QLocale::c().toString(static_cast<qulonglong>(n));
}
}  // namespace

/// `text` broken into lines of at most `width` pixels in `font`: at spaces where it can, inside
/// a word only where one word alone is wider. The lines joined give `text` back: nothing is
/// elided.
QStringList wrapLines(const QString& text, const QFont& font, int width) {
  QTextLayout layout(text, font);
  QTextOption option;
  option.setWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
  layout.setTextOption(option);
  QStringList lines;
  layout.beginLayout();
  for (QTextLine line = layout.createLine(); line.isValid(); line = layout.createLine()) {
    line.setLineWidth(std::max(1, width));
    lines << text.mid(line.textStart(), line.textLength());
  }
  layout.endLayout();
  if (lines.isEmpty()) lines << text;
  return lines;
}

/// One row per pass: name, a bar proportional to its share of the frame, and the time. A
/// name wider than its room wraps onto more lines (its row grows), never elided.
class PassBarsWidget : public QWidget {
 public:
  PassBarsWidget() {
    QSizePolicy policy = sizePolicy();
    policy.setHeightForWidth(true);
    setSizePolicy(policy);
  }

  void setPasses(std::vector<sl::PassTiming> passes, double totalMs) {
    passes_ = std::move(passes);
    totalMs_ = totalMs;
    updateGeometry();
    update();
  }

  QSize sizeHint() const override { return {320, heightForWidth(width() > 0 ? width() : 320)}; }
  QSize minimumSizeHint() const override { return {200, rowHeight() * 2}; }
  bool hasHeightForWidth() const override { return true; }
  int heightForWidth(int w) const override {
    int h = 0;
    for (const auto& pass : passes_) h += rowHeightOf(wrapped(pass, w).size(), w);
    return std::max(h, rowHeight() * 3);
  }

  /// The widest pass name, the value column ("0000.00 ms  100%") and the least bar width:
  /// what one row needs with the name beside its bar.
  int nameWidth() const {
    const QFontMetrics fm = fontMetrics();
    int w = 0;
    for (const auto& pass : passes_)
      w = std::max(w, fm.horizontalAdvance(QString::fromStdString(pass.name)));
    return w + 10;
  }
  int valueWidth() const {
    return fontMetrics().horizontalAdvance(QStringLiteral("0000.00 ms  100%")) + 8;
  }
  int besideWidth() const { return nameWidth() + valueWidth() + 60; }
  /// The name on a line of its own above its bar: the names do not fit beside the bars.
  bool namesAbove() const { return namesAbove(width()); }

  QStringList names() const {
    QStringList out;
    for (const auto& pass : passes_) out << QString::fromStdString(pass.name);
    return out;
  }
  /// Each name as paintEvent draws it (its lines joined: the whole name, never elided).
  QStringList shownNames() const {
    QStringList out;
    for (const auto& pass : passes_) out << wrapped(pass, width()).join(QString());
    return out;
  }

 protected:
  void paintEvent(QPaintEvent*) override {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPalette& pal = palette();
    if (passes_.empty()) {
      p.setPen(pal.color(QPalette::Disabled, QPalette::Text));
      p.drawText(rect(), Qt::AlignCenter, tr("No frame yet"));
      return;
    }
    double sum = 0;
    for (const auto& pass : passes_) sum += pass.ms;
    const double scale = std::max({totalMs_, sum, 1e-6});
    const bool above = namesAbove();
    const int nameW = above ? 0 : this->nameW(width());
    const int valueW = valueWidth();
    const int barX = nameW, barW = std::max(10, width() - nameW - valueW);
    const int lineH = fontMetrics().height() + 8, textH = fontMetrics().height();
    QColor bar = pal.color(QPalette::Highlight);
    int y = 0;
    for (const sl::PassTiming& pass : passes_) {
      const QStringList lines = wrapped(pass, width());
      const int rowH = rowHeightOf(lines.size(), width());
      p.setPen(pal.color(QPalette::Text));
      if (above) {
        for (int k = 0; k < lines.size(); ++k)
          p.drawText(QRect(2, y + 1 + k * textH, width() - 4, textH),
                     Qt::AlignVCenter | Qt::AlignLeft, lines[k].trimmed());
        y += rowH - lineH;  // the bar's line under the name's
      } else {
        for (int k = 0; k < lines.size(); ++k)
          p.drawText(QRect(0, y + 4 + k * textH, nameW - 6, textH),
                     Qt::AlignVCenter | Qt::AlignRight, lines[k].trimmed());
      }
      const QRectF track(barX, y + 4, barW, lineH - 8);
      p.setPen(Qt::NoPen);
      p.setBrush(pal.color(QPalette::AlternateBase));
      p.drawRoundedRect(track, 3, 3);
      QRectF fill = track;
      fill.setWidth(std::max(2.0, track.width() * pass.ms / scale));
      p.setBrush(bar);
      p.drawRoundedRect(fill, 3, 3);
      p.setPen(pal.color(QPalette::Text));
      p.drawText(
          QRect(barX + barW + 8, y, valueW - 8, lineH), Qt::AlignVCenter | Qt::AlignLeft,
          QStringLiteral("%1  %2%").arg(formatMs(pass.ms)).arg(100.0 * pass.ms / scale, 0, 'f', 0));
      y += above ? lineH : rowH;
    }
  }

  void resizeEvent(QResizeEvent*) override { updateGeometry(); }

 private:
  bool namesAbove(int w) const { return w < besideWidth(); }
  int nameW(int w) const { return std::min(nameWidth(), w * 9 / 20); }
  /// A pass's name in the lines it is drawn on at width `w`.
  QStringList wrapped(const sl::PassTiming& pass, int w) const {
    const int room = namesAbove(w) ? w - 4 : nameW(w) - 6;
    return wrapLines(QString::fromStdString(pass.name), font(), room);
  }
  /// A row at width `w` whose name takes `lines` lines.
  int rowHeightOf(qsizetype lines, int w) const {
    const int lineH = fontMetrics().height() + 8, textH = fontMetrics().height();
    const int nameH = int(lines) * textH;
    return namesAbove(w) ? lineH + nameH + 2 : std::max(lineH, nameH + 8);
  }
  int rowHeight() const { return rowHeightOf(1, width()); }
  std::vector<sl::PassTiming> passes_;
  double totalMs_ = 0;
};

/// The total frame time of the last frames, newest on the right, with min/avg/max.
class FrameHistoryWidget : public QWidget {
 public:
  using QWidget::QWidget;
  static constexpr std::size_t kFrames = 180;

  void add(double ms) {
    frames_.push_back(ms);
    while (frames_.size() > kFrames) frames_.pop_front();
    update();
  }
  void clear() {
    frames_.clear();
    update();
  }
  QSize sizeHint() const override { return {260, 90}; }
  QSize minimumSizeHint() const override { return {120, 50}; }

 protected:
  void paintEvent(QPaintEvent*) override {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPalette& pal = palette();
    const QFontMetrics fm = fontMetrics();
    // The title's numbers wrap onto a second line in a narrow box, never elided.
    double lo = 0, hi = 0, avg = 0;
    QString title;
    if (!frames_.empty()) {
      lo = *std::min_element(frames_.begin(), frames_.end());
      hi = *std::max_element(frames_.begin(), frames_.end());
      avg = std::accumulate(frames_.begin(), frames_.end(), 0.0) / double(frames_.size());
      title = tr("min %1 · avg %2 · max %3").arg(formatMs(lo), formatMs(avg), formatMs(hi));
    }
    const int titleH =
        std::max(fm.height(), fm.boundingRect(QRect(0, 0, std::max(1, width() - 4), 100000),
                                              Qt::TextWordWrap | Qt::AlignLeft, title)
                                  .height());
    const QRectF area = QRectF(rect()).adjusted(2, titleH + 4, -2, -2);
    p.setPen(Qt::NoPen);
    p.setBrush(pal.color(QPalette::AlternateBase));
    p.drawRoundedRect(area, 3, 3);
    if (frames_.empty()) {
      p.setPen(pal.color(QPalette::Disabled, QPalette::Text));
      p.drawText(area, Qt::AlignCenter, tr("No frame yet"));
      return;
    }
    // Scale to the 90th percentile so that one slow frame (shader compile) does not
    // flatten the rest; taller frames are clipped at the top.
    std::vector<double> sorted(frames_.begin(), frames_.end());
    std::sort(sorted.begin(), sorted.end());
    const double p90 = sorted[std::min(sorted.size() - 1, sorted.size() * 9 / 10)];
    const double top = std::max(p90 * 1.4, 1e-3);
    p.setPen(pal.color(QPalette::Text));
    p.drawText(QRect(2, 0, width() - 4, titleH + 2),
               Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap, title);
    QPainterPath path;
    const double dx = area.width() / double(kFrames - 1);
    const double x0 = area.right() - dx * double(frames_.size() - 1);
    for (std::size_t i = 0; i < frames_.size(); ++i) {
      const QPointF pt(x0 + dx * double(i),
                       area.bottom() - area.height() * std::min(frames_[i] / top, 1.0));
      i == 0 ? path.moveTo(pt) : path.lineTo(pt);
    }
    QColor line = pal.color(QPalette::Highlight);
    p.setPen(QPen(line, 1.5));
    p.setBrush(Qt::NoBrush);
    p.drawPath(path);
    // Average as a dashed line.
    const double yAvg = area.bottom() - area.height() * avg / top;
    QColor avgColor = pal.color(QPalette::Text);
    avgColor.setAlpha(110);
    p.setPen(QPen(avgColor, 1, Qt::DashLine));
    p.drawLine(QPointF(area.left(), yAvg), QPointF(area.right(), yAvg));
  }

 private:
  std::deque<double> frames_;
};

TimingPanel::TimingPanel(QWidget* parent) : QWidget(parent) {
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(8, 4, 8, 6);
  outer->setSpacing(4);
  summary_ = new QLabel(tr("No frame yet"));
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  // Wrapped: the line grows with the frame (a split view's second technique, the timing
  // method), and unwrapped at a presenter's font it asked for more width than the screen.
  summary_->setWordWrap(true);
  outer->addWidget(summary_);

  auto* row = row_ = new QBoxLayout(QBoxLayout::LeftToRight);
  row->setSpacing(10);
  auto* passBox = new QGroupBox(tr("Passes (current frame)"));
  auto* passLayout = new QVBoxLayout(passBox);
  passes_ = new PassBarsWidget;
  passLayout->addWidget(passes_);
  passLayout->addStretch(1);
  row->addWidget(passBox, 4);

  auto* historyBox =
      new QGroupBox(tr("Frame time (last %1 frames)").arg(FrameHistoryWidget::kFrames));
  auto* historyLayout = new QVBoxLayout(historyBox);
  history_ = new FrameHistoryWidget;
  historyLayout->addWidget(history_);
  row->addWidget(historyBox, 3);

  auto* memoryBox = new QGroupBox(tr("Shadow memory"));
  auto* memoryLayout = new QVBoxLayout(memoryBox);
  memory_ = new QTreeWidget;
  memory_->setRootIsDecorated(false);
  memory_->setUniformRowHeights(true);
  memory_->setAlternatingRowColors(true);
  memory_->setHeaderLabels({tr("Resource"), tr("Format"), tr("Size"), tr("Bytes")});
  // Every column as wide as its widest cell (a narrow box scrolls sideways): a resource's
  // name or its bytes are never elided.
  memory_->setTextElideMode(Qt::ElideNone);
  memory_->header()->setStretchLastSection(false);
  memory_->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
  memory_->header()->setMinimumSectionSize(60);
  memoryLayout->addWidget(memory_);
  memoryTotal_ = new QLabel;
  memoryLayout->addWidget(memoryTotal_);
  row->addWidget(memoryBox, 4);
  outer->addLayout(row, 1);
  outer->setSizeConstraint(QLayout::SetNoConstraint);  // minimumSizeHint below decides
}

QSize TimingPanel::minimumSizeHint() const {
  // Narrow: the boxes one above the other (the widest box's width); short: side by side (the
  // tallest box's height). The panel arranges itself for the shape it is given.
  int w = summary_->minimumSizeHint().width(), h = 0;
  for (int i = 0; i < row_->count(); ++i)
    if (const QWidget* box = row_->itemAt(i)->widget()) {
      w = std::max(w, box->minimumSizeHint().width());
      h = std::max(h, box->minimumSizeHint().height());
    }
  const QMargins m = layout()->contentsMargins();
  return {w + m.left() + m.right(),
          summary_->minimumSizeHint().height() + layout()->spacing() + h + m.top() + m.bottom()};
}

QString TimingPanel::summaryText() const {
  return summary_->text();
}

void TimingPanel::showStats(const sl::FrameStats& stats, const QString& failure) {
  if (!failure.isEmpty()) {
    // A failed frame has no time: n/a and why, never a number (nor a bar or a history point).
    summary_->setText(tr("Frame %1  ·  %2 × %3 px  ·  total <b>n/a</b> (the frame failed: %4)")
                          .arg(stats.frameIndex)
                          .arg(stats.width)
                          .arg(stats.height)
                          .arg(failure.toHtmlEscaped()));
    passes_->setToolTip({});
    passes_->setPasses({}, 0.0);
    arrangeBoxes();
    return;
  }
  summary_->setText(tr("Frame %1  ·  %2 × %3 px  ·  total <b>%4</b>  ·  timing: %5")
                        .arg(stats.frameIndex)
                        .arg(stats.width)
                        .arg(stats.height)
                        .arg(formatMs(stats.totalMs))
                        .arg(stats.timingMethod.empty()
                                 ? tr("unknown")
                                 : QString::fromStdString(stats.timingMethod)) +
                    tr("  ·  panels read back %1").arg(formatBytes(stats.publicationBytes)));
  // Bars in the declared frame order, named by their declared titles (an undeclared timer
  // scope keeps its id); the explanations in the tooltip.
  std::vector<sl::PassTiming> rows;
  QString tip;
  std::vector<bool> used(stats.passes.size(), false);
  for (const sl::PassDecl& d : declared_) {
    for (std::size_t i = 0; i < stats.passes.size(); ++i) {
      if (used[i] || stats.passes[i].name != d.id) continue;
      used[i] = true;
      rows.push_back({d.title, stats.passes[i].ms});
      tip += QStringLiteral("<p><b>%1</b> <code>%2</code><br>%3</p>")
                 .arg(QString::fromStdString(d.title).toHtmlEscaped(),
                      QString::fromStdString(d.id).toHtmlEscaped(),
                      QString::fromStdString(d.explanation).toHtmlEscaped());
      break;
    }
  }
  for (std::size_t i = 0; i < stats.passes.size(); ++i)
    if (!used[i]) rows.push_back(stats.passes[i]);
  passes_->setToolTip(tip);
  passes_->setPasses(std::move(rows), stats.totalMs);
  arrangeBoxes();
  history_->add(stats.totalMs);

  // The memory list only changes with the technique or its parameters.
  QStringList key;
  for (const sl::ResourceInfo& r : stats.memory.resources)
    key << QStringLiteral("%1|%2|%3x%4x%5|%6")
               .arg(QString::fromStdString(r.name), QString::fromStdString(r.format))
               .arg(r.width)
               .arg(r.height)
               .arg(r.layers)
               .arg(r.bytes);
  if (key == memoryKey_) return;
  memoryKey_ = key;
  memory_->clear();
  for (const sl::ResourceInfo& r : stats.memory.resources) {
    QString size = QStringLiteral("%1 × %2").arg(r.width).arg(r.height);
    if (r.layers > 1) size += QStringLiteral(" × %1").arg(r.layers);
    auto* item =
        new QTreeWidgetItem({QString::fromStdString(r.name), QString::fromStdString(r.format), size,
                             formatBytes(r.bytes)});
    item->setToolTip(0, tr("%1 texels").arg(formatCount(r.texels)));
    for (int c = 2; c < 4; ++c) item->setTextAlignment(c, Qt::AlignRight | Qt::AlignVCenter);
    memory_->addTopLevelItem(item);
  }
  QString total = tr("Technique: %1 texels, %2")
                      .arg(formatCount(stats.memory.texels()), formatBytes(stats.memory.bytes()));
  if (const std::uint64_t debug = stats.memory.debugViewBytes())
    total += tr("; debug views (held while a panel shows them): %1").arg(formatBytes(debug));
  memoryTotal_->setText(total);
}

void TimingPanel::setTechnique(const sl::TechniqueInfo* technique) {
  declared_ = technique ? sl::framePassDecls(*technique) : std::vector<sl::PassDecl>{};
}

void TimingPanel::resetHistory() {
  history_->clear();
}

QStringList TimingPanel::passNames() const {
  return passes_->names();
}

QStringList TimingPanel::shownPassNames() const {
  return passes_->shownNames();
}

bool TimingPanel::stacked() const {
  return row_->direction() == QBoxLayout::TopToBottom;
}

void TimingPanel::arrangeBoxes() {
  // Side by side the pass bars get 4/11 of the width; when that is too narrow for the names
  // beside their bars (a narrow dock, presenter mode's large fonts), one box above the other.
  const bool narrow = width() * 4 / 11 < passes_->besideWidth();
  const auto direction = narrow ? QBoxLayout::TopToBottom : QBoxLayout::LeftToRight;
  if (row_->direction() != direction) row_->setDirection(direction);
}

void TimingPanel::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  arrangeBoxes();
}

void TimingPanel::changeEvent(QEvent* event) {
  QWidget::changeEvent(event);
  if (event->type() == QEvent::FontChange) arrangeBoxes();
}

}  // namespace sl::ui
