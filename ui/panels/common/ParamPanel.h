// The Parameters panel: generated from ParamDecls (one row per parameter, group boxes by
// `group`, an editor by type, help as tooltip, reset buttons). Every edit goes through
// ParamSet::set, so the declaration's range is the only range; refusals are reported.
// The same rows make a lesson's compact strip (setStrip): just the few parameters its steps
// change, without titles or group boxes.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <QString>
#include <QWidget>

#include "algo/Params.h"

class QGridLayout;
class QScrollArea;

namespace sl::ui {

class ParamPanel : public QWidget {
  Q_OBJECT

 public:
  /// One block of the panel: a title (technique name, "View & shading"), an optional
  /// description, and the live ParamSet it edits (owned elsewhere, must outlive the binding).
  struct Section {
    QString title;
    QString description;
    sl::ParamSet* params = nullptr;
  };

  explicit ParamPanel(QWidget* parent = nullptr);

  /// Rebuilds the panel for `sections` (empty: shows a placeholder).
  void setSections(std::vector<Section> sections);
  /// One row of a strip: parameter `key` of `params` (owned elsewhere, must outlive the
  /// binding; a key `params` does not declare is skipped).
  struct StripRow {
    sl::ParamSet* params = nullptr;
    std::string key;
  };
  /// Rebuilds the panel as a compact strip: one row per entry (label, slider, value, reset),
  /// the Parameters panel's editors, no scrolling (the panel is as tall as its rows).
  /// Returns the number of rows shown.
  int setStrip(const std::vector<StripRow>& rows);
  /// Drops every reference into the ParamSets (call before they are destroyed).
  void clear();
  /// Whether the panel edits ParamSets now (built, not cleared).
  bool bound() const { return !refreshers_.empty(); }
  /// Re-reads every value (after changes made elsewhere, e.g. --set or presets).
  void refreshValues();
  /// Sets `key` of the first ParamSet shown that declares it, as the key's own editor does
  /// (paramChanged, or editRefused with ParamSet's message); false when none declares it.
  bool edit(const std::string& key, double value);

 Q_SIGNALS:
  /// The panel was rebuilt (setSections) or cleared: what it edits changed.
  void rebuilt();
  /// A value changed (already stored in its ParamSet).
  void paramChanged(const QString& key);
  /// An edit was refused (ParamSet's message, naming the key and range).
  void editRefused(const QString& message);

 private:
  QWidget* buildSection(const Section& section);
  void buildRow(sl::ParamSet& params, const sl::ParamDecl& decl, QGridLayout* grid, int row);
  /// Stores `value` into `params`; on refusal reports it and returns false.
  bool commit(sl::ParamSet& params, const sl::ParamDecl& decl, double value);

  QScrollArea* scroll_ = nullptr;
  std::vector<std::function<void()>> refreshers_;  ///< one per row: value -> widgets
  std::vector<sl::ParamSet*> sets_;                ///< the ParamSets shown (edit())
};

}  // namespace sl::ui
