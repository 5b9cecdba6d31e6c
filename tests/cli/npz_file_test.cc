// Copyright contactlaws authors.
//
// The NumPy archive writer, read back here by the formats' rules: the NPY
// header (magic, version, little-endian length, a dictionary padded to a
// multiple of 64 bytes ending in a newline), and the ZIP records (every
// member's local header, its CRC-32 recomputed from its bytes, the central
// directory reached from the end records). python/tests reads the files
// with numpy itself.

#include "cli/npz_file.h"

#include <sys/stat.h>

#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/pending_file.h"
#include "contactlaws/contact_model.h"

namespace contactlaws {
namespace {

uint64_t Field(const std::string& bytes, size_t at, int n) {
  uint64_t v = 0;
  for (int b = 0; b < n; ++b) {
    v |= static_cast<uint64_t>(static_cast<unsigned char>(bytes.at(at + b))) << (8 * b);
  }
  return v;
}

struct Npy {
  std::string dictionary;
  size_t data_offset = 0;  // from the array's start
};

Npy ParseNpy(const std::string& bytes) {
  Npy p;
  EXPECT_EQ(bytes.substr(0, 6), std::string("\x93NUMPY", 6));
  EXPECT_EQ(bytes[6], 1);
  const size_t length = Field(bytes, 8, 2);
  p.data_offset = 10 + length;
  p.dictionary = bytes.substr(10, length);
  EXPECT_EQ(p.data_offset % 64, 0u);
  EXPECT_EQ(p.dictionary.back(), '\n');
  return p;
}

// The members of a ZIP archive by name: their stored bytes, each checked
// against its CRC-32 and the central directory's sizes.
std::map<std::string, std::string> Members(const std::string& zip) {
  // the end record, its ZIP64 locator before it, the ZIP64 end record there
  constexpr size_t kEnd = 22, kLocator = 20;
  const size_t end = zip.size() - kEnd;
  EXPECT_EQ(Field(zip, end, 4), 0x06054b50u);
  EXPECT_EQ(Field(zip, end - kLocator, 4), 0x07064b50u);
  const size_t end64 = Field(zip, end - kLocator + 8, 8);
  EXPECT_EQ(Field(zip, end64, 4), 0x06064b50u);
  const uint64_t entries = Field(zip, end64 + 32, 8);
  size_t at = Field(zip, end64 + 48, 8);  // the central directory
  EXPECT_EQ(at + Field(zip, end64 + 40, 8), end64);
  std::map<std::string, std::string> members;
  for (uint64_t e = 0; e < entries; ++e) {
    EXPECT_EQ(Field(zip, at, 4), 0x02014b50u);
    EXPECT_EQ(Field(zip, at + 10, 2), 0u);  // stored
    const uint32_t crc = static_cast<uint32_t>(Field(zip, at + 16, 4));
    const size_t name_length = Field(zip, at + 28, 2), extra_length = Field(zip, at + 30, 2);
    const std::string name = zip.substr(at + 46, name_length);
    // the ZIP64 field: the sizes and the local header's offset
    const size_t extra = at + 46 + name_length;
    EXPECT_EQ(Field(zip, extra, 2), 1u);
    const uint64_t size = Field(zip, extra + 4, 8);
    EXPECT_EQ(Field(zip, extra + 12, 8), size);
    const uint64_t local = Field(zip, extra + 20, 8);
    EXPECT_EQ(Field(zip, local, 4), 0x04034b50u);
    EXPECT_EQ(Field(zip, local + 14, 4), crc);
    const size_t data = local + 30 + Field(zip, local + 26, 2) + Field(zip, local + 28, 2);
    EXPECT_EQ(zip.substr(local + 30, name_length), name);
    const std::string bytes = zip.substr(data, size);
    EXPECT_EQ(crc32(0, reinterpret_cast<const Bytef*>(bytes.data()), bytes.size()), crc) << name;
    members[name] = bytes;
    at = extra + extra_length;
  }
  return members;
}

std::string Read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(NpzFileTest, TheNpyHeaderIsWhatNumpyReadsWithRoomForItsCounts) {
  const std::string header = cli::NpyHeader("<f8", {12, 3});
  const Npy p = ParseNpy(header);
  EXPECT_EQ(p.data_offset, header.size());
  EXPECT_EQ(p.dictionary.rfind("{'descr': '<f8', 'fortran_order': False, 'shape': (12, 3), }", 0),
            0u);
  EXPECT_EQ(cli::NpyHeader("<f8", {std::numeric_limits<size_t>::max(), 3}).size(), header.size());
  EXPECT_NE(ParseNpy(cli::NpyHeader("<U4", {7})).dictionary.find("'shape': (7,)"),
            std::string::npos);
}

TEST(NpzFileTest, TheArchiveHoldsTheRowsAndTheColumnNames) {
  const std::string path = testing::TempDir() + "npz_file_test.npz";
  {
    cli::NpzFile file(path);
    file.Header({"time", "bille.\xc3\xa9z"});  // é: two bytes, one code point
    file.Row({0.0, 0.1});
    file.Row({1e-3, -0.0});
    file.Row({2e-3, std::numeric_limits<double>::denorm_min()});
    file.Commit();
  }
  const std::map<std::string, std::string> members = Members(Read(path));
  ASSERT_EQ(members.size(), 2u);

  const std::string& rows = members.at("rows.npy");
  const Npy r = ParseNpy(rows);
  EXPECT_NE(r.dictionary.find("'descr': '<f8'"), std::string::npos);
  EXPECT_NE(r.dictionary.find("'shape': (3, 2)"), std::string::npos);
  ASSERT_EQ(rows.size(), r.data_offset + 6 * sizeof(double));
  double values[6];
  std::memcpy(values, rows.data() + r.data_offset, sizeof values);
  EXPECT_EQ(values[1], 0.1);
  EXPECT_TRUE(std::signbit(values[3]));
  EXPECT_EQ(values[5], std::numeric_limits<double>::denorm_min());

  const std::string& columns = members.at("columns.npy");
  const Npy c = ParseNpy(columns);
  EXPECT_NE(c.dictionary.find("'descr': '<U8', 'fortran_order': False, 'shape': (2,)"),
            std::string::npos);
  ASSERT_EQ(columns.size(), c.data_offset + 2 * 8 * 4);
  std::u32string names(16, U'\0');
  std::memcpy(names.data(), columns.data() + c.data_offset, 16 * 4);
  EXPECT_EQ(names, std::u32string(U"time\0\0\0\0bille.\u00e9z", 16));
  std::remove(path.c_str());
}

TEST(NpzFileTest, AMalformedNameReadsAsTheReplacementCharacter) {
  const std::string path = testing::TempDir() + "npz_file_malformed.npz";
  {
    cli::NpzFile file(path);
    file.Header({"a\xc3"});  // a lead byte cut short
    file.Commit();
  }
  const std::string columns = Members(Read(path)).at("columns.npy");
  const Npy c = ParseNpy(columns);
  std::u32string name(2, U'\0');
  std::memcpy(name.data(), columns.data() + c.data_offset, 2 * 4);
  EXPECT_EQ(name, std::u32string(U"a\ufffd"));
  std::remove(path.c_str());
}

TEST(NpzFileTest, AnUncommittedFileIsRemovedAndNonFiniteRefused) {
  const std::string path = testing::TempDir() + "npz_file_refused.npz";
  {
    cli::NpzFile file(path);
    file.Header({"time"});
    EXPECT_THROW(file.Row({std::nan("")}), Error);
  }
  EXPECT_FALSE(std::ifstream(path).good());
  EXPECT_FALSE(std::ifstream(path + ".tmp").good());
  EXPECT_TRUE(cli::HasExtension("a/b.npz", ".npz"));
  EXPECT_FALSE(cli::HasExtension(".npz", ".npz"));
  EXPECT_FALSE(cli::HasExtension("b.csv", ".npz"));
}

// A trajectory of 100 MB goes to the file system in large writes: what is
// written stays in PendingFile's buffer until a megabyte has gathered. (The
// buffer glibc allocates itself is 4 KB whatever setvbuf's size: 25,359
// system calls for a 104 MB trajectory, most of its system time.)
TEST(PendingFileTest, WritesAMegabyteAtATime) {
  const std::string path = testing::TempDir() + "pending_file_buffer.bin";
  cli::PendingFile file(path, "wb");
  const std::vector<char> row(5192, 'x');  // a row of 649 numbers
  auto size_on_disk = [&path] {
    struct stat s {};
    return stat((path + ".tmp").c_str(), &s) == 0 ? static_cast<long>(s.st_size) : -1L;
  };
  for (int i = 0; i < 190; ++i) std::fwrite(row.data(), 1, row.size(), file.get());  // 986 KB
  EXPECT_EQ(size_on_disk(), 0);
  for (int i = 0; i < 20; ++i) std::fwrite(row.data(), 1, row.size(), file.get());
  EXPECT_GE(size_on_disk(), 1L << 20);
  file.Commit();
}

}  // namespace
}  // namespace contactlaws
