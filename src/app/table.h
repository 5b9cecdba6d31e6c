// Copyright contactlaws authors.
//
// A result table as columns of numbers and names: what the front-ends turn
// into CSV files (the command line) and DataFrames (Python), the same
// values either way. A number that is not finite is not known (NaN: an
// empty CSV field).

#ifndef CONTACTLAWS_APP_TABLE_H_
#define CONTACTLAWS_APP_TABLE_H_

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace contactlaws::app {

struct Column {
  enum class Kind {
    kNumber,  // a double, NaN where not known
    kCount,   // a whole number, held as a double
    kText,    // a name or a word
  };
  std::string name;
  Kind kind = Kind::kNumber;
  std::vector<double> numbers;    // kNumber, kCount
  std::vector<std::string> text;  // kText
};

// Its fields for the exchange between the ranks of a job (ident/wire.h).
template <typename Archive>
void serialize(Archive& archive, Column& column) {
  archive(column.name, column.kind, column.numbers, column.text);
}

// A cell of a row being added: a number, a count or a text.
struct Cell {
  Column::Kind kind;
  double number;
  std::string text;
};
Cell Number(double value);
Cell Count(double value);
Cell Text(std::string value);
Cell Unknown();  // a number not known (NaN)

class Table {
 public:
  Table() = default;
  // Columns named, filled row by row (AddRow). A row's cells must match the
  // columns' kinds (kCount's cells may be numbers).
  explicit Table(std::vector<std::pair<std::string, Column::Kind>> columns);

  void AddRow(const std::vector<Cell>& cells);

  const std::vector<Column>& columns() const { return columns_; }
  size_t rows() const { return rows_; }

  // Its fields for the exchange between the ranks of a job (ident/wire.h).
  template <typename Archive>
  void serialize(Archive& archive) {
    archive(columns_, rows_);
  }

 private:
  std::vector<Column> columns_;
  size_t rows_ = 0;
};

}  // namespace contactlaws::app

#endif  // CONTACTLAWS_APP_TABLE_H_
