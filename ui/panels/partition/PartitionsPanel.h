// The Partitions panel: every partition's depth map side by side, framed in its colour of
// the view's partition overlay, captioned with its split distances, texel count and texels
// per metre; a table of the same numbers below.
#pragma once

#include <vector>

#include "panels/common/PanelKit.h"
#include "panels/partition/PartitionPanelKeys.h"

class QLabel;
class QHBoxLayout;

namespace sl::ui {

class PartitionsPanel : public PublicationPanel {
  Q_OBJECT

 public:
  explicit PartitionsPanel(QWidget* parent = nullptr);

  std::set<std::string> observedKeys() const override { return partition::partitionsPanelKeys(); }
  void showPublication(const sl::Publication& publication) override;
  void highlightPass(const QString& passId) override;
  QJsonObject drawnValues() const override;

 private:
  QHBoxLayout* maps_ = nullptr;
  std::vector<ImageView*> views_;
  QLabel* table_ = nullptr;
  QJsonObject drawn_;
};

}  // namespace sl::ui
