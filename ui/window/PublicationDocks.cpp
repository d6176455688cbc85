// The publication panels' docks and their requests (see PublicationDocks.h).
#include "window/PublicationDocks.h"

#include "core/ViewSide.h"

#include <algorithm>

#include <QDockWidget>
#include <QTimer>

namespace sl::ui {

void PublicationDocks::add(const PanelEntry& entry, QDockWidget* dock, PublicationPanel* panel) {
  docks_.push_back({entry, dock, panel});
}

QDockWidget* PublicationDocks::dock(const std::string& id) const {
  for (const Dock& d : docks_)
    if (d.entry.id.toStdString() == id) return d.dock;
  return nullptr;
}

std::set<std::string> PublicationDocks::keys(bool all) const {
  std::set<std::string> keys;
  for (const Dock& d : docks_) {
    if (!all && !d.dock->isVisible()) continue;
    const std::set<std::string> k = d.panel->observedKeys();
    keys.insert(k.begin(), k.end());
  }
  return keys;
}

bool PublicationDocks::isCurrent(const sl::ViewSide& renderer, bool all) const {
  const sl::Publication& pub = renderer.publication();
  if (pub.frameIndex == 0 || pub.frameIndex != renderer.stats().frameIndex) return false;
  const std::set<std::string> wanted = keys(all);
  return std::includes(pub.requested.begin(), pub.requested.end(), wanted.begin(), wanted.end());
}

void PublicationDocks::feed(const sl::ViewSide& renderer, bool all) const {
  if (renderer.publication().frameIndex == 0) return;
  if (all) {
    queued_.clear();
    for (const Dock& d : docks_) d.panel->showPublication(renderer.publication());
    if (onFed_) onFed_();
    return;
  }
  const bool idle = queued_.empty();
  queued_.clear();
  queuedFrom_ = &renderer;
  for (const Dock& d : docks_)
    if (d.dock->isVisible()) queued_.emplace_back(d.panel);
  if (idle) feedNext();
}

void PublicationDocks::feedNext() const {
  while (!queued_.empty() && !queued_.front()) queued_.pop_front();  // a panel gone
  if (queued_.empty() || !queuedFrom_) return;
  PublicationPanel* panel = queued_.front();
  queued_.pop_front();
  panel->showPublication(queuedFrom_->publication());
  if (!queued_.empty())
    QTimer::singleShot(0, panel, [this] { feedNext(); });
  else if (onFed_)
    onFed_();
}

void PublicationDocks::resetHistory() const {
  for (const Dock& d : docks_) d.panel->resetHistory();
}

void PublicationDocks::showOnlyFor(const sl::TechniqueInfo& info) {
  for (const Dock& d : docks_) {
    // Open: not closed (a tab behind another is open, moved out of sight by the layout).
    // Not the toggle action: it follows only once the window has been shown.
    const bool open = !d.dock->isHidden();
    if (!open) openedByHand_.erase(d.entry.id);  // closed since (its title bar's button)
    const bool describes = d.panel->describes(info);
    const bool show = describes || openedByHand_.contains(d.entry.id);
    if (open != show) d.dock->setVisible(show);
    if (describes) d.dock->raise();  // in front of its tab group (e.g. of Timing)
  }
}

void PublicationDocks::setOpenedByHand(const QString& id, bool open) {
  if (open)
    openedByHand_.insert(id);
  else
    openedByHand_.erase(id);
}

void PublicationDocks::raiseFor(const sl::TechniqueInfo& info) const {
  const Dock *front = nullptr, *first = nullptr;
  for (const Dock& d : docks_) {
    if (d.entry.area != Qt::BottomDockWidgetArea || d.dock->isFloating() || d.dock->isHidden())
      continue;
    if (!d.dock->visibleRegion().isEmpty()) front = &d;  // the tab in front of its group
    if (!first && d.panel->describes(info)) first = &d;
  }
  if (first && (!front || !front->panel->describes(info))) first->dock->raise();
}

QDockWidget* PublicationDocks::firstShowing(const sl::TechniqueInfo& info) const {
  QDockWidget* hiddenOne = nullptr;
  for (const Dock& d : docks_) {
    if (!d.panel->describes(info)) continue;
    if (!d.dock->isHidden()) return d.dock;
    if (!hiddenOne) hiddenOne = d.dock;
  }
  return hiddenOne;
}

void PublicationDocks::showProbe(const std::optional<sl::PixelProbe>& probe) const {
  for (const Dock& d : docks_) d.panel->showProbe(probe);
}

bool PublicationDocks::probeWanted() const {
  return std::any_of(docks_.begin(), docks_.end(),
                     [](const Dock& d) { return d.dock->isVisible() && d.panel->wantsProbe(); });
}

void PublicationDocks::highlightPass(const QString& passId) const {
  for (const Dock& d : docks_) d.panel->highlightPass(passId);
}

QJsonObject PublicationDocks::drawnValues() const {
  QJsonObject panels;
  for (const Dock& d : docks_) panels[d.dock->objectName()] = d.panel->drawnValues();
  return panels;
}

QJsonObject PublicationDocks::placeholders() const {
  QJsonObject shown;
  for (const Dock& d : docks_)
    if (const QString text = d.panel->placeholderShown(); !text.isEmpty())
      shown[d.dock->objectName()] = text;
  return shown;
}

}  // namespace sl::ui
