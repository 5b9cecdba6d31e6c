// Copyright contactlaws authors.
//
// Measured trajectories (docs/identification.md): a long CSV, one row per
// sample,
//
//   trajectory,time,<body>.x,.y,.z,.qw,.qx,.qy,.qz[,.vx,.vy,.vz,.wx,.wy,.wz],
//              <joint>.q[,.v],...
//
// with the run CSV's own column names and units: positions in m, the body's
// orientation as the unit quaternion (w, x, y, z) from its frame to the
// world's, linear velocity in m/s and angular velocity in rad/s, both in the
// world frame; a hinge's q in rad, a slide's in m. The rows of one
// trajectory are consecutive, its times strictly increasing.

#ifndef CONTACTLAWS_MEASURED_H_
#define CONTACTLAWS_MEASURED_H_

#include <string>
#include <string_view>
#include <vector>

namespace contactlaws {

// One trial: its samples, row by row.
struct MeasuredTrajectory {
  std::string name;          // the trajectory column's value
  int first_row = 0;         // the file's line of its first sample (header: 1)
  std::vector<double> time;  // s, strictly increasing
  // sample k's value of column c (MeasuredData::columns) at k * columns + c
  std::vector<double> values;
  int samples() const { return static_cast<int>(time.size()); }
};

struct MeasuredData {
  std::string source;                // the file, for messages
  std::vector<std::string> columns;  // the columns after trajectory,time
  std::vector<MeasuredTrajectory> trajectories;
  // The index of a column in columns, -1 when absent.
  int Column(std::string_view name) const;
};

// The columns a trajectory CSV may give for a body, in the order they are
// written, and a joint's.
inline constexpr const char* kBodyQuantities[] = {"x",  "y",  "z",  "qw", "qx", "qy", "qz",
                                                  "vx", "vy", "vz", "wx", "wy", "wz"};
inline constexpr const char* kJointQuantities[] = {"q", "v"};

// A quaternion column group whose norm is off unity by more than this is
// refused: the tracking writes ~7 digits (1e-6), a quaternion that far off
// is not a rotation.
inline constexpr double kQuaternionNormTolerance = 1e-3;

// Reads and checks a trajectory file. Throws Error naming the file, the row
// (its line), the column and the value: a header without trajectory,time
// first, a repeated or malformed column, a row of another width, a value
// that is not a finite number, a time not strictly increasing within a
// trajectory, a trajectory whose rows are not consecutive or that has fewer
// than 2 samples, a quaternion far from unit norm, an empty file.
MeasuredData ReadMeasuredData(const std::string& path);

// The same from text in memory; source names it in messages.
MeasuredData ParseMeasuredData(std::string_view text, const std::string& source);

// The same from a table's columns (Python's DataFrame): per sample its
// trajectory's name and its time (s), and the measured columns' names with
// their values (values[c][k]: column c at sample k), checked as a file is;
// a sample is named in messages "SOURCE row K" (K from 0). Also throws
// Error for columns of other lengths than the samples'.
MeasuredData MeasuredFromColumns(const std::vector<std::string>& trajectory,
                                 const std::vector<double>& time,
                                 const std::vector<std::string>& columns,
                                 const std::vector<std::vector<double>>& values,
                                 const std::string& source);

}  // namespace contactlaws

#endif  // CONTACTLAWS_MEASURED_H_
