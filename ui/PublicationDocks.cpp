// The publication panels' docks and their requests (see PublicationDocks.h).
#include "PublicationDocks.h"

#include <algorithm>

#include <QDockWidget>

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

bool PublicationDocks::isCurrent(const sl::Renderer& renderer, bool all) const {
  const sl::Publication& pub = renderer.publication();
  if (pub.frameIndex == 0 || pub.frameIndex != renderer.stats().frameIndex) return false;
  const std::set<std::string> wanted = keys(all);
  return std::includes(pub.requested.begin(), pub.requested.end(), wanted.begin(), wanted.end());
}

void PublicationDocks::feed(const sl::Renderer& renderer, bool all) const {
  if (renderer.publication().frameIndex == 0) return;
  for (const Dock& d : docks_)
    if (all || d.dock->isVisible()) d.panel->showPublication(renderer.publication());
}

void PublicationDocks::resetHistory() const {
  for (const Dock& d : docks_) d.panel->resetHistory();
}

namespace {
/// The panel draws something the technique itself declares (not only the renderer's keys).
bool showsTechnique(const PublicationPanel& panel, const sl::TechniqueInfo& info) {
  for (const std::string& key : panel.observedKeys()) {
    if (info.findPublication(key)) return true;
    for (const sl::PublicationDecl& d : info.publications)  // a pattern against a pattern
      if (sl::publicationKeyMatches(key, d.key)) return true;
  }
  return false;
}
}  // namespace

void PublicationDocks::raiseFor(const sl::TechniqueInfo& info) const {
  const Dock *front = nullptr, *first = nullptr;
  for (const Dock& d : docks_) {
    if (d.entry.area != Qt::BottomDockWidgetArea || d.dock->isFloating() || d.dock->isHidden())
      continue;
    if (!d.dock->visibleRegion().isEmpty()) front = &d;  // the tab in front of its group
    if (!first && showsTechnique(*d.panel, info)) first = &d;
  }
  if (first && (!front || !showsTechnique(*front->panel, info))) first->dock->raise();
}

QDockWidget* PublicationDocks::firstShowing(const sl::TechniqueInfo& info) const {
  QDockWidget* hiddenOne = nullptr;
  for (const Dock& d : docks_) {
    if (!showsTechnique(*d.panel, info)) continue;
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

}  // namespace sl::ui
