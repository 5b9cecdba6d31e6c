// Copyright contactlaws authors.

#include "app/csv_text.h"

#include <charconv>
#include <cmath>
#include <cstring>

#include <fmt/format.h>

namespace contactlaws::app {

void AppendFields(std::string* out, const std::vector<std::string>& fields) {
  for (size_t i = 0; i < fields.size(); ++i) {
    if (i) *out += ',';
    const std::string& f = fields[i];
    if (f.find_first_of(",\"\r\n") == std::string::npos) {
      *out += f;
      continue;
    }
    *out += '"';
    for (char c : f) {
      if (c == '"') *out += '"';
      *out += c;
    }
    *out += '"';
  }
  *out += '\n';
}

namespace {

// The longest form WriteShortest writes: "-0.0000" and 17 digits, or
// "-d." 16 digits "e-308"; with room to spare.
constexpr size_t kShortestRoom = 32;

// AppendShortest into [p, p + kShortestRoom); returns the end.
char* WriteShortest(char* p, double value) {
  // [-]d[.ddd]e(+|-)XX[X]: 17 significant digits at most
  char text[kShortestRoom];
  char* const end = std::to_chars(text, text + sizeof text, value, std::chars_format::scientific).ptr;
  const char* e = end - 4;  // e+XX or e+XXX
  if (*e != 'e') --e;
  int exponent = 0;
  for (const char* c = e + 2; c != end; ++c) exponent = 10 * exponent + (*c - '0');
  if (e[1] == '-') exponent = -exponent;
  if (exponent < -4 || exponent >= 16) {  // fmt's exponent form is to_chars' own
    std::memcpy(p, text, kShortestRoom);
    return p + (end - text);
  }
  const char* c = text;
  if (*c == '-') *p++ = *c++;
  // d[.ddd]: the first digit, then those after the point up to e
  const char* const first = c;
  const char* const rest = c[1] == '.' ? c + 2 : c + 1;
  if (exponent < 0) {  // 0.000ddd
    *p++ = '0';
    *p++ = '.';
    for (int k = -1; k > exponent; --k) *p++ = '0';
    *p++ = *first;
    for (c = rest; c != e; ++c) *p++ = *c;
    return p;
  }
  // ddd000 without a point, or dd.ddd
  *p++ = *first;
  c = rest;
  for (int k = 0; k < exponent; ++k) *p++ = c != e ? *c++ : '0';
  if (c != e) {
    *p++ = '.';
    while (c != e) *p++ = *c++;
  }
  return p;
}

}  // namespace

void AppendShortest(std::string* out, double value) {
  char text[kShortestRoom];
  out->append(text, static_cast<size_t>(WriteShortest(text, value) - text));
}

bool AppendRow(std::string* out, const std::vector<std::string>& prefix,
               const std::vector<double>& values) {
  for (double v : values) {
    if (!std::isfinite(v)) return false;
  }
  for (const std::string& field : prefix) {
    *out += field;
    *out += ',';
  }
  // the numbers written in place, the string cut to them after
  const size_t start = out->size();
  out->resize(start + values.size() * (kShortestRoom + 1) + 1);
  char* const first = out->data() + start;
  char* p = first;
  for (size_t i = 0; i < values.size(); ++i) {
    if (i) *p++ = ',';
    // -0 is written 0
    p = WriteShortest(p, values[i] == 0 ? 0.0 : values[i]);
  }
  *p++ = '\n';
  out->resize(start + (p - first));
  return true;
}

std::string Field(double value) {
  // no -0, inf or nan in a CSV: -0 is 0, and what is not finite is not known
  if (!std::isfinite(value)) return "";
  std::string field;
  AppendShortest(&field, value == 0 ? 0.0 : value);
  return field;
}

std::string Field(const std::optional<double>& value) { return value ? Field(*value) : ""; }

std::vector<std::string> TableFields(const app::Table& table, size_t i) {
  std::vector<std::string> fields;
  fields.reserve(table.columns().size());
  for (const app::Column& c : table.columns()) {
    fields.push_back(c.kind == app::Column::Kind::kText ? c.text[i] : Field(c.numbers[i]));
  }
  return fields;
}

std::vector<std::string> TableColumns(const app::Table& table) {
  std::vector<std::string> names;
  for (const app::Column& c : table.columns()) names.push_back(c.name);
  return names;
}

std::string TableCell(const std::optional<double>& value, const char* format) {
  return value ? fmt::format(fmt::runtime(format), *value) : "-";
}

}  // namespace contactlaws::app
