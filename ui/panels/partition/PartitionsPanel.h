// The Partitions panel: every partition's depth map, side by side in as many rows as the
// panel's width needs for each to stay at its minimum size, framed in its colour of the
// view's partition overlay, captioned with its split distances; a table of their numbers
// below (a map's fallback to a uniform warp as a numbered note under it).
#pragma once

#include <vector>

#include "panels/common/PanelKit.h"
#include "panels/partition/PartitionPanelKeys.h"

class QLabel;
class QGridLayout;

namespace sl::ui {

class PartitionsPanel : public PublicationPanel {
  Q_OBJECT

 public:
  explicit PartitionsPanel(QWidget* parent = nullptr);

  std::set<std::string> observedKeys() const override { return partition::partitionsPanelKeys(); }
  void showPublication(const sl::Publication& publication) override;
  void highlightPass(const QString& passId) override;
  QJsonObject drawnValues() const override;

 protected:
  void readableMinimumsChanged() override { arrangeMaps(); }
  void resizeEvent(QResizeEvent* event) override;

 private:
  /// The shown maps in rows of as many as the width holds at their minimum width.
  void arrangeMaps();

  QGridLayout* maps_ = nullptr;
  int shown_ = 0;    ///< maps shown (the frame's partition count)
  int columns_ = 0;  ///< as arranged
  std::vector<ImageView*> views_;
  QLabel* table_ = nullptr;
  QJsonObject drawn_;
};

}  // namespace sl::ui
