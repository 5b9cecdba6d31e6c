// Copyright contactlaws authors.
//
// The one number parser of contactlaws: every number in a tag and every
// number on the command line goes through ParseNumber, so that the same text
// means the same value (or the same refusal) wherever it is written.
//
// The rule: a finite decimal number, written whole, in plain or scientific
// notation: an optional sign, digits with at most one decimal point, and an
// optional exponent (e or E, an optional sign, digits). Refused: empty text,
// white space anywhere, hexadecimal (0x10, 0x1p-1), inf, nan, a value beyond
// the range of a double (1e999, 1e-400), and text over 64 characters.

#ifndef CONTACTLAWS_SCENE_NUMBER_H_
#define CONTACTLAWS_SCENE_NUMBER_H_

#include <optional>
#include <string_view>

namespace contactlaws {

// The value of text, or nullopt unless the whole text is one finite decimal
// number (the rule above).
std::optional<double> ParseNumber(std::string_view text);

// The value of text when it is a whole number in [lo, hi] (written as a
// decimal, e.g. 2 or 2.0 or 2e0), else nullopt.
std::optional<long> ParseWholeNumber(std::string_view text, long lo, long hi);

}  // namespace contactlaws

#endif  // CONTACTLAWS_SCENE_NUMBER_H_
