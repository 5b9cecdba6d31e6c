// Copyright contactlaws authors.
//
// The message ParsePairTag throws for a tag's data, for the tests of the tag
// grammar and of its table of keys.

#ifndef CONTACTLAWS_TESTS_SCENE_PAIR_TAG_ERROR_H_
#define CONTACTLAWS_TESTS_SCENE_PAIR_TAG_ERROR_H_

#include <string>

#include "contactlaws/contact_model.h"
#include "scene/tags.h"

namespace contactlaws {

// The message ParsePairTag("s.xml", "contactlaw:t", data) throws, or "" when
// it accepts data.
inline std::string PairTagError(const std::string& data) {
  try {
    internal::ParsePairTag("s.xml", "contactlaw:t", data);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace contactlaws

#endif  // CONTACTLAWS_TESTS_SCENE_PAIR_TAG_ERROR_H_
