// The FVSM panel (see FvsmPanel.h).
#include "FvsmPanel.h"

#include <algorithm>
#include <map>

#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QScrollArea>
#include <QVBoxLayout>

#include "window/Theme.h"

namespace sl::ui {

namespace {
constexpr int kChannelNeedU = 2, kChannelNeedV = 3;              // fvsm.smtmm: u, v, need u, need v
constexpr int kGridNeedU = 0, kGridNeedV = 1, kGridEntries = 2;  // fvsm.grid (gridChannels)

QColor leafColor(std::size_t k) {
  return QColor::fromHsv(int((k * 67) % 360), 200, 255);
}

/// The frame's part of the camera thumbnail (fvsm.camera: the frame from the bottom-left,
/// −2 beyond it), as its own image; empty when there is none.
sl::FloatImage framePart(const sl::FloatImage& thumb) {
  if (thumb.width <= 0 || thumb.height <= 0 || thumb.channels != 1) return {};
  int w = 0, h = 0;
  while (w < thumb.width && thumb.values[std::size_t(w)] > -1.5f) ++w;
  while (h < thumb.height && thumb.values[std::size_t(h) * thumb.width] > -1.5f) ++h;
  sl::FloatImage out{w, h, 1, {}};
  out.values.reserve(std::size_t(w) * std::size_t(h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      out.values.push_back(thumb.values[std::size_t(y) * thumb.width + x]);
  return out;
}
}  // namespace

FvsmPanel::FvsmPanel(QWidget* parent) : PublicationPanel(parent) {
  auto [content, layout] = newPanelColumn();
  // One captioned image view, added to `row`.
  const auto addView = [](QHBoxLayout* row, const QString& caption) {
    auto* view = new ImageView;
    view->setCaption(caption);
    row->addWidget(view);
    return view;
  };
  auto* views = new QHBoxLayout;
  camera_ = addView(views, tr("Camera image (unshadowed): each kd leaf's screen rectangle, where "
                              "its deferred shadowing runs"));
  light_ = addView(views, tr("Light's view (depth): the kd-tree's leaves, log2 texture size"));
  auto* maps = new QHBoxLayout;
  needU_ = addView(maps, tr("SMTMM (camera view): log2 texels needed along SM u; kd leaves' "
                            "screen rectangles"));
  needV_ = addView(maps, tr("SMTMM: log2 texels needed along SM v"));
  grid_ =
      addView(maps, tr("Tile grid over the light's view: need per cell; kd leaves (log2 texture)"));
  auto* lower = new QHBoxLayout;
  histogram_ = new PlotWidget;
  histogram_->setAxisLabels(tr("log2 need"), tr("SMTMM entries"));
  textures_ = new QLabel;
  textures_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  textures_->setWordWrap(true);
  textures_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  // The list of tile textures grows with the kd leaves: scrolled, so it never makes the panel
  // (and a presenter's window) taller than the screen.
  auto* texturesScroll = new QScrollArea;
  texturesScroll->setWidget(textures_);
  texturesScroll->setWidgetResizable(true);
  texturesScroll->setFrameShape(QFrame::NoFrame);
  texturesScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  lower->addWidget(histogram_, 2);
  lower->addWidget(texturesScroll, 1);
  numbers_ = new QLabel;
  numbers_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  numbers_->setWordWrap(true);
  layout->addLayout(views, 4);
  layout->addLayout(maps, 3);
  layout->addLayout(lower, 2);
  layout->addWidget(numbers_);
  setContent(content);
  // Screen rectangles (SMTMM entries, inclusive) over a view of the whole frame: the camera
  // image and the SMTMM.
  const auto drawScreenRects = [this](QPainter& p, const QRectF& r) {
    const glm::ivec2 t = smtmmSize_;
    if (t.x <= 0 || t.y <= 0) return;
    for (std::size_t k = 0; k < tiles_.size(); ++k) {
      const fvsm::EntryRect& s = tiles_[k].tile.screen;
      if (s.empty()) continue;
      const double x0 = r.left() + r.width() * s.min.x / t.x;
      const double x1 = r.left() + r.width() * (s.max.x + 1) / t.x;
      const double y0 = r.bottom() - r.height() * (s.max.y + 1) / t.y;
      const double y1 = r.bottom() - r.height() * s.min.y / t.y;
      p.setPen(QPen(leafColor(k), 1.2));
      p.setBrush(Qt::NoBrush);
      p.drawRect(QRectF(QPointF(x0, y0), QPointF(x1, y1)));
    }
  };
  needU_->setOverlay(drawScreenRects);
  camera_->setOverlay(drawScreenRects);
  // kd leaves (SM uv) over a view of the whole map: the light's depth and the tile grid, each
  // with its texture's log2 size; over the grid the selected cell too.
  const auto drawLeaves = [this](QPainter& p, const QRectF& r) {
    p.setFont(bodyRelativeFont(kSmallText, p.font()));
    for (std::size_t k = 0; k < tiles_.size(); ++k) {
      const fvsm::Tile& t = tiles_[k].tile;
      const glm::dvec2 lo = t.uvMin(), hi = t.uvMax();
      const QRectF cell(QPointF(r.left() + r.width() * lo.x, r.bottom() - r.height() * hi.y),
                        QPointF(r.left() + r.width() * hi.x, r.bottom() - r.height() * lo.y));
      p.setPen(QPen(leafColor(k), 1.4));
      p.setBrush(Qt::NoBrush);
      p.drawRect(cell);
      if (cell.width() > 34 && cell.height() > 14) {
        p.setPen(Qt::white);
        p.drawText(cell.adjusted(2, 1, -1, -1), Qt::AlignLeft | Qt::AlignTop,
                   QStringLiteral("%1x%2").arg(t.textureLog2.x).arg(t.textureLog2.y));
      }
    }
  };
  light_->setOverlay(drawLeaves);
  grid_->setOverlay([this, drawLeaves](QPainter& p, const QRectF& r) {
    drawLeaves(p, r);
    const QSize n = grid_->texelSize();
    if (cellX_ >= 0 && !n.isEmpty()) {
      const double w = r.width() / n.width(), h = r.height() / n.height();
      p.setPen(QPen(Qt::white, 2.0, Qt::DashLine));
      p.drawRect(QRectF(r.left() + cellX_ * w, r.bottom() - (cellY_ + 1) * h, w, h));
    }
  });
}

std::set<std::string> FvsmPanel::observedKeys() const {
  return {"fvsm.smtmm",       "fvsm.tiles",          "fvsm.tiles.unmet",    "fvsm.need_log2.u",
          "fvsm.need_log2.v", "fvsm.texels",         "fvsm.grid",           "fvsm.grid.histogram",
          "fvsm.tiles.list",  "fvsm.histogram.eta0", "fvsm.histogram.eta1", "fvsm.camera",
          "fvsm.light.depth", "fvsm.tile_ms"};
}

void FvsmPanel::highlightPass(const QString& passId) {
  const bool smtmm = passId == QLatin1String("smtmm");
  const bool grid = passId == QLatin1String("fvsm grid");
  const bool pyramid = passId == QLatin1String("fvsm pyramid");
  const bool kdTree = passId == QLatin1String("fvsm kd-tree");
  needU_->setHighlighted(smtmm);
  needV_->setHighlighted(smtmm);
  // The grid and its histograms; the pyramid is built over the grid; the kd leaves are drawn
  // over the grid and the light's view.
  grid_->setHighlighted(grid || pyramid || kdTree);
  histogram_->setHighlighted(grid);
  // The kd leaves are rendered over the light's view, applied inside their rectangles.
  light_->setHighlighted(kdTree || passId == QLatin1String("tile depth"));
  camera_->setHighlighted(passId == QLatin1String("tile apply"));
}

void FvsmPanel::selectCell(int x, int y) {
  const int n = gridImage_.width;
  if (n <= 0 || x < 0 || y < 0 || x >= n || y >= n) return;
  cellX_ = x;
  cellY_ = y;
  drawHistogram();
}

void FvsmPanel::drawHistogram() {
  const int buckets = eta1_ - eta0_ + 1;
  const int n = histImage_.width;
  if (cellX_ < 0 || n <= 0 || histImage_.channels != 2 * buckets) {
    histogram_->setSeries({});
    histogram_->setPlaceholder(tr("no histogram"));
    return;
  }
  const float* h = &histImage_.values[(std::size_t(cellY_) * n + cellX_) * histImage_.channels];
  const float* g = &gridImage_.values[(std::size_t(cellY_) * n + cellX_) * fvsm::kGridChannels];
  std::vector<PlotWidget::Series> series = {{tr("along u"), {}, QColor(80, 170, 255)},
                                            {tr("along v"), {}, QColor(255, 150, 60)}};
  double total[2] = {0.0, 0.0};
  for (int axis = 0; axis < 2; ++axis) {
    for (int b = 0; b < buckets; ++b) {
      const double c = h[axis * buckets + b];
      total[axis] += c;
      // A step per bucket: bucket b spans need η0 + b − ½ .. η0 + b + ½.
      series[std::size_t(axis)].points.push_back({eta0_ + b - 0.5, c});
      series[std::size_t(axis)].points.push_back({eta0_ + b + 0.5, c});
    }
  }
  histogram_->setTitle(tr("cell (%1, %2): %3 entries, need 2^%4 x 2^%5 (end buckets ≤ %6, ≥ %7)")
                           .arg(cellX_)
                           .arg(cellY_)
                           .arg(g[kGridEntries])
                           .arg(g[kGridNeedU])
                           .arg(g[kGridNeedV])
                           .arg(eta0_)
                           .arg(eta1_));
  histogram_->setXRange(eta0_ - 0.5, eta1_ + 0.5);
  histogram_->setSeries(std::move(series));
  drawn_["cell_x"] = cellX_;
  drawn_["cell_y"] = cellY_;
  drawn_["cell_entries"] = double(g[kGridEntries]);
  drawn_["hist_u_total"] = total[0];
  drawn_["hist_v_total"] = total[1];
}

void FvsmPanel::showPublication(const sl::Publication& pub) {
  const auto img = pub.images.find("fvsm.smtmm");
  const auto& n = pub.numbers;
  if (img == pub.images.end() || img->second.channels != 4 || !n.count("fvsm.tiles")) {
    drawn_ = {};
    showContent(false,
                noDataText(QString::fromStdString(pub.techniqueId), tr("FVSM"), observedKeys()));
    return;
  }
  showContent(true);
  drawn_ = {};
  const auto number = [&](const char* key) { return n.count(key) ? n.at(key) : -1.0; };
  eta0_ = int(number("fvsm.histogram.eta0"));
  eta1_ = int(number("fvsm.histogram.eta1"));
  tiles_.clear();
  if (auto c = pub.curves.find("fvsm.tiles.list"); c != pub.curves.end()) {
    try {
      tiles_ = fvsm::unpackTileRecords(c->second);
    } catch (const std::invalid_argument&) {
      tiles_.clear();  // a malformed list draws nothing rather than garbage
    }
  }
  // Per-leaf (depth, apply) ms in the leaves' order; only when it lists exactly these leaves
  // (with timer queries it is a frame older than the list).
  std::vector<float> tileMs;
  if (auto c = pub.curves.find("fvsm.tile_ms");
      c != pub.curves.end() && c->second.size() == 2 * tiles_.size())
    tileMs = c->second;
  const sl::FloatImage& smtmm = img->second;
  smtmmSize_ = {smtmm.width, smtmm.height};
  int cameraRects = 0, lightLeaves = 0;
  sl::FloatImage camera;
  if (auto c = pub.images.find("fvsm.camera"); c != pub.images.end()) camera = framePart(c->second);
  if (camera.width > 0 && camera.height > 0) {
    // −1 (no surface) below the range: drawn black.
    camera_->setImage(colorize(camera, 0, ValueRange{0.0f, 1.0f, false}, ColorMap::Grey),
                      camera.width, camera.height);
    camera_->setLegend({}, ColorMap::Grey, {}, false);
    for (const fvsm::TileRecord& t : tiles_) cameraRects += t.tile.screen.empty() ? 0 : 1;
    drawn_["camera_surface_texels"] = double(std::count_if(
        camera.values.begin(), camera.values.end(), [](float v) { return v >= 0.0f; }));
  } else {
    camera_->clearImage(tr("no camera image published"));
  }
  if (auto l = pub.images.find("fvsm.light.depth");
      l != pub.images.end() && l->second.width > 0 && l->second.channels == 1) {
    const sl::FloatImage& depth = l->second;
    const ValueRange range = finiteRange(depth.values, 1, 0, 1.0f);  // 1: nothing there
    light_->setImage(colorize(depth, 0, range, ColorMap::Grey), depth.width, depth.height);
    light_->setLegend(range, ColorMap::Grey, tr("depth"));
    light_->setValueReader([depth](int x, int y) {
      return QStringLiteral("depth %1")
          .arg(double(depth.values[std::size_t(y) * depth.width + x]), 0, 'f', 4);
    });
    lightLeaves = int(tiles_.size());
    drawn_["light_geometry_texels"] = double(
        std::count_if(depth.values.begin(), depth.values.end(), [](float v) { return v < 1.0f; }));
    drawn_["light_w"] = depth.width;
    drawn_["light_h"] = depth.height;
  } else {
    light_->clearImage(tr("no light view published"));
  }
  drawn_["camera_w"] = camera.width;
  drawn_["camera_h"] = camera.height;
  drawn_["camera_rects_drawn"] = cameraRects;
  drawn_["light_leaves_drawn"] = lightLeaves;
  float maxNeed = 0.0f;
  for (std::size_t i = 0; i + 3 < smtmm.values.size(); i += 4)
    maxNeed = std::max({maxNeed, smtmm.values[i + kChannelNeedU], smtmm.values[i + kChannelNeedV]});
  // Empty entries hold −1: below the range, drawn as its lowest colour.
  const ValueRange range{0.0f, std::max(maxNeed, 1.0f), false};
  for (auto [view, channel] : {std::pair{needU_, kChannelNeedU}, {needV_, kChannelNeedV}}) {
    view->setImage(colorize(smtmm, channel, range, ColorMap::Viridis), smtmm.width, smtmm.height);
    view->setLegend(range, ColorMap::Viridis, tr("log2 texels"));
    view->setValueReader([smtmm, ch = channel](int x, int y) {
      const float v = smtmm.values[(std::size_t(y) * smtmm.width + x) * 4 + ch];
      return v < 0.0f ? QStringLiteral("no surface") : QStringLiteral("2^%1").arg(int(v));
    });
  }
  int rects = 0;
  for (const fvsm::TileRecord& t : tiles_) rects += t.tile.screen.empty() ? 0 : 1;

  // The grid: the larger of the two needs per cell.
  gridImage_ = {};
  histImage_ = {};
  const auto g = pub.images.find("fvsm.grid");
  if (g != pub.images.end() && g->second.channels == fvsm::kGridChannels && g->second.width > 0) {
    gridImage_ = g->second;
    if (auto h = pub.images.find("fvsm.grid.histogram"); h != pub.images.end())
      histImage_ = h->second;
    const int cells = gridImage_.width * gridImage_.height;
    sl::FloatImage need{gridImage_.width, gridImage_.height, 1, {}};
    need.values.resize(std::size_t(cells));
    float maxCell = 1.0f;
    int neediest = 0;
    for (int i = 0; i < cells; ++i) {
      const float* c = &gridImage_.values[std::size_t(i) * fvsm::kGridChannels];
      need.values[std::size_t(i)] = std::max(c[kGridNeedU], c[kGridNeedV]);
      if (need.values[std::size_t(i)] > maxCell) maxCell = need.values[std::size_t(i)];
      if (need.values[std::size_t(i)] > need.values[std::size_t(neediest)]) neediest = i;
    }
    const ValueRange gridRange{0.0f, maxCell, false};
    grid_->setImage(colorize(need, 0, gridRange, ColorMap::Viridis), need.width, need.height);
    grid_->setLegend(gridRange, ColorMap::Viridis, tr("log2 need"));
    grid_->setValueReader([this, gi = gridImage_, tileMs](int x, int y) {
      // The readout of the cell under the cursor also selects it for the histogram (drawn
      // in its own widget; the grid's selection outline follows on its next repaint).
      if (x != cellX_ || y != cellY_) {
        userCell_ = true;
        selectCell(x, y);
      }
      const float* c = &gi.values[(std::size_t(y) * gi.width + x) * fvsm::kGridChannels];
      if (c[kGridEntries] <= 0.0f) return tr("no entry");
      QString s = tr("need 2^%1 x 2^%2 (max 2^%3 x 2^%4), %5 entries")
                      .arg(c[kGridNeedU])
                      .arg(c[kGridNeedV])
                      .arg(c[3])
                      .arg(c[4])
                      .arg(c[kGridEntries]);
      const glm::dvec2 uv((x + 0.5) / gi.width, (y + 0.5) / gi.height);
      for (std::size_t k = 0; k < tiles_.size(); ++k) {
        const fvsm::TileRecord& t = tiles_[k];
        const glm::dvec2 lo = t.tile.uvMin(), hi = t.tile.uvMax();
        if (uv.x < lo.x || uv.y < lo.y || uv.x >= hi.x || uv.y >= hi.y) continue;
        s += tr("; leaf %1: texture %2x%3 in %4x%5%6")
                 .arg(k)
                 .arg(t.texture.viewport.x)
                 .arg(t.texture.viewport.y)
                 .arg(t.texture.size.x)
                 .arg(t.texture.size.y)
                 .arg(t.tile.unmet ? tr(" (unmet)") : QString());
        if (2 * k + 1 < tileMs.size())
          s += tr(", depth %1 ms + apply %2 ms")
                   .arg(double(tileMs[2 * k]), 0, 'f', 1)
                   .arg(double(tileMs[2 * k + 1]), 0, 'f', 1);
      }
      return s;
    });
    if (!userCell_ || cellX_ >= gridImage_.width || cellY_ >= gridImage_.height) {
      cellX_ = neediest % gridImage_.width;
      cellY_ = neediest / gridImage_.width;
    }
    drawn_["grid_n"] = gridImage_.width;
    drawHistogram();
  } else {
    grid_->clearImage(tr("no tile grid published"));
    histogram_->setSeries({});
    histogram_->setPlaceholder(tr("no tile grid published"));
  }

  // The textures the leaves used: viewport in texture, how many leaves each.
  std::map<std::pair<std::pair<int, int>, std::pair<int, int>>, int> kinds;
  for (const fvsm::TileRecord& t : tiles_)
    ++kinds[{{t.texture.size.x, t.texture.size.y}, {t.texture.viewport.x, t.texture.viewport.y}}];
  QString text = tr("Tile textures (viewport in texture: leaves):");
  for (const auto& [k, count] : kinds) {
    text += QStringLiteral("\n  %1x%2 in %3x%4: %5")
                .arg(k.second.first)
                .arg(k.second.second)
                .arg(k.first.first)
                .arg(k.first.second)
                .arg(count);
  }
  // The leaves' times (fvsm.tile_ms), dearest first: what each leaf cost to render and apply.
  double tileMsSum = 0.0;
  if (!tileMs.empty()) {
    std::vector<std::size_t> order(tiles_.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
      order[k] = k;
      tileMsSum += double(tileMs[2 * k]) + double(tileMs[2 * k + 1]);
    }
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return tileMs[2 * a] + tileMs[2 * a + 1] > tileMs[2 * b] + tileMs[2 * b + 1];
    });
    constexpr std::size_t kListed = 8;
    text += tr("\n\nTile times (depth + apply), %1 leaves, %2 ms in all; the dearest:")
                .arg(tiles_.size())
                .arg(tileMsSum, 0, 'f', 1);
    for (std::size_t i = 0; i < std::min(kListed, order.size()); ++i) {
      const std::size_t k = order[i];
      const fvsm::TileRecord& t = tiles_[k];
      text += QStringLiteral("\n  #%1 %2x%3: %4 + %5 ms")
                  .arg(k)
                  .arg(t.texture.viewport.x)
                  .arg(t.texture.viewport.y)
                  .arg(double(tileMs[2 * k]), 0, 'f', 1)
                  .arg(double(tileMs[2 * k + 1]), 0, 'f', 1);
    }
  } else {
    text += tr("\n\nTile times: not published for these leaves");
  }
  drawn_["tile_times_listed"] = double(tileMs.size() / 2);
  drawn_["tile_ms_sum"] = tileMsSum;
  textures_->setText(text);
  numbers_->setText(tr("kd leaves %1 (unmet at the finest level: %2)    whole map needs 2^%3 x "
                       "2^%4 texels    tile texels %5")
                        .arg(number("fvsm.tiles"))
                        .arg(number("fvsm.tiles.unmet"))
                        .arg(number("fvsm.need_log2.u"))
                        .arg(number("fvsm.need_log2.v"))
                        .arg(formatValue(number("fvsm.texels"))));
  drawn_["tiles"] = number("fvsm.tiles");
  drawn_["unmet"] = number("fvsm.tiles.unmet");
  drawn_["need_u"] = number("fvsm.need_log2.u");
  drawn_["need_v"] = number("fvsm.need_log2.v");
  drawn_["max_entry_need"] = double(maxNeed);
  drawn_["leaves_drawn"] = double(tiles_.size());
  drawn_["rects_drawn"] = rects;
  drawn_["texture_kinds"] = double(kinds.size());
  needU_->update();
  grid_->update();
  camera_->update();
  light_->update();
}

}  // namespace sl::ui
