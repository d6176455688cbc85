// The FVSM panel (see FvsmPanel.h).
#include "FvsmPanel.h"

#include <algorithm>

#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace sl::ui {

namespace {
constexpr int kChannelNeedU = 2, kChannelNeedV = 3;  // fvsm.smtmm: u, v, need u, need v
}  // namespace

FvsmPanel::FvsmPanel(QWidget* parent) : PublicationPanel(parent) {
  auto* content = new QWidget;
  auto* layout = new QVBoxLayout(content);
  layout->setContentsMargins(4, 4, 4, 4);
  auto* maps = new QHBoxLayout;
  needU_ = new ImageView;
  needV_ = new ImageView;
  needU_->setCaption(tr("SMTMM: log2 texels needed along SM u"));
  needV_->setCaption(tr("SMTMM: log2 texels needed along SM v"));
  maps->addWidget(needU_);
  maps->addWidget(needV_);
  numbers_ = new QLabel;
  numbers_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  numbers_->setWordWrap(true);
  layout->addLayout(maps, 1);
  layout->addWidget(numbers_);
  setContent(content);
}

std::set<std::string> FvsmPanel::observedKeys() const {
  return {"fvsm.smtmm",       "fvsm.tiles",       "fvsm.tiles.unmet",
          "fvsm.need_log2.u", "fvsm.need_log2.v", "fvsm.texels"};
}

void FvsmPanel::highlightPass(const QString& passId) {
  const bool smtmm = passId == QLatin1String("smtmm");
  needU_->setHighlighted(smtmm);
  needV_->setHighlighted(smtmm);
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
  const sl::FloatImage& smtmm = img->second;
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
  const auto number = [&](const char* key) { return n.count(key) ? n.at(key) : -1.0; };
  numbers_->setText(tr("kd leaves %1 (unmet at the finest level: %2)    whole map needs 2^%3 x "
                       "2^%4 texels    tile texels %5")
                        .arg(number("fvsm.tiles"))
                        .arg(number("fvsm.tiles.unmet"))
                        .arg(number("fvsm.need_log2.u"))
                        .arg(number("fvsm.need_log2.v"))
                        .arg(formatValue(number("fvsm.texels"))));
  drawn_ = {{"tiles", number("fvsm.tiles")},
            {"unmet", number("fvsm.tiles.unmet")},
            {"need_u", number("fvsm.need_log2.u")},
            {"need_v", number("fvsm.need_log2.v")},
            {"max_entry_need", double(maxNeed)}};
}

}  // namespace sl::ui
