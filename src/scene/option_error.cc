// Copyright contactlaws authors.

#include <string>
#include <utility>
#include <vector>

#include "contactlaws/contact_model.h"

namespace contactlaws {
namespace {

// text with each mention named by its key (a given word after "=").
std::string KeyNamed(const std::string& text, const std::vector<OptionError::Mention>& mentions) {
  std::string message;
  size_t next = 0;
  for (const char c : text) {
    if (c != OptionError::kMark || next >= mentions.size()) {
      message += c;
      continue;
    }
    const OptionError::Mention& m = mentions[next++];
    message += m.key;
    if (m.form == OptionError::Form::kGiven) message += "=" + m.word;
  }
  return message;
}

}  // namespace

OptionError::OptionError(std::string text, std::vector<Mention> mentions)
    : Error(KeyNamed(text, mentions)), text_(std::move(text)), mentions_(std::move(mentions)) {}

}  // namespace contactlaws
