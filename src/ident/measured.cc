// Copyright contactlaws authors.

#include "contactlaws/measured.h"

#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <unordered_map>

#include <fmt/format.h>

#include "contactlaws/error.h"
#include "scene/number.h"

namespace contactlaws {

int MeasuredData::Column(std::string_view name) const {
  for (size_t c = 0; c < columns.size(); ++c) {
    if (columns[c] == name) return static_cast<int>(c);
  }
  return -1;
}

namespace {

// The comma-separated fields of one line (a trailing '\r' dropped).
std::vector<std::string_view> Fields(std::string_view line) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  std::vector<std::string_view> fields;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma - start));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

class Reader {
 public:
  explicit Reader(const std::string& source) : source_(source) {}

  [[noreturn]] void Fail(int row, std::string_view what) const {
    throw Error(fmt::format("{}:{}: {}", source_, row, what));
  }

  void Header(std::string_view line, MeasuredData* data) const {
    const std::vector<std::string_view> fields = Fields(line);
    if (fields.size() < 3 || fields[0] != "trajectory" || fields[1] != "time") {
      Fail(1, fmt::format("the header must start with trajectory,time and name at least one "
                          "measured column, not '{}'",
                          line.substr(0, 80)));
    }
    for (size_t c = 2; c < fields.size(); ++c) {
      const std::string_view name = fields[c];
      const size_t dot = name.rfind('.');
      if (dot == std::string_view::npos || dot == 0 || dot + 1 == name.size()) {
        Fail(1, fmt::format("column {} '{}' is not of the form <body>.<quantity> or "
                            "<joint>.<quantity>",
                            c + 1, name));
      }
      if (data->Column(name) >= 0) Fail(1, fmt::format("column '{}' is given twice", name));
      data->columns.emplace_back(name);
    }
  }

  // One sample into data; row is the file's line.
  void Sample(int row, std::string_view line, MeasuredData* data) {
    const std::vector<std::string_view> fields = Fields(line);
    const size_t width = data->columns.size() + 2;
    if (fields.size() != width) {
      Fail(row, fmt::format("{} fields where the header has {}", fields.size(), width));
    }
    const std::string_view name = fields[0];
    if (name.empty()) Fail(row, "column trajectory: empty value");
    auto value = [&](size_t f, std::string_view column) {
      const std::optional<double> v = ParseNumber(fields[f]);
      if (!v) {
        Fail(row, fmt::format("column {}: value '{}' is not a finite number", column, fields[f]));
      }
      return *v;
    };
    if (data->trajectories.empty() || data->trajectories.back().name != name) {
      if (!seen_.emplace(std::string(name), row).second) {
        Fail(row, fmt::format("column trajectory: '{}' continues after other trajectories (its "
                              "rows from line {} on must be consecutive)",
                              name, seen_[std::string(name)]));
      }
      Finish(data);
      MeasuredTrajectory t;
      t.name = std::string(name);
      t.first_row = row;
      data->trajectories.push_back(std::move(t));
    }
    MeasuredTrajectory& t = data->trajectories.back();
    const double time = value(1, "time");
    if (!t.time.empty() && !(time > t.time.back())) {
      Fail(row, fmt::format("column time: value {} does not increase within trajectory '{}' "
                            "(previous sample: {})",
                            fields[1], t.name, t.time.back()));
    }
    t.time.push_back(time);
    for (size_t c = 0; c < data->columns.size(); ++c) {
      t.values.push_back(value(c + 2, data->columns[c]));
    }
  }

  // Checks of the trajectory just read.
  void Finish(MeasuredData* data) const {
    if (data->trajectories.empty()) return;
    const MeasuredTrajectory& t = data->trajectories.back();
    if (t.samples() < 2) {
      Fail(t.first_row, fmt::format("trajectory '{}' has {} sample (at least 2 are needed)",
                                    t.name, t.samples()));
    }
  }

  // Every quaternion group (<body>.qw .qx .qy .qz) of unit norm, within
  // kQuaternionNormTolerance.
  void CheckQuaternions(const MeasuredData& data) const {
    for (size_t c = 0; c < data.columns.size(); ++c) {
      const std::string& name = data.columns[c];
      if (name.size() < 3 || name.compare(name.size() - 3, 3, ".qw") != 0) continue;
      const std::string body = name.substr(0, name.size() - 3);
      int q[4] = {static_cast<int>(c), data.Column(body + ".qx"), data.Column(body + ".qy"),
                  data.Column(body + ".qz")};
      if (q[1] < 0 || q[2] < 0 || q[3] < 0) continue;  // the scene's check names the gap
      const int width = static_cast<int>(data.columns.size());
      for (const MeasuredTrajectory& t : data.trajectories) {
        for (int k = 0; k < t.samples(); ++k) {
          double norm2 = 0;
          for (int i : q) norm2 += t.values[k * width + i] * t.values[k * width + i];
          const double norm = std::sqrt(norm2);
          if (std::abs(norm - 1.0) > kQuaternionNormTolerance) {
            Fail(t.first_row + k,
                 fmt::format("columns {}.qw .qx .qy .qz: norm {:.6g} is not a unit quaternion "
                             "(within {})",
                             body, norm, kQuaternionNormTolerance));
          }
        }
      }
    }
  }

 private:
  const std::string& source_;
  std::unordered_map<std::string, int> seen_;  // trajectory -> its first line
};

}  // namespace

MeasuredData ParseMeasuredData(std::string_view text, const std::string& source) {
  MeasuredData data;
  data.source = source;
  Reader reader(source);
  int row = 0;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++row;
    if (row == 1) {
      reader.Header(line, &data);
    } else if (!line.empty() && line != "\r") {
      reader.Sample(row, line, &data);
    }
  }
  if (row == 0) throw Error(fmt::format("{}: the file is empty (a header and samples expected)", source));
  if (data.trajectories.empty()) throw Error(fmt::format("{}: no sample after the header", source));
  reader.Finish(&data);
  reader.CheckQuaternions(data);
  return data;
}

MeasuredData ReadMeasuredData(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw Error(fmt::format("{}: cannot open the file", path));
  std::ostringstream text;
  text << file.rdbuf();
  return ParseMeasuredData(text.str(), path);
}

}  // namespace contactlaws
