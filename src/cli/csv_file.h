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

#include "app/csv_text.h"
#include "app/table.h"
#include "cli/pending_file.h"

namespace contactlaws::cli {

// The results' CSV text (app/csv_text.h), as the files write it.
using app::AppendFields;
using app::AppendRow;
using app::AppendShortest;
using app::Field;
using app::TableColumns;
using app::TableFields;

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
  std::optional<PendingFile> pending_;  // none: standard output
  std::FILE* file_ = nullptr;           // stdout, the pending file's, or none
  std::string line_;
};

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_CSV_FILE_H_
