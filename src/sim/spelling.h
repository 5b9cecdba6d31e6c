// Copyright contactlaws authors.
//
// How a front-end names an option in the library's messages, from its key
// (snake_case: "max_timestep"): the command line "--max-timestep", Python
// "max_timestep". The library's advice ("use --timestep 6.66e-05 or
// smaller") and its option errors are written through the caller's
// Spelling, so that each front-end's user reads the options they give.

#ifndef CONTACTLAWS_SIM_SPELLING_H_
#define CONTACTLAWS_SIM_SPELLING_H_

#include <string>
#include <string_view>

#include "contactlaws/contact_model.h"

namespace contactlaws {

struct Spelling {
  // the option: "--max-timestep", "max_timestep"
  std::string (*name)(std::string_view key);
  // the option given a word: "--timestep auto", "timestep=\"auto\""
  std::string (*given)(std::string_view key, std::string_view word);
  // a switch turned on: "--settle", "settle=True"
  std::string (*set)(std::string_view key);
  // the option given a number: "--timestep 6.66e-05", "timestep=6.66e-05"
  std::string (*valued)(std::string_view key, std::string_view number);
  // a command: "contactlaws check", "contactlaws.check()"
  std::string (*command)(std::string_view name);
};

// The command line's flags and commands.
extern const Spelling kCommandLineSpelling;
// Python's keyword arguments (the key as it is, a word as a str, a switch
// True) and functions.
extern const Spelling kKeywordSpelling;

// e's message with each option it mentions as spelling names it.
std::string Spelled(const OptionError& e, const Spelling& spelling);

}  // namespace contactlaws

#endif  // CONTACTLAWS_SIM_SPELLING_H_
