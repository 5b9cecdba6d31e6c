// Copyright contactlaws authors.

#include "scene/parsed_tags.h"

#include "contactlaws/contact_model.h"
#include "scene/model_queries.h"

namespace contactlaws::internal {

namespace {

// The parser's refusal of the tag as its message, "" when it is read.
template <typename Parse>
std::string Refusal(const Parse& parse) {
  try {
    parse();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

bool StartsWith(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

}  // namespace

ParsedTags::ParsedTags(const mjModel* m, std::string_view source) {
  for (int i = 0; i < m->ntext && prefix_error_.empty(); ++i) {
    prefix_error_ = Refusal([&] { CheckTagPrefix(source, TextName(m, i)); });
  }
  for (int i = 0; i < m->ntext; ++i) {
    const std::string_view name = TextName(m, i);
    if (StartsWith(name, kDriveTagPrefix)) {
      Tag<DriveTagSpec>& tag = drives_.emplace_back();
      tag.name = std::string(name);
      tag.error = Refusal([&] { tag.spec = ParseDriveTag(source, name, TextData(m, i)); });
    } else if (StartsWith(name, kPairTagPrefix)) {
      Tag<PairTagSpec>& tag = pairs_.emplace_back();
      tag.name = std::string(name);
      tag.error = Refusal([&] { tag.spec = ParsePairWords(source, name, TextData(m, i)); });
    }
  }
}

}  // namespace contactlaws::internal
