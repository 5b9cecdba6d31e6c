// Copyright contactlaws authors.
//
// The command line's option parsing: restitution lists and ranges, law lists.

#include "cli/options.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "contactlaws/contactlaws.h"

namespace contactlaws {
namespace {

using cli::ParseLawList;
using cli::ParseRestitutionList;

// The message of the Error fn throws, or "" when it throws none.
template <typename Fn>
std::string ErrorOf(Fn fn) {
  try {
    fn();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(OptionsTest, RestitutionRangeGivesTheDecimalValues) {
  const std::vector<double> values = ParseRestitutionList("--restitution", "0.1:1.0:0.1");
  // rounded to 12 decimals: 0.1 + 2 * 0.1 is 0.30000000000000004 unrounded
  EXPECT_EQ(values, (std::vector<double>{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0}));
  EXPECT_EQ(ParseRestitutionList("--restitution", "0.05:1:0.05").size(), 20u);
  EXPECT_EQ(ParseRestitutionList("--restitution", "0.5:0.5:0.1"), std::vector<double>{0.5});
  EXPECT_EQ(ParseRestitutionList("--restitution", "0:1:0.3"),
            (std::vector<double>{0.0, 0.3, 0.6, 0.9}));
  EXPECT_EQ(ParseRestitutionList("--restitution", "0.9,0.6,0.3"),
            (std::vector<double>{0.9, 0.6, 0.3}));
  EXPECT_EQ(ParseRestitutionList("--restitution", "1"), std::vector<double>{1.0});
}

TEST(OptionsTest, BadRestitutionListsAreRefusedByName) {
  const struct {
    const char* text;
    const char* message;
  } cases[] = {
      {"1:0:0.1", "--restitution=1:0:0.1 must have start <= stop (start:stop:step)"},
      {"0:1:0", "--restitution=0:1:0 must have a step > 0 (start:stop:step)"},
      {"0:1:-0.1", "--restitution=0:1:-0.1 must have a step > 0 (start:stop:step)"},
      {"0:1", "--restitution=0:1 must be E1,E2,... or start:stop:step"},
      {"0.5,abc", "--restitution=0.5,abc has 'abc', which is not a finite number"},
      {"0.5,", "--restitution=0.5, has '', which is not a finite number"},
      {"nan", "--restitution=nan has 'nan', which is not a finite number"},
      {"0.5,1.5", "--restitution=0.5,1.5 has 1.5, outside [0, 1]"},
      {"0.5:1.5:0.5", "--restitution=0.5:1.5:0.5 has 1.5, outside [0, 1]"},
      {"0.5,0.5", "--restitution=0.5,0.5 has 0.5 twice"},
      {"0:1:1e-9", "--restitution=0:1:1e-9 expands to more than 100000 values"},
  };
  for (const auto& c : cases) {
    EXPECT_EQ(ErrorOf([&] { ParseRestitutionList("--restitution", c.text); }), c.message);
  }
}

TEST(OptionsTest, LawLists) {
  EXPECT_EQ(ParseLawList("--laws", "all"),
            std::vector<LawId>(AllLaws().begin(), AllLaws().end()));
  EXPECT_EQ(ParseLawList("--laws", "flores,hertz"),
            (std::vector<LawId>{*ParseLawName("flores"), *ParseLawName("hertz")}));
  EXPECT_EQ(ErrorOf([] { ParseLawList("--laws", "flores,hooke"); }),
            "--laws=flores,hooke has 'hooke', which is not a law (all, " + LawNameList() + ")");
  EXPECT_EQ(ErrorOf([] { ParseLawList("--laws", "flores,flores"); }),
            "--laws=flores,flores names flores twice");
}

}  // namespace
}  // namespace contactlaws
