// The FVSM panel (fitted virtual shadow maps, Giegl & Wimmer 2007), drawn from what the
// renderer publishes (never GL): the SMTMM as heat maps of the log2 resolution the whole
// virtual map needs along each SM axis (`fvsm.smtmm`) with each kd leaf's screen rectangle
// over it (`fvsm.tiles.list`; the SMTMM is the camera's view at one entry per block); the
// tile grid over the light's view (`fvsm.grid`: each cell's need after outlier rejection)
// with the kd-tree's leaves drawn as their SM rectangles, labelled with the log2 texture
// each was rendered at; the need histogram of the hovered (else the neediest) grid cell
// (`fvsm.grid.histogram`, end buckets η0, η1); the textures the leaves used (size, mode's
// viewport) and the frame's numbers.
#pragma once

#include <vector>

#include "algo/fvsm/Fvsm.h"
#include "panels/common/PanelKit.h"

class QLabel;

namespace sl::ui {

class FvsmPanel : public PublicationPanel {
  Q_OBJECT

 public:
  explicit FvsmPanel(QWidget* parent = nullptr);

  std::set<std::string> observedKeys() const override;
  void showPublication(const sl::Publication& publication) override;
  void highlightPass(const QString& passId) override;
  /// "tiles", "unmet", "need_u", "need_v", "max_entry_need" as shown; "grid_n", "leaves_drawn"
  /// (kd leaves drawn over the grid), "rects_drawn" (screen rectangles drawn over the SMTMM),
  /// "cell_x", "cell_y", "cell_entries" (the cell whose histogram is drawn), "hist_u_total",
  /// "hist_v_total" (its histogram's counts), "texture_kinds" (distinct tile textures).
  QJsonObject drawnValues() const override { return drawn_; }

 private:
  void selectCell(int x, int y);
  void drawHistogram();

  ImageView* needU_ = nullptr;
  ImageView* needV_ = nullptr;
  ImageView* grid_ = nullptr;
  PlotWidget* histogram_ = nullptr;
  QLabel* numbers_ = nullptr;
  QLabel* textures_ = nullptr;
  QJsonObject drawn_;
  // The frame's copies the overlays and the histogram read.
  std::vector<fvsm::TileRecord> tiles_;
  sl::FloatImage gridImage_, histImage_;
  int eta0_ = 17, eta1_ = 22;
  int cellX_ = -1, cellY_ = -1;
  bool userCell_ = false;  ///< the cell was hovered (kept across frames)
};

}  // namespace sl::ui
