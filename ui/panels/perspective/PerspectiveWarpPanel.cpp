// The Perspective warp panel (see PerspectiveWarpPanel.h): reads the warp.* numbers of the
// publication; the cause's words come from the algorithm (warp::fallbackCauseText).
#include "PerspectiveWarpPanel.h"

#include <algorithm>
#include <cmath>

#include <QLabel>
#include <QVBoxLayout>

#include "algo/warp/PerspectiveWarp.h"
#include "algo/warp/PostPerspective.h"

namespace sl::ui {

PerspectiveWarpPanel::PerspectiveWarpPanel(QWidget* parent) : PublicationPanel(parent) {
  auto [content, layout] = newPanelColumn();
  state_ = new QLabel;
  state_->setWordWrap(true);
  state_->setTextFormat(Qt::RichText);
  numbers_ = new QLabel;
  numbers_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(state_);
  layout->addWidget(numbers_);
  layout->addStretch(1);
  setContent(content);
}

std::set<std::string> PerspectiveWarpPanel::observedKeys() const {
  return {"warp.eta", "warp.n_prime",  "warp.fallback", "warp.fallback_cause",
          "psm.case", "psm.slide_back"};
}

void PerspectiveWarpPanel::showPublication(const sl::Publication& pub) {
  const auto& n = pub.numbers;
  if (n.count("psm.case") && n.at("psm.case") >= 0.0) {
    // psm's post-perspective map (Stamminger and Drettakis): no light-space n' or eta.
    showContent(true);
    const auto c =
        warp::PsmLightCase(std::clamp(int(n.at("psm.case")), 0, int(warp::PsmLightCase::Uniform)));
    const double slide = n.count("psm.slide_back") ? n.at("psm.slide_back") : 0.0;
    const QString text = QString::fromUtf8(warp::psmLightCaseText(c)).toHtmlEscaped();
    if (c == warp::PsmLightCase::Uniform)
      state_->setText(tr("<b style='color:#c0392b'>Fallback to the uniform map</b>: %1").arg(text));
    else
      state_->setText(tr("<b>Post-perspective</b> (Stamminger and Drettakis): %1").arg(text));
    numbers_->setText(tr("virtual camera slid back %1 m").arg(formatValue(slide)));
    drawn_ = {{"psm_case", int(c)},
              {"slide_back", slide},
              {"fallback", c == warp::PsmLightCase::Uniform}};
    return;
  }
  if (!n.count("warp.fallback") || !n.count("warp.eta") || !n.count("warp.n_prime")) {
    drawn_ = {};
    showContent(false, noDataText(QString::fromStdString(pub.techniqueId), tr("perspective warp"),
                                  observedKeys()));
    return;
  }
  showContent(true);
  const bool fallback = n.at("warp.fallback") != 0.0;
  const int causeIndex = n.count("warp.fallback_cause") ? int(n.at("warp.fallback_cause")) : 0;
  const auto cause =
      warp::FallbackCause(std::clamp(causeIndex, 0, int(warp::FallbackCause::Degenerate)));
  const double eta = n.at("warp.eta"), nPrime = n.at("warp.n_prime");
  if (fallback)
    state_->setText(tr("<b style='color:#c0392b'>Fallback to the uniform map</b>: %1")
                        .arg(QString::fromUtf8(warp::fallbackCauseText(cause)).toHtmlEscaped()));
  else if (std::isinf(nPrime))
    state_->setText(tr("<b>Uniform</b> (eta = -1 asked for)"));
  else
    state_->setText(tr("<b>Warped</b> along light-space z"));
  numbers_->setText(tr("eta %1    n' %2 m")
                        .arg(formatValue(eta))
                        .arg(std::isinf(nPrime) ? QStringLiteral("∞") : formatValue(nPrime)));
  drawn_ = {{"eta", eta},
            {"n_prime", std::isinf(nPrime) ? -1.0 : nPrime},
            {"fallback", fallback},
            {"cause", QString::fromUtf8(warp::fallbackCauseText(cause))}};
}

}  // namespace sl::ui
