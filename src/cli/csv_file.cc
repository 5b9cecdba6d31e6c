// Copyright contactlaws authors.

#include "cli/csv_file.h"

#include <cerrno>
#include <cmath>
#include <cstring>

#include <fmt/format.h>

#include "contactlaws/error.h"

namespace contactlaws::cli {

CsvFile::CsvFile(std::string path) : path_(std::move(path)) {
  if (path_ == "-") {
    file_ = stdout;
    is_stdout_ = true;
    return;
  }
  temp_ = path_ + ".tmp";
  file_ = std::fopen(temp_.c_str(), "w");
  if (!file_) {
    throw Error(fmt::format("{}: cannot write ({})", path_, std::strerror(errno)));
  }
}

CsvFile::~CsvFile() {
  if (file_ && !is_stdout_) {
    std::fclose(file_);
    std::remove(temp_.c_str());
  }
}

void CsvFile::Header(const std::vector<std::string>& columns) { Fields(columns); }

void CsvFile::Fields(const std::vector<std::string>& fields) {
  line_.clear();
  for (size_t i = 0; i < fields.size(); ++i) {
    if (i) line_ += ',';
    line_ += fields[i];
  }
  line_ += '\n';
  std::fwrite(line_.data(), 1, line_.size(), file_);
}

void CsvFile::Row(const std::vector<double>& values) { Row({}, values); }

void CsvFile::Row(const std::vector<std::string>& prefix, const std::vector<double>& values) {
  line_.clear();
  for (const std::string& field : prefix) {
    line_ += field;
    line_ += ',';
  }
  for (size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      throw Error(fmt::format("{}: refusing to write a non-finite value", path_));
    }
    if (i) line_ += ',';
    fmt::format_to(std::back_inserter(line_), "{}", values[i]);
  }
  line_ += '\n';
  std::fwrite(line_.data(), 1, line_.size(), file_);
}

void CsvFile::Commit() {
  if (is_stdout_) {
    std::fflush(stdout);
    return;
  }
  const bool ok = std::fflush(file_) == 0 && !std::ferror(file_);
  std::fclose(file_);
  file_ = nullptr;
  if (!ok || std::rename(temp_.c_str(), path_.c_str()) != 0) {
    const int error = errno;
    std::remove(temp_.c_str());
    throw Error(fmt::format("{}: cannot write ({})", path_, std::strerror(error)));
  }
}

}  // namespace contactlaws::cli
