// Copyright contactlaws authors.
//
// Result tables (app/table.h) handed to Python as columns.

#include "bindings.h"

namespace contactlaws::python {

namespace py = pybind11;

py::dict TableDict(const app::Table& table) {
  py::dict columns;
  for (const app::Column& c : table.columns()) {
    switch (c.kind) {
      case app::Column::Kind::kText: columns[py::str(c.name)] = c.text; break;
      case app::Column::Kind::kCount:
        columns[py::str(c.name)] = Array(std::vector<int64_t>(c.numbers.begin(), c.numbers.end()));
        break;
      case app::Column::Kind::kNumber: columns[py::str(c.name)] = Array(c.numbers); break;
    }
  }
  return columns;
}

}  // namespace contactlaws::python
