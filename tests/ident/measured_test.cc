// Copyright contactlaws authors.

#include "contactlaws/replay.h"

#include <string>

#include <gtest/gtest.h>

#include "contactlaws/contact_model.h"

namespace contactlaws {
namespace {

constexpr char kHeader[] = "trajectory,time,cube.x,cube.y,cube.z,cube.qw,cube.qx,cube.qy,cube.qz\n";

std::string Refusal(const std::string& text) {
  try {
    ParseMeasuredData(text, "tosses.csv");
  } catch (const Error& e) {
    return e.what();
  }
  return "accepted";
}

TEST(MeasuredTest, ReadsTrajectoriesInOrder) {
  const MeasuredData data = ParseMeasuredData(std::string(kHeader) +
                                                  "a,0,1,2,3,1,0,0,0\n"
                                                  "a,0.5,1,2,3,1,0,0,0\n"
                                                  "b,0,4,5,6,0,1,0,0\r\n"
                                                  "b,1,4,5,7,0,1,0,0\n",
                                              "tosses.csv");
  ASSERT_EQ(data.trajectories.size(), 2u);
  EXPECT_EQ(data.columns.size(), 7u);
  EXPECT_EQ(data.Column("cube.z"), 2);
  EXPECT_EQ(data.Column("cube.vx"), -1);
  const MeasuredTrajectory& b = data.trajectories[1];
  EXPECT_EQ(b.name, "b");
  EXPECT_EQ(b.first_row, 4);
  EXPECT_EQ(b.samples(), 2);
  EXPECT_EQ(b.values[1 * 7 + 2], 7.0);
}

TEST(MeasuredTest, RefusesBadInputNamingFileRowColumnAndValue) {
  const std::string h = kHeader;
  EXPECT_EQ(Refusal(""), "tosses.csv: the file is empty (a header and samples expected)");
  EXPECT_EQ(Refusal("time,trajectory,cube.x\n"),
            "tosses.csv:1: the header must start with trajectory,time and name at least one "
            "measured column, not 'time,trajectory,cube.x'");
  EXPECT_EQ(Refusal("trajectory,time,cube\n"),
            "tosses.csv:1: column 3 'cube' is not of the form <body>.<quantity> or "
            "<joint>.<quantity>");
  EXPECT_EQ(Refusal("trajectory,time,cube.x,cube.x\n"), "tosses.csv:1: column 'cube.x' is given twice");
  EXPECT_EQ(Refusal(h + "a,0,1,2,nan,1,0,0,0\n"),
            "tosses.csv:2: column cube.z: value 'nan' is not a finite number");
  EXPECT_EQ(Refusal(h + "a,0,1,2,inf,1,0,0,0\n"),
            "tosses.csv:2: column cube.z: value 'inf' is not a finite number");
  EXPECT_EQ(Refusal(h + "a,0,1,2,3,1,0,0\n"), "tosses.csv:2: 8 fields where the header has 9");
  EXPECT_EQ(Refusal(h + "a,0,1,2,3,1,0,0,0\na,0,1,2,3,1,0,0,0\n"),
            "tosses.csv:3: column time: value 0 does not increase within trajectory 'a' "
            "(previous sample: 0)");
  EXPECT_EQ(Refusal(h + "a,0,1,2,3,1,0,0,0\n"),
            "tosses.csv:2: trajectory 'a' has 1 sample (at least 2 are needed)");
  EXPECT_EQ(Refusal(h + "a,0,1,2,3,1,0,0,0\na,1,1,2,3,1,0,0,0\nb,0,1,2,3,1,0,0,0\n"
                        "b,1,1,2,3,1,0,0,0\na,2,1,2,3,1,0,0,0\n"),
            "tosses.csv:6: column trajectory: 'a' continues after other trajectories (its rows "
            "from line 2 on must be consecutive)");
  EXPECT_EQ(Refusal(h + "a,0,1,2,3,1,0,0,0\na,1,1,2,3,0.9,0,0,0\n"),
            "tosses.csv:3: columns cube.qw .qx .qy .qz: norm 0.9 is not a unit quaternion "
            "(within 0.001)");
  EXPECT_EQ(Refusal(h), "tosses.csv: no sample after the header");
}

TEST(MeasuredTest, AMissingFileIsNamed) {
  try {
    ReadMeasuredData("/nonexistent/tosses.csv");
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/tosses.csv: cannot open the file");
  }
}

}  // namespace
}  // namespace contactlaws
