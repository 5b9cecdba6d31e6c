// Copyright contactlaws authors.
//
// The tags of a model read once: what every ContactModel of the model
// resolves, with its overrides set on them as values (ContactModel), so that
// making one more (a thread's, a fit evaluation's) reads no text. A Scene
// reads its model's tags once and its simulations share them, its model's
// copies with edited numbers too (their <text> entries are the same).
//
// A tag the parser refuses keeps the parser's message, which ContactModel
// throws where it reads the tag: the same refusal, at the same point, as when
// the tag is parsed there.

#ifndef CONTACTLAWS_SCENE_PARSED_TAGS_H_
#define CONTACTLAWS_SCENE_PARSED_TAGS_H_

#include <string>
#include <string_view>
#include <vector>

#include <mujoco/mujoco.h>

#include "scene/tags.h"

namespace contactlaws {

class Scene;

namespace internal {

class ParsedTags {
 public:
  // One tag, in the order of the model's <text> entries.
  template <typename Spec>
  struct Tag {
    std::string name;   // the <text> name: "contactlaw:LABEL"
    Spec spec;          // parsed, when error is empty
    std::string error;  // the parser's refusal, "" when none
  };

  // Reads m's <text> entries; source names the file in messages.
  ParsedTags(const mjModel* m, std::string_view source);

  // CheckTagPrefix's refusal of the first mistyped prefix, "" when none.
  const std::string& prefix_error() const { return prefix_error_; }
  // The contactdrive tags.
  const std::vector<Tag<DriveTagSpec>>& drives() const { return drives_; }
  // The contactlaw tags' words (ParsePairWords): CheckPairTag not yet run.
  const std::vector<Tag<PairTagSpec>>& pairs() const { return pairs_; }

 private:
  std::string prefix_error_;
  std::vector<Tag<DriveTagSpec>> drives_;
  std::vector<Tag<PairTagSpec>> pairs_;
};

// The tags of scene's model, read when the scene was made.
const ParsedTags& TagsOf(const Scene& scene);

}  // namespace internal
}  // namespace contactlaws

#endif  // CONTACTLAWS_SCENE_PARSED_TAGS_H_
