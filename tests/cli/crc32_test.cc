// Copyright contactlaws authors.

#include "cli/crc32.h"

#include <zlib.h>

#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace contactlaws::cli {
namespace {

uint32_t Zlib(uint32_t crc, const unsigned char* data, size_t size) {
  return static_cast<uint32_t>(crc32_z(crc, data, static_cast<z_size_t>(size)));
}

std::vector<unsigned char> RandomBytes(size_t size, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::vector<unsigned char> bytes(size);
  for (unsigned char& b : bytes) b = static_cast<unsigned char>(random());
  return bytes;
}

TEST(Crc32Test, IsZlibsForEveryLengthStartAndAlignment) {
  // lengths across the fold's cases (below 64 bytes: zlib's alone; then
  // four blocks, the 16-byte tail blocks, the last bytes) from every
  // alignment, and a register that is not zlib's start
  const std::vector<unsigned char> bytes = RandomBytes(1200, 1);
  std::mt19937 random(2);
  for (size_t offset = 0; offset < 16; ++offset) {
    for (size_t size = 0; size + offset <= 700; ++size) {
      const uint32_t start = size % 3 == 0 ? 0 : static_cast<uint32_t>(random());
      ASSERT_EQ(Crc32(start, bytes.data() + offset, size),
                Zlib(start, bytes.data() + offset, size))
          << "offset " << offset << ", " << size << " bytes, from " << start;
    }
  }
}

TEST(Crc32Test, ChainsOverAFileOfRows) {
  // a 10 MB file written row by row, as NpzFile does, and in one piece;
  // and the messages a fold gets wrong first: all zeros, all ones
  const std::vector<unsigned char> bytes = RandomBytes(10'000'000, 3);
  uint32_t chained = 0;
  constexpr size_t kRow = 649 * 8;
  for (size_t at = 0; at < bytes.size(); at += kRow) {
    chained = Crc32(chained, bytes.data() + at, std::min(kRow, bytes.size() - at));
  }
  const uint32_t zlib = Zlib(0, bytes.data(), bytes.size());
  EXPECT_EQ(chained, zlib);
  EXPECT_EQ(Crc32(0, bytes.data(), bytes.size()), zlib);
  for (const unsigned char fill : {0x00, 0xff}) {
    const std::vector<unsigned char> flat(4096 + 7, fill);
    EXPECT_EQ(Crc32(0, flat.data(), flat.size()), Zlib(0, flat.data(), flat.size()));
  }
  // the check value of the CRC-32 catalogue: "123456789" -> 0xcbf43926,
  // and 64 bytes of it, which the fold takes
  const char* nine = "123456789";
  EXPECT_EQ(Crc32(0, nine, 9), 0xcbf43926u);
  std::vector<unsigned char> repeated;
  for (int i = 0; i < 64; ++i) repeated.push_back(static_cast<unsigned char>(nine[i % 9]));
  EXPECT_EQ(Crc32(0, repeated.data(), repeated.size()),
            Zlib(0, repeated.data(), repeated.size()));
}

TEST(Crc32Test, FoldsWhereTheProcessorMultipliesCarryLess) {
#if defined(__x86_64__) || defined(__i386__)
  if (!__builtin_cpu_supports("pclmul")) GTEST_SKIP() << "no PCLMULQDQ here";
  EXPECT_TRUE(Crc32Folds());
#else
  EXPECT_FALSE(Crc32Folds());
#endif
}

}  // namespace
}  // namespace contactlaws::cli
