// The FVSM panel (fitted virtual shadow maps, Giegl & Wimmer 2007): the SMTMM as heat maps of
// the log2 resolution the whole virtual map needs along each SM axis (the `fvsm.smtmm`
// publication), and the frame's kd-tree numbers (tiles, unmet tiles, the root's need, texels).
// Not yet drawn: the tile grid's histograms, the kd leaves over the light's view, each tile's
// screen rectangle and texture.
#pragma once

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
  /// "tiles", "unmet", "need_u", "need_v", "max_entry_need" as shown.
  QJsonObject drawnValues() const override { return drawn_; }

 private:
  ImageView* needU_ = nullptr;
  ImageView* needV_ = nullptr;
  QLabel* numbers_ = nullptr;
  QJsonObject drawn_;
};

}  // namespace sl::ui
