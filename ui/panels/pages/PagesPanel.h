// The Pages panel (rmsm and asm): the page table per level (rmsm: requested / allocated
// unasked / coarsened because the pool ran out; asm's cache: allocated this frame / requested,
// not allocated / cached and used / cached unused / evicted; colours with a legend, the cells
// of every level counted as drawn), the level serving each finest
// page, this frame's requests as a heat map, the pool with each slot's level, the pool's
// depth, the frame's counts, and the pool's use over the last frames. Reads the pages.*
// publications (algo/pages/PageViews.h).
#pragma once

#include <deque>
#include <map>
#include <string>
#include <vector>

#include "panels/common/PanelKit.h"

class QComboBox;
class QLabel;
class QSpinBox;

namespace sl::ui {

class PagesPanel : public PublicationPanel {
  Q_OBJECT

 public:
  explicit PagesPanel(QWidget* parent = nullptr);

  std::set<std::string> observedKeys() const override;
  void showPublication(const sl::Publication& publication) override;
  void highlightPass(const QString& passId) override;
  QJsonObject drawnValues() const override;

 private:
  void redraw();

  QComboBox* viewChoice_ = nullptr;
  QSpinBox* level_ = nullptr;
  ImageView* view_ = nullptr;
  PlotWidget* use_ = nullptr;  ///< pool pages used and requested per frame
  QLabel* info_ = nullptr;
  struct FrameUse {
    double frame, allocated, requested, pool, fresh, evicted;
  };
  std::deque<FrameUse> history_;                  ///< the last kHistory frames published
  std::map<std::string, sl::FloatImage> images_;  ///< the last frame's pages.* images
  std::vector<float> poolLevels_;
  int poolColumns_ = 1;
  int levels_ = 0;
  int shownLevels_ = -1;  ///< levels_ when the level was last chosen for the user
  QJsonObject drawn_;
};

}  // namespace sl::ui
