// Copyright contactlaws authors.

#include "cli/options.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

namespace contactlaws::cli {
namespace {

constexpr char kLawNames[] =
    "hertz, kelvin-voigt, hunt-crossley, lankarani-nikravesh, flores";

// Longest restitution list a range may expand to.
constexpr long kMaxListLength = 100000;

std::vector<std::string_view> Split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  size_t start = 0;
  while (true) {
    const size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end == std::string_view::npos ? end : end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

// The whole of text as a finite number, or Refuse.
double Number(std::string_view option, std::string_view text, std::string_view whole) {
  const std::string s(text);
  char* end = nullptr;
  const double value = s.empty() ? 0.0 : std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(value)) {
    Refuse(option, whole, fmt::format("has '{}', which is not a finite number", text));
  }
  return value;
}

double Round12(double v) { return std::round(v * 1e12) / 1e12; }

}  // namespace

void Refuse(std::string_view option, std::string_view value, std::string_view requirement) {
  throw Error(fmt::format("{}={} {}", option, value, requirement));
}

void RequirePositive(std::string_view option, double value, std::string_view unit) {
  if (!(std::isfinite(value) && value > 0)) {
    Refuse(option, fmt::format("{}", value), fmt::format("must be a number > 0 ({})", unit));
  }
}

int ParseIntegrator(std::string_view name) {
  if (name == "euler") return mjINT_EULER;
  if (name == "rk4") return mjINT_RK4;
  if (name == "implicit") return mjINT_IMPLICIT;
  Refuse("--integrator", name, "must be euler, rk4 or implicit");
}

SimulationOptions ParseCommon(const CommonArgs& args) {
  RequirePositive("--duration", args.duration, "s");
  RequirePositive("--sample-rate", args.sample_rate, "rows per simulated second");
  SimulationOptions options;
  if (args.timestep && *args.timestep != "auto") {
    const std::string& text = *args.timestep;
    char* end = nullptr;
    const double value = text.empty() ? 0.0 : std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size()) {
      Refuse("--timestep", text, "must be a number > 0 (s) or auto");
    }
    RequirePositive("--timestep", value, "s");
    options.timestep = value;
  }
  if (args.max_timestep) {
    if (!args.timestep || *args.timestep != "auto") {
      Refuse("--max-timestep", fmt::format("{}", *args.max_timestep),
             "goes with --timestep auto");
    }
    RequirePositive("--max-timestep", *args.max_timestep, "s");
  }
  if (args.integrator) options.integrator = ParseIntegrator(*args.integrator);
  return options;
}

std::optional<AutoTimestepOptions> ParseAutoTimestep(const CommonArgs& args) {
  if (!args.timestep || *args.timestep != "auto") return std::nullopt;
  AutoTimestepOptions options;
  if (args.max_timestep) options.max_step = *args.max_timestep;
  return options;
}

LawKind ParseLaw(std::string_view option, std::string_view name) {
  const std::optional<LawKind> law = ParseLawName(name);
  if (!law) Refuse(option, name, fmt::format("is not a law ({})", kLawNames));
  return *law;
}

std::vector<LawKind> ParseLawList(std::string_view option, std::string_view text) {
  if (text == "all") return {std::begin(kAllLaws), std::end(kAllLaws)};
  std::vector<LawKind> laws;
  for (std::string_view name : Split(text, ',')) {
    const std::optional<LawKind> law = ParseLawName(name);
    if (!law) {
      Refuse(option, text, fmt::format("has '{}', which is not a law (all, {})", name, kLawNames));
    }
    if (std::find(laws.begin(), laws.end(), *law) != laws.end()) {
      Refuse(option, text, fmt::format("names {} twice", name));
    }
    laws.push_back(*law);
  }
  return laws;
}

double ParseRestitution(std::string_view option, double value) {
  if (!(std::isfinite(value) && value >= 0 && value <= 1)) {
    Refuse(option, fmt::format("{}", value), "must be in [0, 1]");
  }
  return value;
}

std::vector<double> ParseRestitutionList(std::string_view option, std::string_view text) {
  std::vector<double> values;
  const std::vector<std::string_view> range = Split(text, ':');
  if (range.size() == 3) {
    const double start = Number(option, range[0], text);
    const double stop = Number(option, range[1], text);
    const double step = Number(option, range[2], text);
    if (!(step > 0)) Refuse(option, text, "must have a step > 0 (start:stop:step)");
    if (stop < start) Refuse(option, text, "must have start <= stop (start:stop:step)");
    const double count = std::floor((stop - start) / step + 1e-9) + 1;
    if (count > kMaxListLength) {
      Refuse(option, text, fmt::format("expands to more than {} values", kMaxListLength));
    }
    for (long i = 0; i < static_cast<long>(count); ++i) values.push_back(Round12(start + i * step));
  } else if (range.size() == 1) {
    for (std::string_view item : Split(text, ',')) values.push_back(Number(option, item, text));
  } else {
    Refuse(option, text, "must be E1,E2,... or start:stop:step");
  }
  for (size_t i = 0; i < values.size(); ++i) {
    if (!(values[i] >= 0 && values[i] <= 1)) {
      Refuse(option, text, fmt::format("has {}, outside [0, 1]", values[i]));
    }
    if (std::find(values.begin(), values.begin() + i, values[i]) != values.begin() + i) {
      Refuse(option, text, fmt::format("has {} twice", values[i]));
    }
  }
  return values;
}

}  // namespace contactlaws::cli
