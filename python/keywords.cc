// Copyright contactlaws authors.
//
// The library's errors spoken to a Python caller. The options' messages
// name the keywords already (the application's grammar, app/options.h, reads
// them with Python's spelling), and so does the library's advice (written
// through the caller's Spelling, sim/spelling.h) and an OptionError's
// message (settling's refusals, replay's columns and start, the tags'
// dissipation override: spelled from its mentions). KeywordSpelling is left
// for any other contactlaws.Error that names a flag: each --flag becomes the
// keyword argument of the same name (--max-timestep -> max_timestep,
// --settle -> settle=True), a few phrases Python's own (--timestep auto ->
// timestep="auto").

#include <algorithm>
#include <array>
#include <regex>
#include <string>
#include <utility>

#include "bindings.h"
#include "sim/spelling.h"

namespace contactlaws::python {
namespace {

// Phrases first: a flag followed by its value as a word, and the commands.
constexpr std::array<std::pair<const char*, const char*>, 7> kPhrases = {{
    {"--metric weighted", "metric=\"weighted\""},
    {"--laws all", "laws=\"all\""},
    {"--timestep auto", "timestep=\"auto\""},
    {"--contact-steps auto", "contact_steps=\"auto\""},
    {"contactlaws check", "contactlaws.check()"},
    {"contactlaws run", "contactlaws.run()"},
    {"contactlaws compare", "contactlaws.compare()"},
}};
// The flags that take no value: keywords set to True.
constexpr std::array<const char*, 2> kSwitches = {"settle", "impacts-per-point"};

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

}  // namespace

std::string KeywordSpelling(const std::string& message) {
  std::string text = message;
  for (const auto& [from, to] : kPhrases) text = Replace(text, from, to);
  static const std::regex flag("--([a-z][a-z0-9]*(-[a-z0-9]+)*)");
  std::string spoken;
  auto last = text.cbegin();
  for (std::sregex_iterator it(text.begin(), text.end(), flag), end; it != end; ++it) {
    spoken.append(last, (*it)[0].first);
    std::string name = (*it)[1];
    const bool is_switch = std::find(kSwitches.begin(), kSwitches.end(), name) != kSwitches.end();
    for (char& c : name) c = c == '-' ? '_' : c;
    spoken += is_switch ? name + "=True" : name;
    last = (*it)[0].second;
  }
  spoken.append(last, text.cend());
  return spoken;
}

void BindKeywordSpelling(pybind11::module_& m) {
  // contactlaws.Error, a ValueError, carries the command line's message
  // with the keywords' names
  static pybind11::exception<Error> error(m, "Error", PyExc_ValueError);
  pybind11::register_exception_translator([](std::exception_ptr raised) {
    try {
      if (raised) std::rethrow_exception(raised);
    } catch (const OptionError& e) {
      error(Spelled(e, kKeywordSpelling).c_str());
    } catch (const Error& e) {
      error(KeywordSpelling(e.what()).c_str());
    }
  });
  m.def("_spelled", &KeywordSpelling, "a command line's message with the keywords' names");
}

}  // namespace contactlaws::python
