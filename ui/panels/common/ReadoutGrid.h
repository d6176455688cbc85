// A panel's readout: rows of a name and its value (two labels), in one column, or in two
// side by side (half as tall) where the panel is wide enough (e.g. the Covariance panel's
// numbers beside its image at a presenter's size). QWidget only, no GL.
#pragma once

#include <vector>

#include <QWidget>

class QGridLayout;
class QLabel;

namespace sl::ui {

class ReadoutGrid : public QWidget {
  Q_OBJECT

 public:
  explicit ReadoutGrid(QWidget* parent = nullptr);

  /// One more row (the grid takes both labels); rows run down the first column, then the
  /// second, in the order added.
  void addRow(QLabel* name, QLabel* value);
  /// The width the rows need in `columns` columns: the widest name and value ever shown
  /// (a value that changes every frame does not make the choice flicker), the gap between.
  int widthFor(int columns) const;
  /// Lays the rows out in two columns where `width` holds them (widthFor(2)), else in one.
  void fitColumns(int width);
  int columns() const { return columns_; }

  /// At least one column's width, whatever the current columns: a panel that narrows goes
  /// back to one column (fitColumns) rather than being held at two columns' width.
  QSize minimumSizeHint() const override;

  static constexpr int kColumnGap = 16;  ///< px between two columns of rows

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void arrange(int columns);

  struct Row {
    QLabel* name = nullptr;
    QLabel* value = nullptr;
  };
  std::vector<Row> rows_;
  QGridLayout* grid_ = nullptr;
  int columns_ = 1;
  mutable int widestName_ = 0, widestValue_ = 0;
};

}  // namespace sl::ui
