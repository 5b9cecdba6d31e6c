// Copyright contactlaws authors.

#include "app/table.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace contactlaws::app {

Cell Number(double value) {
  return {Column::Kind::kNumber,
          std::isfinite(value) ? value : std::numeric_limits<double>::quiet_NaN(), {}};
}
Cell Count(double value) { return {Column::Kind::kCount, value, {}}; }
Cell Text(std::string value) { return {Column::Kind::kText, 0, std::move(value)}; }
Cell Unknown() { return Number(std::numeric_limits<double>::quiet_NaN()); }

Table::Table(std::vector<std::pair<std::string, Column::Kind>> columns) {
  for (auto& [name, kind] : columns) {
    Column c;
    c.name = std::move(name);
    c.kind = kind;
    columns_.push_back(std::move(c));
  }
}

void Table::AddRow(const std::vector<Cell>& cells) {
  if (cells.size() != columns_.size()) {
    throw std::logic_error("Table::AddRow: " + std::to_string(cells.size()) + " cells for " +
                           std::to_string(columns_.size()) + " columns");
  }
  for (size_t i = 0; i < cells.size(); ++i) {
    Column& c = columns_[i];
    const bool text = c.kind == Column::Kind::kText;
    if (text != (cells[i].kind == Column::Kind::kText)) {
      throw std::logic_error("Table::AddRow: column " + c.name + ": a cell of another kind");
    }
    if (text) {
      c.text.push_back(cells[i].text);
    } else {
      c.numbers.push_back(cells[i].number);
    }
  }
  ++rows_;
}

}  // namespace contactlaws::app
