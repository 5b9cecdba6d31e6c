// Copyright contactlaws authors.
//
// The NPY format (numpy.lib.format, version 1.0: a 2-byte header length, a
// Python dictionary literal, the array's bytes after it) inside a ZIP archive
// (PKWARE's APPNOTE 6.3: stored members, ZIP64 sizes and offsets, so that a
// trajectory beyond 4 GiB is read as well; Python's zipfile, under
// numpy.load, checks every member's CRC-32).

#include "cli/npz_file.h"

#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>

#include <fmt/format.h>

#include "cli/crc32.h"
#include "contactlaws/contact_model.h"

namespace contactlaws::cli {
namespace {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the numbers are written as '<f8'");

constexpr char kMagic[] = "\x93NUMPY";
constexpr size_t kMagicLength = 6;
constexpr size_t kPrefix = kMagicLength + 2 + 2;  // magic, version 1.0, 2-byte length
constexpr size_t kAlignment = 64;                  // the array starts at a multiple of it
constexpr size_t kCountDigits = 20;                // digits of the largest size_t

// ZIP records (APPNOTE 4.3.7, 4.3.12, 4.3.14, 4.3.15, 4.3.16) and the ZIP64
// extra field (4.5.3)
constexpr uint32_t kLocalHeader = 0x04034b50;
constexpr uint32_t kCentralHeader = 0x02014b50;
constexpr uint32_t kEnd64 = 0x06064b50;
constexpr uint32_t kEnd64Locator = 0x07064b50;
constexpr uint32_t kEnd = 0x06054b50;
constexpr uint16_t kZip64Extra = 0x0001;
constexpr uint16_t kVersion = 45;           // 4.5: ZIP64
constexpr uint16_t kDate = (0 << 9) | (1 << 5) | 1;  // 1980-01-01, so that a run's bytes repeat
constexpr uint32_t kOverflow = 0xffffffff;  // "in the ZIP64 field"

const char kRowsName[] = "rows.npy";
const char kColumnsName[] = "columns.npy";

// Little-endian fields appended to a record.
class Record {
 public:
  Record& U16(uint16_t v) { return Bytes(v, 2); }
  Record& U32(uint32_t v) { return Bytes(v, 4); }
  Record& U64(uint64_t v) { return Bytes(v, 8); }
  Record& Text(std::string_view s) {
    bytes_.append(s);
    return *this;
  }
  const std::string& bytes() const { return bytes_; }

 private:
  Record& Bytes(uint64_t v, int n) {
    for (int b = 0; b < n; ++b) bytes_ += static_cast<char>((v >> (8 * b)) & 0xff);
    return *this;
  }
  std::string bytes_;
};

// The local header of a stored member; with sizes, a ZIP64 one (its sizes in
// the extra field, which has room for them whatever they are).
std::string LocalHeader(const char* name, uint32_t crc, uint64_t size, bool zip64) {
  Record r;
  r.U32(kLocalHeader).U16(zip64 ? kVersion : 20).U16(0).U16(0).U16(0).U16(kDate).U32(crc);
  if (zip64) {
    r.U32(kOverflow).U32(kOverflow);
  } else {
    r.U32(static_cast<uint32_t>(size)).U32(static_cast<uint32_t>(size));
  }
  r.U16(static_cast<uint16_t>(std::strlen(name))).U16(zip64 ? 20 : 0).Text(name);
  if (zip64) r.U16(kZip64Extra).U16(16).U64(size).U64(size);
  return r.bytes();
}

// The central directory's entry of a member, its sizes and offset in a ZIP64
// extra field.
std::string CentralHeader(const char* name, uint32_t crc, uint64_t size, uint64_t offset) {
  Record r;
  r.U32(kCentralHeader).U16(kVersion).U16(kVersion).U16(0).U16(0).U16(0).U16(kDate).U32(crc);
  r.U32(kOverflow).U32(kOverflow);
  r.U16(static_cast<uint16_t>(std::strlen(name))).U16(28).U16(0);  // name, extra, comment
  r.U16(0).U16(0).U32(0).U32(kOverflow);  // disk, attributes, the offset in the extra field
  r.Text(name);
  r.U16(kZip64Extra).U16(24).U64(size).U64(size).U64(offset);
  return r.bytes();
}

// The archive's end: the ZIP64 end record, its locator, the end record.
std::string End(uint64_t directory_offset, uint64_t directory_size, uint16_t entries) {
  const uint64_t end64_offset = directory_offset + directory_size;
  const auto narrow = [](uint64_t v) {
    return v < kOverflow ? static_cast<uint32_t>(v) : kOverflow;
  };
  Record r;
  r.U32(kEnd64).U64(44).U16(kVersion).U16(kVersion).U32(0).U32(0);
  r.U64(entries).U64(entries).U64(directory_size).U64(directory_offset);
  r.U32(kEnd64Locator).U32(0).U64(end64_offset).U32(1);
  r.U32(kEnd).U16(0).U16(0).U16(entries).U16(entries);
  r.U32(narrow(directory_size)).U32(narrow(directory_offset)).U16(0);
  return r.bytes();
}

// The code points of UTF-8 text; a malformed sequence reads as U+FFFD.
std::u32string CodePoints(std::string_view text) {
  constexpr char32_t kReplacement = 0xfffd;
  std::u32string out;
  for (size_t i = 0; i < text.size();) {
    const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char lead = byte(i);
    const int more = lead < 0x80 ? 0 : (lead >> 5) == 0x6 ? 1 : (lead >> 4) == 0xe ? 2
                   : (lead >> 3) == 0x1e ? 3 : -1;
    char32_t c = more == 0 ? lead : more == 1 ? lead & 0x1f : more == 2 ? lead & 0x0f : lead & 0x07;
    bool ok = more >= 0 && i + more < text.size();
    for (int k = 1; ok && k <= more; ++k) {
      ok = (byte(i + k) & 0xc0) == 0x80;
      c = (c << 6) | (byte(i + k) & 0x3f);
    }
    out += ok ? c : kReplacement;
    i += ok ? more + 1 : 1;
  }
  return out;
}

}  // namespace

bool HasExtension(std::string_view path, std::string_view extension) {
  return path.size() > extension.size() &&
         path.substr(path.size() - extension.size()) == extension;
}

std::string NpyHeader(std::string_view descr, const std::vector<size_t>& shape) {
  std::string dims;
  size_t room = 0;  // what larger dimensions could add
  for (const size_t n : shape) {
    const std::string digits = std::to_string(n);
    dims += (dims.empty() ? "" : ", ") + digits;
    room += kCountDigits - digits.size();
  }
  if (shape.size() == 1) dims += ',';  // Python's tuple of one
  const std::string dictionary =
      fmt::format("{{'descr': '{}', 'fortran_order': False, 'shape': ({}), }}", descr, dims);
  const size_t length =
      (kPrefix + dictionary.size() + room + 1 + kAlignment - 1) / kAlignment * kAlignment;
  std::string header(kMagic, kMagicLength);
  header += '\x01';
  header += '\0';
  const size_t size = length - kPrefix;
  header += static_cast<char>(size & 0xff);
  header += static_cast<char>(size >> 8);
  header += dictionary;
  header.append(length - header.size() - 1, ' ');
  header += '\n';
  return header;
}

NpzFile::NpzFile(std::string path) : file_(std::move(path), "wb") {}

void NpzFile::Write(const std::string& bytes) {
  if (file_.get()) std::fwrite(bytes.data(), 1, bytes.size(), file_.get());
  written_ += bytes.size();
}

void NpzFile::Header(const std::vector<std::string>& columns) {
  columns_ = columns.size();
  // the names as UTF-32 code units, each padded with zeros to the longest
  std::vector<std::u32string> names;
  size_t width = 1;
  for (const std::string& c : columns) {
    names.push_back(CodePoints(c));
    width = std::max(width, names.back().size());
  }
  std::string array = NpyHeader(fmt::format("<U{}", width), {columns_});
  for (std::u32string& name : names) {
    name.resize(width, U'\0');
    array.append(reinterpret_cast<const char*>(name.data()), width * sizeof(char32_t));
  }
  names_ = {kColumnsName, written_, array.size(), Crc32(0, array.data(), array.size())};
  Write(LocalHeader(kColumnsName, names_.crc, names_.size, false));
  Write(array);

  // rows: its local header and its NPY header are written again at Commit
  rows_member_.name = kRowsName;
  rows_member_.offset = written_;
  Write(LocalHeader(kRowsName, 0, 0, true));
  rows_data_offset_ = written_;
  const std::string header = NpyHeader("<f8", {0, columns_});
  rows_header_length_ = header.size();
  Write(header);
}

void NpzFile::Row(const std::vector<double>& values) {
  for (const double v : values) {
    if (!std::isfinite(v)) {
      throw Error(fmt::format("{}: refusing to write a non-finite value", file_.path()));
    }
  }
  ++rows_;
  const size_t bytes = values.size() * sizeof(double);
  data_crc_ = Crc32(data_crc_, values.data(), bytes);
  if (file_.get()) std::fwrite(values.data(), 1, bytes, file_.get());
  written_ += bytes;
}

void NpzFile::Commit() {
  std::FILE* f = file_.get();
  if (f) {
    const std::string header = NpyHeader("<f8", {rows_, columns_});
    const uint64_t data_bytes = written_ - rows_data_offset_ - rows_header_length_;
    rows_member_.size = header.size() + data_bytes;
    rows_member_.crc = static_cast<uint32_t>(
        crc32_combine(Crc32(0, header.data(), header.size()), data_crc_,
                      static_cast<z_off_t>(data_bytes)));
    const uint64_t directory = written_;
    const std::string local = LocalHeader(kRowsName, rows_member_.crc, rows_member_.size, true);
    const bool ok =
        header.size() == rows_header_length_ &&
        std::fseek(f, static_cast<long>(rows_member_.offset), SEEK_SET) == 0 &&
        std::fwrite(local.data(), 1, local.size(), f) == local.size() &&
        std::fwrite(header.data(), 1, header.size(), f) == header.size() &&
        std::fseek(f, 0, SEEK_END) == 0;
    if (!ok) throw Error(fmt::format("{}: cannot write ({})", file_.path(), std::strerror(errno)));
    std::string central;
    for (const Member* m : {&names_, &rows_member_}) {
      central += CentralHeader(m->name.c_str(), m->crc, m->size, m->offset);
    }
    Write(central);
    Write(End(directory, central.size(), 2));
  }
  file_.Commit();
}

}  // namespace contactlaws::cli
