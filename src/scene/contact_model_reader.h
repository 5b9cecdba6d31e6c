// Copyright contactlaws authors.
//
// How a ContactModel is read from a model's tags (its friend): the drives
// (drives.cc), then each pair tag with its overrides, its geom pairs, their
// friction and the trust of their depth (contact_model.cc). Refusals throw
// Error; warnings go to the model's warnings().

#ifndef CONTACTLAWS_SCENE_CONTACT_MODEL_READER_H_
#define CONTACTLAWS_SCENE_CONTACT_MODEL_READER_H_

#include <string>
#include <vector>

#include "contactlaws/contact_model.h"
#include "scene/parsed_tags.h"
#include "scene/tags.h"

namespace contactlaws::internal {

class TagResolver;  // contact_model.cc: a tag's geoms and its messages

class ContactModelReader {
 public:
  explicit ContactModelReader(ContactModel* model) : cm_(*model) {}

  void ReadDrives(const ParsedTags& tags);
  void ReadTags(const ParsedTags& tags, const Overrides& overrides);

 private:
  // The geom pairs of one tag (appended to the model's pairs and tag->pairs).
  void AddPairs(const PairTagSpec& spec, const LawParams& base, const TagResolver& resolve,
                PairTag* tag);
  // The pair's friction (scene/pair_friction.h); refuses bad values, warns
  // of friction keys on a frictionless pair.
  void AddFriction(int g1, int g2, const PairTagSpec& spec, const std::string& pair_name,
                   const TagResolver& resolve, GeomPair* pair);
  // Refuses the pair when MuJoCo's depth for its geom types is wrong; warns
  // (once per tag and type, warned_types) when it has a known limit.
  void CheckDepth(int g1, int g2, const std::string& pair_name, const TagResolver& resolve,
                  std::vector<int>* warned_types);

  ContactModel& cm_;
};

}  // namespace contactlaws::internal

#endif  // CONTACTLAWS_SCENE_CONTACT_MODEL_READER_H_
