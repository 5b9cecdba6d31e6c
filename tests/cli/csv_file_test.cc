// Copyright contactlaws authors.
//
// The CSV writer's numbers: AppendShortest writes what fmt's "{}" writes,
// byte for byte, so that every CSV the program writes stays the same.

#include "cli/csv_file.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace contactlaws {
namespace {

std::string Shortest(double v) {
  std::string s;
  cli::AppendShortest(&s, v);
  return s;
}

TEST(CsvFileTest, ShortestIsFmtsFormOnItsBoundaries) {
  const double cases[] = {0.0, 1.0, -1.0, 0.1, 0.5, 1.5, 10, 100, 1500, 123456789,
                          // fixed below 1e16, exponent form from it; 1e-4 fixed, 1e-5 not
                          9999999999999998.0, 1e15, 1e16, 1.5e16, 0.0001, 0.00012345,
                          0.00009999, 1e-5, -1e-5, 2.5e-7,
                          // 17 significant digits, both forms
                          0.1 + 0.2, 1.0 / 3, 2.0 / 3 * 1e-6, 123456.78901234567,
                          // the ends of the double
                          std::numeric_limits<double>::max(), std::numeric_limits<double>::min(),
                          std::numeric_limits<double>::denorm_min(), -4.9406564584124654e-324,
                          1e308, 1e-308, 1e100, 1e-100, 5e-324, 9.87654321e-10, 6.02214076e23};
  for (double v : cases) EXPECT_EQ(Shortest(v), fmt::format("{}", v)) << fmt::format("{}", v);
}

// Random bit patterns (every exponent, subnormals among them) and numbers of
// a trajectory's sizes: the forms and the digits must agree on every one.
TEST(CsvFileTest, ShortestIsFmtsFormOnAMillionDoubles) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-12, 18);
  int compared = 0;
  for (int i = 0; i < 500000; ++i) {
    const uint64_t bits = random();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    if (!std::isfinite(v)) continue;
    ASSERT_EQ(Shortest(v), fmt::format("{}", v)) << bits;
    const double w = mantissa(random) * std::pow(10.0, exponent(random));
    ASSERT_EQ(Shortest(w), fmt::format("{}", w)) << fmt::format("{:.17g}", w);
    compared += 2;
  }
  EXPECT_GT(compared, 995000);
}

TEST(CsvFileTest, ARowWritesZeroForNegativeZeroAndRefusesWhatIsNotFinite) {
  std::string line;
  EXPECT_TRUE(cli::AppendRow(&line, {"a"}, {-0.0, 1e-5, 0.25}));
  EXPECT_EQ(line, "a,0,1e-05,0.25\n");
  EXPECT_FALSE(cli::AppendRow(&line, {}, {1.0, std::nan("")}));
  EXPECT_EQ(line, "a,0,1e-05,0.25\n");
}

}  // namespace
}  // namespace contactlaws
