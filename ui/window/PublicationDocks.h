// The docks of the publication panels (panels/PanelRegistry.h): which keys they request
// from the renderer (only the visible ones'), whether the last frame published them, and
// handing the Publication to them.
#pragma once

#include <deque>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <QJsonObject>
#include <QPointer>
#include <QString>

#include "panels/PanelRegistry.h"

class QDockWidget;
namespace sl {
struct TechniqueInfo;
class ViewSide;
}  // namespace sl

namespace sl::ui {

class PublicationDocks {
 public:
  struct Dock {
    PanelEntry entry;
    QDockWidget* dock = nullptr;
    PublicationPanel* panel = nullptr;
  };

  void add(const PanelEntry& entry, QDockWidget* dock, PublicationPanel* panel);
  const std::vector<Dock>& docks() const { return docks_; }
  /// The dock of panel `id` (PassDecl::panel), null when no panel has that id.
  QDockWidget* dock(const std::string& id) const;

  /// The keys of the visible panels (`all`: of every panel).
  std::set<std::string> keys(bool all) const;
  /// The renderer's last frame published (at least) what keys(all) asks for.
  bool isCurrent(const sl::ViewSide& renderer, bool all) const;
  /// Hands the last publication to the visible panels (`all`: to every panel, at once). The
  /// visible panels get it one per turn of the event loop, so that one frame's panels never
  /// hold the UI thread longer than one panel's work; a newer frame's feed replaces the
  /// panels still queued (they get the newest publication).
  void feed(const sl::ViewSide& renderer, bool all) const;
  /// Called once feed() has handed a frame to the last queued panel (the window checks that
  /// it still fits its screen: a panel grows with its first data).
  void setOnFed(std::function<void()> onFed) { onFed_ = std::move(onFed); }
  /// Panels are still queued by feed() (scripts wait for them).
  bool feeding() const { return !queued_.empty(); }

  /// After a technique switch: the docks whose panel describes `info` (its own panel
  /// family) are shown and brought in front of their tab group, the others hidden, except
  /// those opened by hand that are still open.
  void showOnlyFor(const sl::TechniqueInfo& info);
  /// The user opened (`open`) or closed dock `id` from View > Panels: an opened one stays
  /// through technique switches until it is closed.
  void setOpenedByHand(const QString& id, bool open);
  const std::set<QString>& openedByHand() const { return openedByHand_; }

  /// After a technique switch: when the front bottom tab shows nothing `info` publishes (an
  /// RTW warp panel for `cube`), the first bottom tab that does comes to the front.
  void raiseFor(const sl::TechniqueInfo& info) const;
  /// The first dock (visible ones first, in registry order) whose panel draws something
  /// `info` publishes; null when none does (presenter mode's big panel).
  QDockWidget* firstShowing(const sl::TechniqueInfo& info) const;
  void resetHistory() const;
  void highlightPass(const QString& passId) const;
  /// The view's pixel under the mouse, to every panel (visible or not: cheap, no readback).
  void showProbe(const std::optional<sl::PixelProbe>& probe) const;
  /// A visible panel draws the probe (PublicationPanel::wantsProbe): the view reads it.
  bool probeWanted() const;
  /// What each panel drew, by dock name (for --grab's published.json).
  QJsonObject drawnValues() const;
  /// The placeholder text of each panel that shows one instead of data, by dock name.
  QJsonObject placeholders() const;

 private:
  void feedNext() const;
  std::vector<Dock> docks_;
  std::set<QString> openedByHand_;
  mutable std::deque<QPointer<PublicationPanel>> queued_;  ///< feed(): still to be fed
  mutable const sl::ViewSide* queuedFrom_ = nullptr;
  std::function<void()> onFed_;
};

}  // namespace sl::ui
