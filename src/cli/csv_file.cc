// Copyright contactlaws authors.

#include "cli/csv_file.h"

#include <charconv>
#include <cmath>

#include <filesystem>

#include <fmt/format.h>

#include "contactlaws/contact_model.h"

namespace contactlaws::cli {

bool SamePath(const std::string& a, const std::string& b) {
  if (a == "-" || b == "-") return a == b;
  std::error_code code;
  if (std::filesystem::equivalent(a, b, code)) return true;
  const auto normal = [](const std::string& path) {
    std::error_code ignored;
    return std::filesystem::absolute(path, ignored).lexically_normal();
  };
  return normal(a) == normal(b);
}

CsvFile::CsvFile(std::string path) : path_(std::move(path)) {
  if (path_ == "-") {
    file_ = stdout;
    return;
  }
  pending_.emplace(path_, "w");
  file_ = pending_->get();
}

CsvFile::~CsvFile() = default;

void CsvFile::Fields(const std::vector<std::string>& fields) {
  line_.clear();
  AppendFields(&line_, fields);
  Write(line_);
}

void CsvFile::Row(const std::vector<std::string>& prefix, const std::vector<double>& values) {
  line_.clear();
  if (!AppendRow(&line_, prefix, values)) {
    throw Error(fmt::format("{}: refusing to write a non-finite value", path_));
  }
  Write(line_);
}

void CsvFile::Write(std::string_view lines) {
  if (!file_) return;
  std::fwrite(lines.data(), 1, lines.size(), file_);
}

void CsvFile::Flush() {
  if (file_) std::fflush(file_);
}

void CsvFile::Commit() {
  if (!pending_) {
    std::fflush(stdout);
    return;
  }
  file_ = nullptr;
  pending_->Commit();
}


void WriteTable(const app::Table& table, CsvFile* file) {
  file->Header(TableColumns(table));
  for (size_t i = 0; i < table.rows(); ++i) file->Fields(TableFields(table, i));
}

}  // namespace contactlaws::cli
