// Copyright contactlaws authors.
//
// The results' CSV text, as the command line's files hold it: numbers in
// their shortest exact form, fields quoted where they must be (RFC 4180).
// Rows can be formatted into a string on the thread of the run that made
// them, so that one thread writes them in order.

#ifndef CONTACTLAWS_APP_CSV_TEXT_H_
#define CONTACTLAWS_APP_CSV_TEXT_H_

#include <optional>
#include <string>
#include <vector>

#include "app/table.h"

namespace contactlaws::app {

// Appends a finite double as fmt's "{}" writes it, byte for byte: the
// shortest digits that read back to the same double, in fixed notation for
// a decimal exponent in [-4, 16) ("0.0001", "1500", "2.5") and else as
// d[.ddd]e+XX ("1e-05", "1.5e+16"). From std::to_chars' shortest scientific
// form (C++17), a third of fmt's cost on a trajectory's rows.
void AppendShortest(std::string* out, double value);

// Appends one CSV line of preformatted fields to out; a field holding a comma,
// a double quote or a line break is quoted (RFC 4180).
void AppendFields(std::string* out, const std::vector<std::string>& fields);

// Appends one CSV line: the preformatted prefix fields, then numbers in their
// shortest exact form. Returns false, appending nothing, when a number is NaN
// or infinite (no such value is ever written).
bool AppendRow(std::string* out, const std::vector<std::string>& prefix,
               const std::vector<double>& values);

// A number in its shortest exact form; an empty field for what is not known
// (nullopt, NaN, an infinity), and 0 for -0.
std::string Field(double value);
std::string Field(const std::optional<double>& value);

// Row i of table as CSV fields: text as it is, numbers as Field.
std::vector<std::string> TableFields(const app::Table& table, size_t i);

// The names of table's columns.
std::vector<std::string> TableColumns(const app::Table& table);

// A printed table's cell: the value formatted (fmt), "-" for a value that
// does not exist.
std::string TableCell(const std::optional<double>& value, const char* format);

}  // namespace contactlaws::app

#endif  // CONTACTLAWS_APP_CSV_TEXT_H_
