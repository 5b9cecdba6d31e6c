// Copyright contactlaws authors.

#include "contactlaws/replay.h"

#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <unordered_map>

#include <fmt/format.h>

#include "contactlaws/contact_model.h"
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
  // rows: "SOURCE:LINE" of a file, else "SOURCE row K" (a table's, from 0)
  Reader(const std::string& source, bool lines) : source_(source), lines_(lines) {}

  [[noreturn]] void Fail(int row, std::string_view what) const {
    throw Error(fmt::format(lines_ ? "{}:{}: {}" : "{} row {}: {}", source_, row, what));
  }

  // The header's (a file's line 1, a table's column names).
  [[noreturn]] void FailHeader(std::string_view what) const {
    if (lines_) Fail(1, what);
    throw Error(fmt::format("{}: {}", source_, what));
  }

  void Header(std::string_view line, MeasuredData* data) const {
    const std::vector<std::string_view> fields = Fields(line);
    if (fields.size() < 3 || fields[0] != "trajectory" || fields[1] != "time") {
      Fail(1, fmt::format("the header must start with trajectory,time and name at least one "
                          "measured column, not '{}'",
                          line.substr(0, 80)));
    }
    Columns(std::vector<std::string_view>(fields.begin() + 2, fields.end()), data);
  }

  // The measured columns' names (after trajectory,time), checked into data.
  void Columns(const std::vector<std::string_view>& names, MeasuredData* data) const {
    for (size_t k = 0; k < names.size(); ++k) {
      const size_t c = k + 2;
      const std::string_view name = names[k];
      const size_t dot = name.rfind('.');
      if (dot == std::string_view::npos || dot == 0 || dot + 1 == name.size()) {
        FailHeader(fmt::format("column {} '{}' is not of the form <body>.<quantity> or "
                            "<joint>.<quantity>",
                            c + 1, name));
      }
      if (data->Column(name) >= 0) FailHeader(fmt::format("column '{}' is given twice", name));
      data->columns.emplace_back(name);
    }
  }

  // One sample of a file into data; row is the file's line.
  void Sample(int row, std::string_view line, MeasuredData* data) {
    const std::vector<std::string_view> fields = Fields(line);
    const size_t width = data->columns.size() + 2;
    if (fields.size() != width) {
      Fail(row, fmt::format("{} fields where the header has {}", fields.size(), width));
    }
    auto value = [&](size_t f, std::string_view column) {
      const std::optional<double> v = ParseNumber(fields[f]);
      if (!v) {
        Fail(row, fmt::format("column {}: value '{}' is not a finite number", column, fields[f]));
      }
      return *v;
    };
    Sample(row, fields[0], value, fields[1], data);
  }

  // One sample into data: its trajectory's name, value(f, column) of field f
  // (1: time, 2..: the columns), time's text for messages.
  template <typename Value>
  void Sample(int row, std::string_view name, const Value& value, std::string_view time_text,
              MeasuredData* data) {
    if (name.empty()) Fail(row, "column trajectory: empty value");
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
                            time_text, t.name, t.time.back()));
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
  bool lines_;
  std::unordered_map<std::string, int> seen_;  // trajectory -> its first line
};

}  // namespace

MeasuredData ParseMeasuredData(std::string_view text, const std::string& source) {
  MeasuredData data;
  data.source = source;
  Reader reader(source, true);
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

MeasuredData MeasuredFromColumns(const std::vector<std::string>& trajectory,
                                 const std::vector<double>& time,
                                 const std::vector<std::string>& columns,
                                 const std::vector<std::vector<double>>& values,
                                 const std::string& source) {
  MeasuredData data;
  data.source = source;
  Reader reader(source, false);
  if (columns.size() != values.size()) {
    throw Error(fmt::format("{}: {} column names for {} columns of values", source,
                            columns.size(), values.size()));
  }
  if (columns.empty()) {
    throw Error(fmt::format("{}: no measured column beside trajectory and time", source));
  }
  const size_t rows = trajectory.size();
  if (time.size() != rows) {
    throw Error(fmt::format("{}: {} times for {} samples", source, time.size(), rows));
  }
  for (size_t c = 0; c < columns.size(); ++c) {
    if (values[c].size() != rows) {
      throw Error(fmt::format("{}: column {}: {} values for {} samples", source, columns[c],
                              values[c].size(), rows));
    }
  }
  reader.Columns(std::vector<std::string_view>(columns.begin(), columns.end()), &data);
  if (rows == 0) throw Error(fmt::format("{}: no sample", source));
  for (size_t k = 0; k < rows; ++k) {
    const int row = static_cast<int>(k);
    auto value = [&](size_t f, std::string_view column) {
      const double v = f == 1 ? time[k] : values[f - 2][k];
      if (!std::isfinite(v)) {
        reader.Fail(row, fmt::format("column {}: value {} is not a finite number", column, v));
      }
      return v;
    };
    reader.Sample(row, trajectory[k], value, fmt::format("{}", time[k]), &data);
  }
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
