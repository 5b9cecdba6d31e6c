// Copyright contactlaws authors.

#include "scene/number.h"

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>
#include <system_error>

namespace contactlaws {
namespace {

// Longest text taken as a number: more digits than a double holds, and room
// for an exponent.
constexpr size_t kMaxNumberLength = 64;

bool IsDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// [sign] digits [. digits] [(e|E) [sign] digits], with at least one digit
// before the exponent.
bool IsDecimal(std::string_view text) {
  size_t i = 0;
  auto sign = [&] {
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  };
  auto digits = [&] {
    const size_t start = i;
    while (i < text.size() && IsDigit(text[i])) ++i;
    return i - start;
  };
  sign();
  size_t mantissa = digits();
  if (i < text.size() && text[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    sign();
    if (digits() == 0) return false;
  }
  return i == text.size();
}

}  // namespace

std::optional<double> ParseNumber(std::string_view text) {
  if (text.empty() || text.size() > kMaxNumberLength || !IsDecimal(text)) {
    return std::nullopt;
  }
  // from_chars: the correctly rounded value, as strtod's, at a tenth of its
  // cost (a measured trajectory is ~10^5 numbers); strtod's ERANGE rule
  // decides what lies near the range's ends (zeros, subnormals, overflow)
  const std::string_view digits = text.front() == '+' ? text.substr(1) : text;
  double fast = 0;
  const auto [stop, error] = std::from_chars(digits.data(), digits.data() + digits.size(), fast);
  if (error == std::errc() && stop == digits.data() + digits.size() && std::isnormal(fast)) {
    return fast;
  }
  const std::string buffer(text);
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(buffer.c_str(), &end);
  // ERANGE: beyond the range of a double, either way (1e999, 1e-400)
  if (end != buffer.c_str() + buffer.size() || errno == ERANGE || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

std::optional<long> ParseWholeNumber(std::string_view text, long lo, long hi) {
  const std::optional<double> value = ParseNumber(text);
  if (!value || *value != std::floor(*value) || *value < lo || *value > hi) return std::nullopt;
  return static_cast<long>(*value);
}

}  // namespace contactlaws
