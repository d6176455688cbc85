// The Pages panel (see PagesPanel.h).
#include "PagesPanel.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <array>
#include <cmath>

#include <QComboBox>
#include <QHBoxLayout>
#include <QJsonObject>
#include <QLabel>
#include <QSpinBox>
#include <QVBoxLayout>

#include "algo/pages/PageViews.h"

namespace sl::ui {

namespace {
enum View { Table = 0, Served, Heat, PoolLevels, PoolDepth };
constexpr std::size_t kHistory = 300;  ///< frames of pool use kept

/// Every page-table state (pages::PageState 0..8): its colour, legend text and name in
/// drawnValues. RMSM's frames use 0..3, ASM's cache 0 and 4..8.
struct StateStyle {
  pages::PageState state;
  QRgb colour;
  const char* legend;
  const char* id;
};
constexpr StateStyle kStates[pages::kPageStates] = {
    {pages::PageState::Empty, qRgb(40, 40, 44), "empty", "empty"},
    {pages::PageState::Requested, qRgb(60, 190, 90), "requested", "requested"},
    {pages::PageState::Fallback, qRgb(70, 110, 230),
     "allocated unasked (top level, ancestor of coarsened)", "fallback"},
    {pages::PageState::Coarsened, qRgb(230, 60, 50), "requested, coarsened (pool ran out)",
     "coarsened"},
    {pages::PageState::New, qRgb(120, 230, 70), "allocated this frame", "new"},
    {pages::PageState::CachedHit, qRgb(40, 180, 210), "cached, used (hit)", "cached_hit"},
    {pages::PageState::CachedIdle, qRgb(60, 80, 150), "cached, unused", "cached_idle"},
    {pages::PageState::Evicted, qRgb(245, 150, 30), "evicted this frame", "evicted"},
    {pages::PageState::Pending, qRgb(225, 50, 150), "requested, not allocated (budget, pool)",
     "requested_waiting"},
};

const StateStyle& styleOf(float v) {
  const int i = int(v);
  return kStates[i >= 0 && i < pages::kPageStates ? i : 0];
}

/// One level of the page table as drawn (row 0 at the bottom).
QImage tableImage(const sl::FloatImage& t) {
  QImage img(t.width, t.height, QImage::Format_RGB32);
  for (int y = 0; y < t.height; ++y)
    for (int x = 0; x < t.width; ++x)
      img.setPixel(x, t.height - 1 - y, styleOf(t.values[size_t(y) * t.width + x]).colour);
  return img;
}

/// The legend of `states` as rich text.
QString legendText(std::initializer_list<pages::PageState> states) {
  QStringList parts;
  for (pages::PageState s : states) {
    const StateStyle& st = kStates[int(s)];
    parts << QStringLiteral("<span style='color:%1'>■</span> %2")
                 .arg(QColor(st.colour).name(), QObject::tr(st.legend));
  }
  return parts.join(QStringLiteral(", "));
}

constexpr int kInfoEms = 30;  ///< the least width (em) the counts are put beside the image at
}  // namespace

PagesPanel::PagesPanel(QWidget* parent) : PublicationPanel(parent) {
  auto [content, layout] = newPanelColumn();
  auto* row = new QHBoxLayout;
  viewChoice_ = new QComboBox;
  viewChoice_->setObjectName(QStringLiteral("pagesView"));
  viewChoice_->addItems({tr("Page table at level"), tr("Level serving each page"),
                         tr("Requests (heat map)"), tr("Pool: each slot's level"),
                         tr("Pool: depth")});
  row->addWidget(viewChoice_, 1);
  level_ = new QSpinBox;
  level_->setObjectName(QStringLiteral("pagesLevel"));
  level_->setRange(0, 0);
  level_->setToolTip(tr("Quadtree level (0 = the finest pages)"));
  row->addWidget(level_);
  layout->addLayout(row);
  view_ = new ImageView;
  view_->setObjectName(QStringLiteral("pagesImage"));
  use_ = new PlotWidget;
  use_->setObjectName(QStringLiteral("pagesUse"));
  use_->setTitle(tr("Pool use over time"));
  use_->setAxisLabels(tr("frame"), tr("pages"));
  use_->setPlaceholder(tr("no frames yet"));
  layout->addWidget(use_);
  info_ = new WrappedLabel;
  info_->setObjectName(QStringLiteral("pagesInfo"));
  info_->setTextFormat(Qt::RichText);
  info_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  // The counts and the table's colours beside the image where the panel is wide, else under
  // it; the pool's use over time at the bottom.
  layout->insertWidget(layout->indexOf(use_), new BesideWhenWide(view_, info_, kInfoEms), 1);
  setContent(content);
  connect(viewChoice_, &QComboBox::currentIndexChanged, this, [this] { redraw(); });
  connect(level_, &QSpinBox::valueChanged, this, [this] { redraw(); });
}

std::set<std::string> PagesPanel::observedKeys() const {
  // asm.*: the cache's own counts, shown next to the cells the table draws.
  return {"pages.table.*",      "pages.served",     "pages.requests.heat",
          "pages.pool.levels",  "pages.pool.depth", "pages.pool.columns",
          "pages.requested",    "pages.allocated",  "pages.coarsened",
          "pages.pool",         "pages.superpages", "pages.requests.compacted",
          "pages.scene_draws",  "asm.new",          "asm.hits",
          "asm.evicted",        "asm.stop",         "asm.requests.left",
          "asm.iterations.run", "asm.cap.stops"};
}

void PagesPanel::showPublication(const sl::Publication& pub) {
  auto number = [&](const char* key) { return pub.number(key, -1.0); };
  images_.clear();
  levels_ = 0;
  for (const auto& [key, image] : pub.images)
    if (key.rfind("pages.", 0) == 0) {
      images_[key] = image;
      if (key.rfind("pages.table.", 0) == 0) ++levels_;
    }
  auto curve = pub.curves.find("pages.pool.levels");
  poolLevels_ = curve == pub.curves.end() ? std::vector<float>{} : curve->second;
  poolColumns_ = std::max(1, int(number("pages.pool.columns")));
  if (images_.empty() && poolLevels_.empty()) {
    drawn_ = {};
    showContent(false, noDataText(QString::fromStdString(pub.techniqueId), tr("shadow-map pages"),
                                  observedKeys()));
    return;
  }
  showContent(true);
  level_->setRange(0, std::max(levels_ - 1, 0));
  const bool newLayout = levels_ != shownLevels_;
  shownLevels_ = levels_;
  const double requested = number("pages.requested"), allocated = number("pages.allocated"),
               pool = number("pages.pool"), coarsened = number("pages.coarsened");
  // Every level's cells as drawn, counted by colour: a cache (ASM) draws states 4..8.
  std::array<int, pages::kPageStates> cells{};
  int finestUsed = -1;  // the finest level with a page in any state but empty
  for (const auto& [key, image] : images_) {
    if (key.rfind("pages.table.", 0) != 0) continue;
    const QImage img = tableImage(image);
    bool used = false;
    for (int y = 0; y < img.height(); ++y)
      for (int x = 0; x < img.width(); ++x)
        for (const StateStyle& st : kStates)
          if (img.pixel(x, y) == st.colour) {
            ++cells[std::size_t(st.state)];
            used = used || st.state != pages::PageState::Empty;
          }
    const int level = std::atoi(key.c_str() + std::strlen("pages.table."));
    if (used && (finestUsed < 0 || level < finestUsed)) finestUsed = level;
  }
  // A new technique or layout opens on the finest level that holds pages (level 0 may be
  // empty: ASM from a coarse map); after that the level is the user's.
  if (newLayout && finestUsed >= 0) level_->setValue(finestUsed);
  auto count = [&](pages::PageState s) { return cells[std::size_t(s)]; };
  using PS = pages::PageState;
  const bool cache = count(PS::New) + count(PS::CachedHit) + count(PS::CachedIdle) +
                         count(PS::Evicted) + count(PS::Pending) >
                     0;
  if (cache)
    info_->setText(
        tr("Page cache: %1 request keys after dedup (all iterations), %2 unique pages "
           "requested; <b>%3 of %4</b> pool pages held: %5 allocated this frame, %6 cached "
           "and used, %7 cached unused; %8 evicted this frame, %9 requested, not allocated."
           "<br>Page table: ")
            .arg(number("pages.requests.compacted"))
            .arg(requested)
            .arg(allocated)
            .arg(pool)
            .arg(count(PS::New))
            .arg(count(PS::CachedHit))
            .arg(count(PS::CachedIdle))
            .arg(count(PS::Evicted))
            .arg(count(PS::Pending)) +
        legendText({PS::New, PS::Pending, PS::CachedHit, PS::CachedIdle, PS::Evicted, PS::Empty}) +
        QStringLiteral("."));
  else
    info_->setText(tr("%1 requests after dedup, %2 unique pages; <b>%3 of %4</b> pool pages "
                      "used, %5 superpages, %7 scene draws; <b>%6</b> requests coarsened (pool ran "
                      "out).<br>Page "
                      "table: ")
                       .arg(number("pages.requests.compacted"))
                       .arg(requested)
                       .arg(allocated)
                       .arg(pool)
                       .arg(number("pages.superpages"))
                       .arg(coarsened)
                       .arg(number("pages.scene_draws")) +
                   legendText({PS::Requested, PS::Fallback, PS::Coarsened, PS::Empty}) +
                   QStringLiteral("."));
  if (!history_.empty() && double(pub.frameIndex) <= history_.back().frame) history_.clear();
  history_.push_back({double(pub.frameIndex), allocated, requested, pool, double(count(PS::New)),
                      double(count(PS::Evicted))});
  while (history_.size() > kHistory) history_.pop_front();
  // ASM's refinement loop: why it stopped this frame, and in how many frames since the pages
  // were last dropped the iteration cap stopped it (never silent, even once later frames, or
  // frames before this panel opened, converged).
  const double stop = number("asm.stop"), left = number("asm.requests.left");
  const double capStops = cache ? number("asm.cap.stops") : -1.0;
  if (cache && stop >= 0.0) {
    QString why;
    if (stop == 0.0)
      why = tr("converged (no page requested)");
    else if (stop == 1.0)
      why = tr("<b><font color=\"#e04030\">stopped by the iteration cap: %1 pages still "
               "requested</font></b>")
                .arg(left);
    else if (stop == 2.0)
      why = tr("the per-frame page budget was spent: %1 requests wait").arg(left);
    else
      why = tr("the pool held only pages used this frame: %1 requests refused").arg(left);
    QString line = tr("<br>Refinement loop this frame: iterations run %1; %2.")
                       .arg(number("asm.iterations.run"))
                       .arg(why);
    if (capStops > 0)
      line += tr(" <b>Frames the iteration cap stopped since the pages were last dropped: %1</b>.")
                  .arg(capStops);
    info_->setText(info_->text() + line);
  }
  PlotWidget::Series used{cache ? tr("held") : tr("allocated"), {}, QColor(60, 190, 90)};
  PlotWidget::Series asked{tr("unique pages requested"), {}, QColor(230, 60, 50)};
  PlotWidget::Series fresh{tr("allocated this frame"), {}, QColor(kStates[int(PS::New)].colour)};
  PlotWidget::Series gone{tr("evicted this frame"), {}, QColor(kStates[int(PS::Evicted)].colour)};
  for (const FrameUse& f : history_) {
    used.points.emplace_back(f.frame, f.allocated);
    asked.points.emplace_back(f.frame, f.requested);
    fresh.points.emplace_back(f.frame, f.fresh);
    gone.points.emplace_back(f.frame, f.evicted);
  }
  if (cache)
    use_->setSeries({used, asked, fresh, gone});
  else
    use_->setSeries({used, asked});
  use_->setLines({{pool, QColor(200, 200, 200), tr("pool.pages")}});
  QJsonObject drawnCells;
  for (const StateStyle& st : kStates) drawnCells[QLatin1String(st.id)] = count(st.state);
  drawn_ = {{QStringLiteral("frames"), int(history_.size())},
            {QStringLiteral("levels"), levels_},
            {QStringLiteral("requested"), requested},
            {QStringLiteral("allocated"), allocated},
            {QStringLiteral("pool"), pool},
            {QStringLiteral("coarsened"), coarsened},
            {QStringLiteral("cache"), cache},
            {QStringLiteral("loop_stop"), cache ? stop : -1.0},
            {QStringLiteral("loop_requests_left"), cache ? left : -1.0},
            {QStringLiteral("cap_stops"), capStops},
            {QStringLiteral("cells"), drawnCells}};
  redraw();
}

void PagesPanel::redraw() {
  const int v = viewChoice_->currentIndex();
  level_->setEnabled(v == Table);
  auto find = [&](const std::string& key) -> const sl::FloatImage* {
    auto it = images_.find(key);
    return it == images_.end() || it->second.width <= 0 ? nullptr : &it->second;
  };
  if (v == Table) {
    const sl::FloatImage* t = find("pages.table." + std::to_string(level_->value()));
    if (!t) return view_->clearImage(tr("no page table published"));
    view_->setImage(tableImage(*t), t->width, t->height);
    view_->setLegend({}, ColorMap::Grey, QString(), false);
    auto copy = std::make_shared<sl::FloatImage>(*t);
    view_->setValueReader([copy](int x, int y) {
      return QObject::tr("page (%1, %2): %3")
          .arg(x)
          .arg(y)
          .arg(QObject::tr(styleOf(copy->values[size_t(y) * copy->width + x]).legend));
    });
    view_->setCaption(
        tr("page table, level %1 (%2 x %2 pages)").arg(level_->value()).arg(t->width));
    return;
  }
  sl::FloatImage shown;
  ColorMap map = ColorMap::Viridis;
  QString caption, unit;
  ValueRange range;
  if (v == PoolLevels) {
    if (poolLevels_.empty()) return view_->clearImage(tr("no pool published"));
    shown.width = poolColumns_;
    shown.height = int((poolLevels_.size() + size_t(poolColumns_) - 1) / size_t(poolColumns_));
    shown.values.assign(size_t(shown.width) * size_t(shown.height), std::nanf(""));
    std::copy(poolLevels_.begin(), poolLevels_.end(), shown.values.begin());
    range = {0.0f, float(std::max(levels_ - 1, 1))};
    caption = tr("pool slots (row 0 at the bottom): level held, black = free");
    unit = tr("level");
  } else {
    const char* key = v == Served ? "pages.served"
                      : v == Heat ? "pages.requests.heat"
                                  : "pages.pool.depth";
    const sl::FloatImage* img = find(key);
    if (!img) return view_->clearImage(tr("not published"));
    shown = displayCopy(*img, 1024);
    if (v == Served) {
      range = {0.0f, float(std::max(levels_ - 1, 1))};
      caption = tr("level serving each finest page");
      unit = tr("level");
    } else if (v == Heat) {
      range = finiteRange(shown.values);
      caption = tr("requests per finest page (after dedup, all levels)");
      unit = tr("requests");
    } else {
      range = finiteRange(shown.values, 1, 0, 1.0f);
      map = ColorMap::Grey;
      caption = tr("pool depth (pages side by side)");
    }
  }
  view_->setImage(colorize(shown, 0, range, map), shown.width, shown.height);
  view_->setLegend(range, map, unit, true);
  auto copy = std::make_shared<sl::FloatImage>(shown);
  view_->setValueReader([copy](int x, int y) {
    return formatValue(copy->values[size_t(y) * size_t(copy->width) + size_t(x)]);
  });
  view_->setCaption(caption);
}

void PagesPanel::highlightPass(const QString& passId) {
  // RMSM's and ASM's passes (both publish their page table and pool here).
  view_->setHighlighted(passId.startsWith(QLatin1String("rmsm")) ||
                        passId.startsWith(QLatin1String("asm")));
}

QJsonObject PagesPanel::drawnValues() const {
  return drawn_;
}

}  // namespace sl::ui
