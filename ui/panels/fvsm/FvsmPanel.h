// The FVSM panel (fitted virtual shadow maps, Giegl & Wimmer 2007), drawn from what the
// renderer publishes (never GL): each kd leaf's screen rectangle over the camera's image
// (`fvsm.camera`, a thumbnail the renderer makes) and the kd-tree's leaves over the light's
// view (`fvsm.light.depth`, the whole fit's depth, small), the two views; the SMTMM as heat
// maps of the log2 resolution the whole virtual map needs along each SM axis (`fvsm.smtmm`) with
// each kd leaf's screen rectangle over it (`fvsm.tiles.list`; the SMTMM is the camera's view at one
// entry per block); the tile grid over the light's view (`fvsm.grid`: each cell's need after
// outlier rejection) with the kd-tree's leaves drawn as their SM rectangles, labelled with the log2
// texture each was rendered at; the need histogram of the hovered (else the neediest) grid cell
// (`fvsm.grid.histogram`, end buckets η0, η1); the textures the leaves used (size, mode's
// viewport), each leaf's depth and apply time (`fvsm.tile_ms`: the dearest listed, the hovered
// cell's leaf in its readout) and the frame's numbers.
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
  /// "camera_w", "camera_h" (the camera image's texels, 0 without one), "camera_rects_drawn"
  /// (screen rectangles drawn over it), "camera_surface_texels" (its texels with a surface),
  /// "light_w", "light_h", "light_leaves_drawn" (the light's view and the kd leaves drawn
  /// over it), "light_geometry_texels" (its texels nearer than the far plane),
  /// "cell_x", "cell_y", "cell_entries" (the cell whose histogram is drawn), "hist_u_total",
  /// "hist_v_total" (its histogram's counts), "texture_kinds" (distinct tile textures),
  /// "tile_times_listed" (leaves with their depth and apply ms, from `fvsm.tile_ms`; 0 when
  /// it does not list this frame's leaves), "tile_ms_sum" (their sum).
  QJsonObject drawnValues() const override { return drawn_; }

 private:
  void selectCell(int x, int y);
  void drawHistogram();

  ImageView* camera_ = nullptr;
  ImageView* light_ = nullptr;
  ImageView* needU_ = nullptr;
  ImageView* needV_ = nullptr;
  ImageView* grid_ = nullptr;
  PlotWidget* histogram_ = nullptr;
  QLabel* numbers_ = nullptr;
  QLabel* textures_ = nullptr;
  QJsonObject drawn_;
  // The frame's copies the overlays and the histogram read.
  std::vector<fvsm::TileRecord> tiles_;
  glm::ivec2 smtmmSize_{0};  ///< the screen rectangles' units (SMTMM entries)
  sl::FloatImage gridImage_, histImage_;
  int eta0_ = 17, eta1_ = 22;
  int cellX_ = -1, cellY_ = -1;
  bool userCell_ = false;  ///< the cell was hovered (kept across frames)
};

}  // namespace sl::ui
