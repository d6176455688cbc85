// The Moment mip chain panel (DA-RTW, seed 000; moments after LEAN mapping, Olano & Baker
// 2010): the six moment textures I, xI, yI, x²I, y²I, xyI at a selectable mip level with
// the value under the cursor, and the top level's six sums with the mean and covariance
// computed from them (sl::rtw::momentsFromTop) beside the values the renderer published.
#pragma once

#include <array>
#include <map>

#include "panels/common/PanelKit.h"
#include "panels/rtw/RtwPanelKeys.h"

class QLabel;
class QSlider;

namespace sl::ui {

class MomentPanel : public PublicationPanel {
  Q_OBJECT

 public:
  explicit MomentPanel(QWidget* parent = nullptr);

  std::set<std::string> observedKeys() const override { return rtw::momentPanelKeys(); }
  void showPublication(const sl::Publication& publication) override;
  void highlightPass(const QString& passId) override;
  QJsonObject drawnValues() const override;

  static constexpr int kChannels = 6;
  /// "I", "xI", "yI", "xxI", "yyI", "xyI": the key parts of "moment.<c>.<level>".
  static const std::array<const char*, kChannels>& channelKeys();

 private:
  void showLevel();
  void showNumbers();

  std::array<std::map<int, sl::FloatImage>, kChannels> levels_;  ///< channel -> level -> image
  std::map<std::string, double> numbers_;
  std::string techniqueId_;
  int levelCount_ = 0;

  std::array<ImageView*, kChannels> views_{};
  QSlider* level_ = nullptr;
  QLabel* levelLabel_ = nullptr;
  QLabel* numbersLabel_ = nullptr;
  QJsonObject computed_;
};

}  // namespace sl::ui
