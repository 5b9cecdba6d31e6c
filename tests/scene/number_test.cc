// Copyright contactlaws authors.
//
// The one number parser: finite decimals, written whole; nothing else.

#include "scene/number.h"

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
