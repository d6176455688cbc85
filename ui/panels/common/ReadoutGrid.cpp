// A panel's readout in one or two columns (see ReadoutGrid.h).
#include "ReadoutGrid.h"

#include <algorithm>

#include <QEvent>
#include <QGridLayout>
#include <QLabel>

namespace sl::ui {

ReadoutGrid::ReadoutGrid(QWidget* parent) : QWidget(parent), grid_(new QGridLayout(this)) {
  grid_->setContentsMargins(0, 0, 0, 0);
  grid_->setVerticalSpacing(1);
}

void ReadoutGrid::addRow(QLabel* name, QLabel* value) {
  rows_.push_back({name, value});
  arrange(columns_);
}

int ReadoutGrid::widthFor(int columns) const {
  for (const Row& r : rows_) {
    widestName_ = std::max(widestName_, r.name->sizeHint().width());
    widestValue_ = std::max(widestValue_, r.value->sizeHint().width());
  }
  const int spacing = std::max(0, grid_->horizontalSpacing());
  const int column = widestName_ + spacing + widestValue_;
  return columns * column + (columns - 1) * (kColumnGap + spacing);
}

void ReadoutGrid::fitColumns(int width) {
  const int columns = rows_.size() > 1 && widthFor(2) <= width ? 2 : 1;
  if (columns != columns_) arrange(columns);
}

void ReadoutGrid::arrange(int columns) {
  columns_ = columns;
  for (const Row& r : rows_) {
    grid_->removeWidget(r.name);
    grid_->removeWidget(r.value);
  }
  // Name, value, (gap, name, value): the gap a column of its own, so that both value columns
  // end at their column's right edge.
  const int perColumn = int((rows_.size() + std::size_t(columns) - 1) / std::size_t(columns));
  for (int c = 0; c < grid_->columnCount(); ++c) grid_->setColumnMinimumWidth(c, 0);
  for (int r = 0; r < grid_->rowCount(); ++r) grid_->setRowStretch(r, 0);
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    const int column = int(i) / std::max(1, perColumn), row = int(i) % std::max(1, perColumn);
    grid_->addWidget(rows_[i].name, row, 3 * column);
    grid_->addWidget(rows_[i].value, row, 3 * column + 1);
  }
  if (columns > 1) grid_->setColumnMinimumWidth(2, kColumnGap);
  grid_->setRowStretch(perColumn, 1);  // the rows at the top
  updateGeometry();
}

QSize ReadoutGrid::minimumSizeHint() const {
  const QSize least = QWidget::minimumSizeHint();
  return {std::min(least.width(), widthFor(1)), least.height()};
}

void ReadoutGrid::changeEvent(QEvent* event) {
  QWidget::changeEvent(event);
  if (event->type() == QEvent::FontChange) widestName_ = widestValue_ = 0;  // measured again
}

}  // namespace sl::ui
