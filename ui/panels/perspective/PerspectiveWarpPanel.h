// The Perspective warp panel (psm, lispsm, tsm; Lloyd et al. 2006 §4): the warp this frame
// used — eta, n' — and, in red, when it fell back to the uniform map and why (light behind
// or in front of the viewer, TSM's focus beyond its line), so the fallback is never silent.
#pragma once

#include "panels/common/PanelKit.h"

class QLabel;

namespace sl::ui {

class PerspectiveWarpPanel : public PublicationPanel {
  Q_OBJECT

 public:
  explicit PerspectiveWarpPanel(QWidget* parent = nullptr);

  std::set<std::string> observedKeys() const override;
  void showPublication(const sl::Publication& publication) override;
  /// "eta", "n_prime", "fallback", "cause" as shown.
  QJsonObject drawnValues() const override { return drawn_; }

 private:
  QLabel* state_ = nullptr;
  QLabel* numbers_ = nullptr;
  QJsonObject drawn_;
};

}  // namespace sl::ui
