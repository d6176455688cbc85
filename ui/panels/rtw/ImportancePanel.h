// The Importance map panel (RTW, seed 002 / Rosen 2012): the light-space importance map
// with a perceptual colour map, its legend, zoom and pan, the value under the cursor, and a
// switch between the raw IM, the collapsed 1D maps and the blurred 1D maps.
#pragma once

#include <vector>

#include "panels/common/PanelKit.h"
#include "panels/rtw/RtwPanelKeys.h"

class QButtonGroup;
class QCheckBox;
class QLabel;

namespace sl::ui {

class ImportancePanel : public PublicationPanel {
  Q_OBJECT

 public:
  enum class Mode { Raw = 0, Collapsed = 1, Blurred = 2 };

  explicit ImportancePanel(QWidget* parent = nullptr);

  std::set<std::string> observedKeys() const override { return rtw::importancePanelKeys(); }
  void showPublication(const sl::Publication& publication) override;
  void highlightPass(const QString& passId) override;
  QJsonObject drawnValues() const override;

  void setMode(Mode mode);
  Mode mode() const { return mode_; }

 private:
  void rebuild();

  Mode mode_ = Mode::Raw;
  sl::FloatImage im_;
  std::vector<float> x_, y_, xBlurred_, yBlurred_;
  std::uint64_t frame_ = 0;
  float max_ = 0.0f;

  ImageView* view_ = nullptr;
  QButtonGroup* modes_ = nullptr;
  QCheckBox* log_ = nullptr;
  QLabel* info_ = nullptr;
};

}  // namespace sl::ui
