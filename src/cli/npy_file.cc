// Copyright contactlaws authors.
//
// The NPY format: numpy.lib.format (version 1.0: a 2-byte header length,
// Latin-1; 2.0: a 4-byte one; 3.0: a 4-byte one, UTF-8). The header is a Python dictionary
// literal; the records follow it, each field little-endian ('<f8').

#include "cli/npy_file.h"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <fmt/format.h>

#include "contactlaws/contact_model.h"

namespace contactlaws::cli {
namespace {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the records are written as '<f8'");

constexpr char kMagic[] = "\x93NUMPY";
constexpr size_t kMagicLength = 6;
constexpr size_t kAlignment = 64;   // the records start at a multiple of it
constexpr size_t kCountRoom = 20;   // digits of the largest size_t

// A Python string literal of name (single-quoted).
std::string Quoted(const std::string& name) {
  std::string quoted = "'";
  for (const char c : name) {
    if (c == '\\' || c == '\'') quoted += '\\';
    quoted += c;
  }
  return quoted + "'";
}

bool Ascii(const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    for (const char c : name) {
      if (static_cast<unsigned char>(c) >= 0x80) return false;
    }
  }
  return true;
}

}  // namespace

bool IsNpyPath(std::string_view path) {
  constexpr std::string_view kExtension = ".npy";
  return path.size() > kExtension.size() &&
         path.substr(path.size() - kExtension.size()) == kExtension;
}

std::string NpyHeader(const std::vector<std::string>& columns, size_t rows, size_t length) {
  std::string dictionary = "{'descr': [";
  for (size_t i = 0; i < columns.size(); ++i) {
    dictionary += fmt::format("{}({}, '<f8')", i ? ", " : "", Quoted(columns[i]));
  }
  dictionary += fmt::format("], 'fortran_order': False, 'shape': ({},), }}", rows);
  // 1.0 while the header's length fits its 2 bytes, 2.0 beyond; 3.0 for
  // names that are not ASCII (UTF-8)
  const auto prefix = [](int version) { return kMagicLength + 2 + (version == 1 ? 2 : 4); };
  const auto least = [&](int version) {
    const size_t bytes = prefix(version) + dictionary.size() + kCountRoom + 1;
    return (bytes + kAlignment - 1) / kAlignment * kAlignment;
  };
  int version = Ascii(columns) ? 1 : 3;
  if (length == 0) length = least(version);
  if (version == 1 && length - prefix(1) > UINT16_MAX) {
    version = 2;
    if (length < least(2)) length = least(2);
  }
  std::string header(kMagic, kMagicLength);
  header += static_cast<char>(version);
  header += '\0';
  const uint32_t size = static_cast<uint32_t>(length - prefix(version));
  for (size_t b = 0; b < prefix(version) - kMagicLength - 2; ++b) {
    header += static_cast<char>((size >> (8 * b)) & 0xff);
  }
  header += dictionary;
  header.append(length - header.size() - 1, ' ');
  header += '\n';
  return header;
}

NpyFile::NpyFile(std::string path) : file_(std::move(path), "wb") {}

void NpyFile::Header(const std::vector<std::string>& columns) {
  columns_ = columns;
  const std::string header = NpyHeader(columns_, 0);
  header_length_ = header.size();
  if (file_.get()) std::fwrite(header.data(), 1, header.size(), file_.get());
}

void NpyFile::Row(const std::vector<double>& values) {
  for (const double v : values) {
    if (!std::isfinite(v)) {
      throw Error(fmt::format("{}: refusing to write a non-finite value", file_.path()));
    }
  }
  ++rows_;
  if (file_.get()) std::fwrite(values.data(), sizeof(double), values.size(), file_.get());
}

void NpyFile::Commit() {
  if (std::FILE* f = file_.get()) {
    // the row count, now known, into the header's room for it
    const std::string header = NpyHeader(columns_, rows_, header_length_);
    if (std::fseek(f, 0, SEEK_SET) != 0 ||
        std::fwrite(header.data(), 1, header.size(), f) != header.size()) {
      throw Error(fmt::format("{}: cannot write ({})", file_.path(), std::strerror(errno)));
    }
  }
  file_.Commit();
}

}  // namespace contactlaws::cli
