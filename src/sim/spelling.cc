// Copyright contactlaws authors.

#include "sim/spelling.h"

#include <algorithm>

#include <fmt/format.h>

namespace contactlaws {
namespace {

std::string Flag(std::string_view key) {
  std::string flag = "--" + std::string(key);
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flag;
}
std::string FlagGiven(std::string_view key, std::string_view word) {
  return Flag(key) + " " + std::string(word);
}
std::string Command(std::string_view name) { return fmt::format("contactlaws {}", name); }

std::string Keyword(std::string_view key) { return std::string(key); }
std::string KeywordGiven(std::string_view key, std::string_view word) {
  return fmt::format("{}=\"{}\"", key, word);
}
std::string KeywordSet(std::string_view key) { return fmt::format("{}=True", key); }
std::string KeywordValued(std::string_view key, std::string_view number) {
  return fmt::format("{}={}", key, number);
}
std::string Function(std::string_view name) { return fmt::format("contactlaws.{}()", name); }

}  // namespace

const Spelling kCommandLineSpelling = {&Flag, &FlagGiven, &Flag, &FlagGiven, &Command};
const Spelling kKeywordSpelling = {&Keyword, &KeywordGiven, &KeywordSet, &KeywordValued,
                                   &Function};

std::string Spelled(const OptionError& e, const Spelling& spelling) {
  std::string message;
  size_t next = 0;
  for (const char c : e.text()) {
    if (c != OptionError::kMark || next >= e.mentions().size()) {
      message += c;
      continue;
    }
    const OptionError::Mention& m = e.mentions()[next++];
    switch (m.form) {
      case OptionError::Form::kName: message += spelling.name(m.key); break;
      case OptionError::Form::kSet: message += spelling.set(m.key); break;
      case OptionError::Form::kGiven: message += spelling.given(m.key, m.word); break;
    }
  }
  return message;
}

}  // namespace contactlaws
