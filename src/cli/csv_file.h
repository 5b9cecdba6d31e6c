// Copyright contactlaws authors.
//
// A CSV output that appears complete or not at all: rows go to PATH.tmp, and
// Commit() renames it to PATH. "-" writes to standard output.

#ifndef CONTACTLAWS_CLI_CSV_FILE_H_
#define CONTACTLAWS_CLI_CSV_FILE_H_

#include <cstdio>
#include <string>
#include <vector>

namespace contactlaws::cli {

class CsvFile {
 public:
  // Throws Error "PATH: cannot write (reason)".
  explicit CsvFile(std::string path);
  ~CsvFile();  // an uncommitted file is removed

  CsvFile(const CsvFile&) = delete;
  CsvFile& operator=(const CsvFile&) = delete;

  void Header(const std::vector<std::string>& columns);
  // Numbers in their shortest exact form; NaN/inf are refused (Error).
  void Row(const std::vector<double>& values);
  // Preformatted leading fields, then numbers as Row.
  void Row(const std::vector<std::string>& prefix, const std::vector<double>& values);
  // A row of preformatted fields.
  void Fields(const std::vector<std::string>& fields);
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
