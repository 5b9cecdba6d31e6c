// Copyright contactlaws authors.
//
// A trajectory as NumPy's archive (.npz: a ZIP of .npy arrays, stored, not
// compressed), the numbers as their 8 bytes:
//   rows     float64, (rows, columns): one row per sample, C order;
//   columns  str ('<U'), (columns,): the names the CSV's header gives them.
// numpy.load reads it with its default limits:
//   z = numpy.load(PATH); pandas.DataFrame(z["rows"], columns=z["columns"])
// gives the CSV's table, each number the same double. A single .npy of
// records would carry every name in its header, which numpy.load refuses
// beyond 10000 bytes (49 balls' columns take 14 KB). For the runs whose
// trajectory is large: no digits to write or read (the shortest decimal form
// is most of a CSV row's cost).

#ifndef CONTACTLAWS_CLI_NPZ_FILE_H_
#define CONTACTLAWS_CLI_NPZ_FILE_H_

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "cli/pending_file.h"

namespace contactlaws::cli {

// Whether path ends in `extension` (".npz", ".npy") after a name.
bool HasExtension(std::string_view path, std::string_view extension);

// The NPY header of an array of `descr` ('<f8', '<U12') and `shape`, in
// version 1.0 (a 2-byte length): the magic string, the version, the length
// and the dictionary numpy reads, padded with spaces to a multiple of 64
// bytes with room for 20-digit dimensions (so that a count written later
// keeps the length), ending in a newline.
std::string NpyHeader(std::string_view descr, const std::vector<size_t>& shape);

class NpzFile {
 public:
  // Throws Error "PATH: cannot write (reason)". Writes PATH.tmp, renamed to
  // PATH by Commit; an uncommitted file is removed.
  explicit NpzFile(std::string path);

  // The column names (UTF-8), written as the archive's "columns".
  void Header(const std::vector<std::string>& columns);
  // One row; NaN/inf are refused (Error), as the CSV refuses them.
  void Row(const std::vector<double>& values);
  // Writes the row count, the sizes and checksums, and the archive's
  // directory; renames PATH.tmp to PATH. Throws Error when it cannot.
  void Commit();

 private:
  // One stored member: where its local header starts, its size and CRC-32.
  struct Member {
    std::string name;
    uint64_t offset = 0;
    uint64_t size = 0;
    uint32_t crc = 0;
  };
  void Write(const std::string& bytes);

  PendingFile file_;
  uint64_t written_ = 0;  // bytes so far
  size_t columns_ = 0;
  size_t rows_ = 0;
  Member names_;
  Member rows_member_;
  uint64_t rows_data_offset_ = 0;  // where rows' NPY header starts
  size_t rows_header_length_ = 0;
  uint32_t data_crc_ = 0;          // CRC-32 of rows' numbers so far
};

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_NPZ_FILE_H_
