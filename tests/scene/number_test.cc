// Copyright contactlaws authors.
//
// The one number parser: finite decimals, written whole; nothing else.

#include "scene/number.h"

#include <cstdlib>
#include <cstring>
#include <optional>
#include <random>
#include <string>

#include <gtest/gtest.h>

namespace contactlaws {
namespace {

TEST(NumberTest, FiniteDecimalsAreRead) {
  EXPECT_EQ(ParseNumber("0"), 0.0);
  EXPECT_EQ(ParseNumber("1.5"), 1.5);
  EXPECT_EQ(ParseNumber("-2"), -2.0);
  EXPECT_EQ(ParseNumber("+3"), 3.0);
  EXPECT_EQ(ParseNumber(".5"), 0.5);
  EXPECT_EQ(ParseNumber("5."), 5.0);
  EXPECT_EQ(ParseNumber("1.4e8"), 1.4e8);
  EXPECT_EQ(ParseNumber("1E-5"), 1e-5);
  EXPECT_EQ(ParseNumber("2e+3"), 2e3);
  // the decimal the text names, as strtod rounds it
  EXPECT_EQ(ParseNumber("0.1"), 0.1);
}

TEST(NumberTest, EverythingElseIsRefused) {
  for (const char* text :
       {"", " 1", "1 ", "1x", "0x10", "0x1p-1", "inf", "-inf", "nan", "NaN", "infinity", "1e",
        "e5", ".", "-", "+-1", "1e5e3", "1..2", "1,5", "1e999", "-1e999", "1e-400", "٣"}) {
    EXPECT_FALSE(ParseNumber(text).has_value()) << "'" << text << "'";
  }
  // more than 64 characters, though a decimal
  EXPECT_FALSE(ParseNumber(std::string(65, '1')).has_value());
  EXPECT_TRUE(ParseNumber(std::string(64, '1')).has_value());
}

// Every number the rule takes is strtod's value, to the bit, whichever way
// it is read: random decimals of 1 to 25 significant digits over the whole
// exponent range, with the signs, points and exponent forms the rule takes
// (a parser off by an ulp anywhere fails here).
TEST(NumberTest, ValuesAreStrtodsToTheBit) {
  std::mt19937_64 random(20261201);
  auto pick = [&](int n) { return static_cast<int>(random() % n); };
  int read = 0;
  for (int i = 0; i < 200000; ++i) {
    std::string text = pick(3) == 0 ? "-" : pick(2) ? "" : "+";
    const int digits = 1 + pick(25);
    const int point = pick(digits + 1);
    for (int k = 0; k < digits; ++k) {
      if (k == point) text += '.';
      text += static_cast<char>('0' + pick(10));
    }
    if (pick(2)) text += (pick(2) ? "e" : "E") + std::to_string(pick(640) - 330);
    const double expected = std::strtod(text.c_str(), nullptr);
    const std::optional<double> value = ParseNumber(text);
    if (!value) continue;  // beyond the range (ERANGE): NumberTest above
    ++read;
    EXPECT_EQ(std::memcmp(&*value, &expected, sizeof expected), 0) << text;
  }
  EXPECT_GT(read, 150000);  // most of them within the range: the test reads
}

TEST(NumberTest, WholeNumbersInARange) {
  EXPECT_EQ(ParseWholeNumber("3", 0, 5), 3);
  EXPECT_EQ(ParseWholeNumber("3.0", 0, 5), 3);
  EXPECT_EQ(ParseWholeNumber("3e0", 0, 5), 3);
  EXPECT_FALSE(ParseWholeNumber("3.5", 0, 5).has_value());
  EXPECT_FALSE(ParseWholeNumber("6", 0, 5).has_value());
  EXPECT_FALSE(ParseWholeNumber("-1", 0, 5).has_value());
  EXPECT_FALSE(ParseWholeNumber("0x3", 0, 5).has_value());
}

}  // namespace
}  // namespace contactlaws
