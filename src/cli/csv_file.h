// Copyright contactlaws authors.
//
// CSV output that appears complete or not at all: rows go to PATH.tmp, and
// Commit() renames it to PATH. "-" writes to standard output. Rows can also be
// formatted into a string first (AppendRow, AppendFields), so that runs on
// other threads prepare theirs and one thread writes them in order.

#ifndef CONTACTLAWS_CLI_CSV_FILE_H_
#define CONTACTLAWS_CLI_CSV_FILE_H_

#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/table.h"

namespace contactlaws::cli {

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

// Whether two output paths name one file ("-" is standard output; a file
// that does not exist yet is compared by its absolute, normal path).
bool SamePath(const std::string& a, const std::string& b);

class CsvFile;

// A result table as CSV: its columns' names, then a line per row.
void WriteTable(const app::Table& table, CsvFile* file);

class CsvFile {
 public:
  // Throws Error "PATH: cannot write (reason)".
  explicit CsvFile(std::string path);
  ~CsvFile();  // an uncommitted file is removed

  CsvFile(const CsvFile&) = delete;
  CsvFile& operator=(const CsvFile&) = delete;

  const std::string& path() const { return path_; }

  void Header(const std::vector<std::string>& columns) { Fields(columns); }
  // Numbers in their shortest exact form; NaN/inf are refused (Error).
  void Row(const std::vector<double>& values) { Row({}, values); }
  // Preformatted leading fields, then numbers as Row.
  void Row(const std::vector<std::string>& prefix, const std::vector<double>& values);
  // A row of preformatted fields.
  void Fields(const std::vector<std::string>& fields);
  // Lines formatted by AppendRow / AppendFields.
  void Write(std::string_view lines);
  // Hands what is written so far to the system (a finished run's rows).
  void Flush();
  // Renames PATH.tmp to PATH (flushes stdout); throws Error when it cannot.
  void Commit();

 private:
  std::string path_;
  std::string temp_;
  std::FILE* file_ = nullptr;
  bool is_stdout_ = false;
  std::string line_;
};

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_CSV_FILE_H_
