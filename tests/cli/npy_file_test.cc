// Copyright contactlaws authors.
//
// The NumPy writer: the header numpy.lib.format reads (read back here by its
// rules: magic, version, little-endian length, a dictionary padded to a
// multiple of 64 bytes ending in a newline), the row count written at the
// commit, the records as the doubles given. tests in python/tests read the
// files with numpy itself.

#include "cli/npy_file.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "contactlaws/contact_model.h"

namespace contactlaws {
namespace {

struct Parsed {
  int version = 0;
  std::string dictionary;
  size_t data_offset = 0;
};

Parsed Parse(const std::string& bytes) {
  Parsed p;
  EXPECT_EQ(bytes.substr(0, 6), std::string("\x93NUMPY", 6));
  p.version = bytes[6];
  const size_t width = p.version == 1 ? 2 : 4;
  uint32_t length = 0;
  for (size_t b = 0; b < width; ++b) {
    length |= static_cast<uint32_t>(static_cast<unsigned char>(bytes[8 + b])) << (8 * b);
  }
  p.data_offset = 8 + width + length;
  p.dictionary = bytes.substr(8 + width, length);
  return p;
}

std::string Read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(NpyFileTest, TheHeaderIsWhatNumpyReads) {
  const std::string header = cli::NpyHeader({"time", "ball.z", "it's"}, 12);
  const Parsed p = Parse(header);
  EXPECT_EQ(p.version, 1);
  EXPECT_EQ(p.data_offset, header.size());
  EXPECT_EQ(header.size() % 64, 0u);
  EXPECT_EQ(header.back(), '\n');
  EXPECT_EQ(p.dictionary.rfind("{'descr': [('time', '<f8'), ('ball.z', '<f8'), ('it\\'s', '<f8')], "
                               "'fortran_order': False, 'shape': (12,), }", 0),
            0u);
}

TEST(NpyFileTest, AHeaderBeyond64KiBIsVersion2AndUtf8NamesVersion3) {
  std::vector<std::string> many(5000, "body_with_a_long_name.vx");
  const std::string large = cli::NpyHeader(many, 1);
  EXPECT_EQ(Parse(large).version, 2);
  EXPECT_GT(large.size(), 65535u);
  EXPECT_EQ(Parse(large).data_offset, large.size());
  EXPECT_EQ(Parse(cli::NpyHeader({"bille.\xc3\xa9"}, 1)).version, 3);
}

TEST(NpyFileTest, TheCommitWritesTheRowCountAndTheRecords) {
  const std::string path = testing::TempDir() + "npy_file_test.npy";
  {
    cli::NpyFile file(path);
    file.Header({"time", "x"});
    file.Row({0.0, 0.1});
    file.Row({1e-3, -0.0});
    file.Row({2e-3, std::numeric_limits<double>::denorm_min()});
    file.Commit();
  }
  const std::string bytes = Read(path);
  const Parsed p = Parse(bytes);
  EXPECT_NE(p.dictionary.find("'shape': (3,)"), std::string::npos);
  ASSERT_EQ(bytes.size(), p.data_offset + 6 * sizeof(double));
  double values[6];
  std::memcpy(values, bytes.data() + p.data_offset, sizeof values);
  EXPECT_EQ(values[1], 0.1);
  EXPECT_TRUE(std::signbit(values[3]));
  EXPECT_EQ(values[5], std::numeric_limits<double>::denorm_min());
  std::remove(path.c_str());
}

TEST(NpyFileTest, AnUncommittedFileIsRemovedAndNonFiniteRefused) {
  const std::string path = testing::TempDir() + "npy_file_refused.npy";
  {
    cli::NpyFile file(path);
    file.Header({"time"});
    EXPECT_THROW(file.Row({std::nan("")}), Error);
  }
  EXPECT_FALSE(std::ifstream(path).good());
  EXPECT_FALSE(std::ifstream(path + ".tmp").good());
  EXPECT_TRUE(cli::IsNpyPath("a/b.npy"));
  EXPECT_FALSE(cli::IsNpyPath(".npy"));
  EXPECT_FALSE(cli::IsNpyPath("b.csv"));
}

}  // namespace
}  // namespace contactlaws
