// The Moment mip chain panel (see MomentPanel.h).
#include "MomentPanel.h"

#include <algorithm>
#include <cmath>

#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QVBoxLayout>

#include "algo/rtw/Moments.h"

namespace sl::ui {

namespace {
const std::array<QString, MomentPanel::kChannels> kTitles = {
    QStringLiteral("I"),         QStringLiteral("x·I"),       QStringLiteral("y·I"),
    QStringLiteral("x\u00b2·I"), QStringLiteral("y\u00b2·I"), QStringLiteral("x·y·I")};

bool isSigned(int channel) {
  return channel == sl::rtw::kMomXI || channel == sl::rtw::kMomYI || channel == sl::rtw::kMomXYI;
}

double numberOr(const std::map<std::string, double>& numbers, const std::string& key,
                double fallback) {
  auto it = numbers.find(key);
  return it == numbers.end() ? fallback : it->second;
}

QString cell(double v) {
  return QStringLiteral("<td align='right'>%1</td>").arg(formatValue(v));
}
}  // namespace

const std::array<const char*, MomentPanel::kChannels>& MomentPanel::channelKeys() {
  static const std::array<const char*, kChannels> keys = {"I", "xI", "yI", "xxI", "yyI", "xyI"};
  return keys;
}

MomentPanel::MomentPanel(QWidget* parent) : PublicationPanel(parent) {
  auto* content = new QWidget;
  auto* outer = new QHBoxLayout(content);
  outer->setContentsMargins(4, 4, 4, 4);
  auto* left = new QVBoxLayout;
  auto* bar = new QHBoxLayout;
  bar->addWidget(new QLabel(tr("Mip level")));
  level_ = new QSlider(Qt::Horizontal);
  level_->setObjectName(QStringLiteral("momentLevel"));
  level_->setToolTip(
      tr("Level 0 = one texel per IM texel; each level sums 2×2 texels of the "
         "one below; the last level (1×1) holds the six sums"));
  level_->setPageStep(1);
  connect(level_, &QSlider::valueChanged, this, [this] { showLevel(); });
  bar->addWidget(level_, 1);
  levelLabel_ = new QLabel;
  levelLabel_->setMinimumWidth(
      levelLabel_->fontMetrics().horizontalAdvance(QStringLiteral("level 88 of 88 (8888×8888)")));
  bar->addWidget(levelLabel_);
  left->addLayout(bar);
  auto* grid = new QGridLayout;
  grid->setSpacing(3);
  for (int c = 0; c < kChannels; ++c) {
    views_[c] = new ImageView;
    views_[c]->setObjectName(QStringLiteral("moment_%1").arg(channelKeys()[c]));
    grid->addWidget(views_[c], c / 3, c % 3);
  }
  left->addLayout(grid, 1);
  outer->addLayout(left, 3);
  numbersLabel_ = new QLabel;
  numbersLabel_->setTextFormat(Qt::RichText);
  numbersLabel_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  numbersLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  numbersLabel_->setWordWrap(true);
  numbersLabel_->setMinimumWidth(230);
  outer->addWidget(numbersLabel_, 1);
  setContent(content);
}

void MomentPanel::showPublication(const sl::Publication& pub) {
  techniqueId_ = pub.techniqueId;
  numbers_ = pub.numbers;
  levelCount_ = 0;
  for (int c = 0; c < kChannels; ++c) {
    levels_[c].clear();
    for (int l = 0;; ++l) {
      auto it =
          pub.images.find(std::string("moment.") + channelKeys()[c] + "." + std::to_string(l));
      if (it == pub.images.end()) break;
      levels_[c][l] = it->second;
      if (c == 0) levelCount_ = l + 1;
    }
  }
  const bool haveNumbers = pub.numbers.count("moment.I") > 0;
  if (levelCount_ == 0 && !haveNumbers) {
    showContent(false, noDataText(QString::fromStdString(pub.techniqueId), tr("moment mip chain"),
                                  observedKeys()));
    return;
  }
  showContent(true);
  {
    QSignalBlocker block(level_);
    level_->setRange(0, std::max(0, levelCount_ - 1));
    level_->setEnabled(levelCount_ > 1);
  }
  showLevel();
  showNumbers();
}

void MomentPanel::showLevel() {
  const int l = level_->value();
  for (int c = 0; c < kChannels; ++c) {
    auto it = levels_[c].find(l);
    if (it == levels_[c].end()) {
      views_[c]->clearImage(levelCount_ == 0 ? tr("no moment textures published")
                                             : tr("not published"));
      views_[c]->setCaption(kTitles[c]);
      continue;
    }
    const sl::FloatImage& image = it->second;
    const bool sgn = isSigned(c);
    const ValueRange range = sgn ? symmetricRange(image.values, image.channels)
                                 : finiteRange(image.values, image.channels);
    const ColorMap map = sgn ? ColorMap::Diverging : ColorMap::Viridis;
    views_[c]->setImage(colorize(image, 0, range, map), image.width, image.height);
    views_[c]->setLegend(range, map, QString());
    views_[c]->setCaption(kTitles[c]);
    const sl::FloatImage copy = image;
    const QString title = kTitles[c];
    views_[c]->setValueReader([copy, title](int x, int y) {
      return QStringLiteral("%1 = %2").arg(
          title, formatValue(copy.values[(size_t(y) * copy.width + x) * copy.channels]));
    });
  }
  const sl::FloatImage* first = levels_[0].count(l) ? &levels_[0].at(l) : nullptr;
  levelLabel_->setText(first ? tr("level %1 of %2 (%3×%4)")
                                   .arg(l)
                                   .arg(levelCount_ - 1)
                                   .arg(first->width)
                                   .arg(first->height)
                             : tr("no levels"));
}

void MomentPanel::showNumbers() {
  // The six sums: the published top-level numbers, else the 1x1 level of the chain.
  sl::rtw::MomentTexel top{};
  bool haveTop = true;
  for (int c = 0; c < kChannels; ++c) {
    const std::string key = std::string("moment.") + channelKeys()[c];
    auto it = numbers_.find(key);
    if (it != numbers_.end()) {
      top[c] = static_cast<float>(it->second);
    } else if (levelCount_ > 0 && levels_[c].count(levelCount_ - 1) &&
               !levels_[c].at(levelCount_ - 1).values.empty()) {
      top[c] = levels_[c].at(levelCount_ - 1).values[0];
    } else {
      haveTop = false;
    }
  }
  if (!haveTop) {
    numbersLabel_->setText(tr("No top-level sums published."));
    computed_ = {};
    return;
  }
  // The scale the renderer's PCA used (pca.scale.*: half extents, or 1 in IM units).
  const glm::vec2 axisScale(
      static_cast<float>(
          numberOr(numbers_, "pca.scale.x", 0.5 * numberOr(numbers_, "light.extent.x", 2.0))),
      static_cast<float>(
          numberOr(numbers_, "pca.scale.y", 0.5 * numberOr(numbers_, "light.extent.y", 2.0))));
  const bool metres = !(axisScale.x == 1.0f && axisScale.y == 1.0f);
  const sl::rtw::MomentStats s = sl::rtw::momentsFromTop(top, axisScale);
  computed_ = {{QStringLiteral("mean.x"), s.meanX},    {QStringLiteral("mean.y"), s.meanY},
               {QStringLiteral("cov.xx"), s.covXX},    {QStringLiteral("cov.xy"), s.covXY},
               {QStringLiteral("cov.yy"), s.covYY},    {QStringLiteral("eigen.1"), s.lambda1},
               {QStringLiteral("eigen.2"), s.lambda2}, {QStringLiteral("valid"), s.valid}};

  QString html = QStringLiteral("<b>%1</b><table cellspacing='0' cellpadding='1'>")
                     .arg(tr("Top level (the sums over the IM)"));
  for (int c = 0; c < kChannels; ++c)
    html += QStringLiteral("<tr><td>\u03a3 %1&nbsp;&nbsp;</td>%2</tr>")
                .arg(kTitles[c].toHtmlEscaped(), cell(top[c]));
  html += QStringLiteral("</table><br><b>%1</b>").arg(tr("Computed from them"));
  html += QStringLiteral("<table cellspacing='0' cellpadding='1'>");
  html += QStringLiteral("<tr><td>x\u0304, y\u0304&nbsp;</td>%1%2</tr>")
              .arg(cell(s.meanX), cell(s.meanY));
  html += QStringLiteral("<tr><td>\u03b1, \u03b2, \u03b3&nbsp;</td>%1%2%3</tr>")
              .arg(cell(s.alpha), cell(s.beta), cell(s.gamma));
  html += QStringLiteral("<tr><td>\u03a3&nbsp;</td>%1%2</tr><tr><td></td>%3%4</tr>")
              .arg(cell(s.covXX), cell(s.covXY), cell(s.covXY), cell(s.covYY));
  html += QStringLiteral("<tr><td>\u03bb1, \u03bb2&nbsp;</td>%1%2</tr>")
              .arg(cell(s.lambda1), cell(s.lambda2));
  html += QStringLiteral("<tr><td>(e<sub>x</sub>, e<sub>y</sub>)&nbsp;</td>%1%2</tr>")
              .arg(cell(s.ex), cell(s.ey));
  html += QStringLiteral("</table>");
  if (numbers_.count("cov.xx")) {
    html += QStringLiteral("<br><b>%1</b><table cellspacing='0' cellpadding='1'>")
                .arg(tr("Published by the renderer"));
    html +=
        QStringLiteral("<tr><td>x\u0304, y\u0304&nbsp;</td>%1%2</tr>")
            .arg(cell(numberOr(numbers_, "mean.x", NAN)), cell(numberOr(numbers_, "mean.y", NAN)));
    html +=
        QStringLiteral("<tr><td>\u03a3&nbsp;</td>%1%2%3</tr>")
            .arg(cell(numberOr(numbers_, "cov.xx", NAN)), cell(numberOr(numbers_, "cov.xy", NAN)),
                 cell(numberOr(numbers_, "cov.yy", NAN)));
    html += QStringLiteral("</table>");
  }
  html += QStringLiteral("<p style='color:gray'>%1</p>")
              .arg(metres ? tr("x, y: texel centres in [-1, 1]; \u03a3 in metres (scaled by the "
                               "light frustum's half-extents %1, %2 m: pca.metric = metres).")
                                .arg(formatValue(axisScale.x), formatValue(axisScale.y))
                          : tr("x, y: texel centres in [-1, 1]; \u03a3 in these IM units "
                               "(pca.metric = im-units, the poster's)."));
  numbersLabel_->setText(html);
}

void MomentPanel::highlightPass(const QString& passId) {
  const bool on = passId == QLatin1String("moments");
  for (ImageView* v : views_) v->setHighlighted(on);
  if (on && levelCount_ > 0) level_->setValue(0);
}

QJsonObject MomentPanel::drawnValues() const {
  QJsonObject o = computed_;
  o[QStringLiteral("levels")] = levelCount_;
  return o;
}

}  // namespace sl::ui
