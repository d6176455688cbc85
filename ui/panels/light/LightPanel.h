// The Light panel: the kind of light (directional, spot, point) and its fields, generated
// from one declaration table (label, unit, range, step, which kinds use it, how it reads
// and writes sl::Light). Edits that fail sl::Light::validate() are shown, not applied.
#pragma once

#include <vector>

#include <QWidget>

#include "algo/Light.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace sl::ui {

class LightPanel : public QWidget {
  Q_OBJECT

 public:
  explicit LightPanel(QWidget* parent = nullptr);
  /// Shows `light` (no lightEdited emitted).
  void showLight(const sl::Light& light);

 Q_SIGNALS:
  /// A valid light the user edited.
  void lightEdited(const sl::Light& light);

 private:
  void onEdited();
  void updateVisibleRows();

  sl::Light light_;
  QComboBox* type_ = nullptr;
  std::vector<QDoubleSpinBox*> fields_;  ///< one per row of lightFieldDecls()
  std::vector<QWidget*> rows_;
  QLabel* status_ = nullptr;
};

}  // namespace sl::ui
