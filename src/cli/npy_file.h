// Copyright contactlaws authors.
//
// A trajectory as a NumPy file (NPY format, the numbers as their 8 bytes):
// a one-dimensional array of records, one per row, a float64 field per
// column, named as the CSV's header names it. numpy.load reads it;
// pandas.DataFrame(numpy.load(PATH)) gives the CSV's table, each number the
// same double. For the runs whose trajectory is large: no digits to write or
// read (the shortest decimal form is most of a CSV row's cost).

#ifndef CONTACTLAWS_CLI_NPY_FILE_H_
#define CONTACTLAWS_CLI_NPY_FILE_H_

#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "cli/pending_file.h"

namespace contactlaws::cli {

// Whether path names a NumPy file (ends in ".npy").
bool IsNpyPath(std::string_view path);

// The NPY header of `rows` records of the float64 fields `columns`: the
// magic string, its version (1.0; 2.0 for a header over 64 KiB; 3.0 when a
// name is not ASCII), the
// header's length and the dictionary numpy reads, padded with spaces to
// `length` bytes in all (0: the least multiple of 64 that holds it with
// room for a 20-digit row count), ending in a newline.
std::string NpyHeader(const std::vector<std::string>& columns, size_t rows, size_t length = 0);

class NpyFile {
 public:
  // Throws Error "PATH: cannot write (reason)". Writes PATH.tmp, renamed to
  // PATH by Commit; an uncommitted file is removed.
  explicit NpyFile(std::string path);

  void Header(const std::vector<std::string>& columns);
  // One record; NaN/inf are refused (Error), as the CSV refuses them.
  void Row(const std::vector<double>& values);
  // Writes the row count into the header and renames PATH.tmp to PATH;
  // throws Error when it cannot.
  void Commit();

 private:
  PendingFile file_;
  std::vector<std::string> columns_;
  size_t header_length_ = 0;
  size_t rows_ = 0;
};

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_NPY_FILE_H_
