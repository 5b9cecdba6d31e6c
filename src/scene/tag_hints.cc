// Copyright contactlaws authors.
//
// The "did you mean" hints of the tag grammar's refusals, and the check of a
// <text> name whose prefix is a typo of a tag's.

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "contactlaws/contact_model.h"
#include "scene/tags.h"

namespace contactlaws {

std::string_view NearestWord(std::string_view word,
                             const std::string_view* candidates, size_t count) {
  // Levenshtein distance, accepting at most a third of the word's length
  std::string_view best;
  size_t best_distance = std::max<size_t>(2, word.size() / 3) + 1;
  std::vector<size_t> row;
  for (size_t c = 0; c < count; ++c) {
    std::string_view cand = candidates[c];
    row.resize(cand.size() + 1);
    for (size_t j = 0; j <= cand.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= word.size(); ++i) {
      size_t diagonal = row[0];
      row[0] = i;
      for (size_t j = 1; j <= cand.size(); ++j) {
        size_t up = row[j];
        size_t cost = word[i - 1] == cand[j - 1] ? 0 : 1;
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + cost});
        diagonal = up;
      }
    }
    if (row[cand.size()] < best_distance) {
      best_distance = row[cand.size()];
      best = cand;
    }
  }
  return best;
}

namespace {

std::string Lower(std::string_view text) {
  std::string lower(text);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower;
}

// ": did you mean 'NAME'?" for the name of names nearest to name, any case.
std::string Suggestion(std::string_view name, const std::vector<std::string_view>& names) {
  const std::string_view nearest = NearestWord(Lower(name), names.data(), names.size());
  return nearest.empty() ? std::string() : fmt::format(": did you mean '{}'?", nearest);
}

}  // namespace

std::string LawSuggestion(std::string_view name) {
  std::vector<std::string_view> names;
  for (const LawInfo& law : Laws()) names.push_back(law.name);
  return Suggestion(name, names);
}

std::string FrictionSuggestion(std::string_view name) {
  std::vector<std::string_view> names;
  for (const FrictionInfo& model : FrictionModels()) names.push_back(model.name);
  return Suggestion(name, names);
}

void CheckTagPrefix(std::string_view source, std::string_view name) {
  const size_t colon = name.find(':');
  if (colon == std::string_view::npos) return;
  const std::string_view prefix = name.substr(0, colon + 1);
  if (prefix == kPairTagPrefix || prefix == kDriveTagPrefix) return;
  const std::string_view kinds[] = {kPairTagPrefix.substr(0, kPairTagPrefix.size() - 1),
                                    kDriveTagPrefix.substr(0, kDriveTagPrefix.size() - 1)};
  const std::string lower = Lower(name.substr(0, colon));
  // a typo: the letter case, or an edit or two (NearestWord's own measure)
  std::string_view meant = lower == kinds[0] ? kinds[0] : lower == kinds[1] ? kinds[1] : "";
  if (meant.empty()) meant = NearestWord(lower, kinds, 2);
  if (meant.empty()) return;
  throw Error(fmt::format("{}: {}: the tag prefix must be '{}:' (not '{}'), or the tag is not read",
                          source, name, meant, prefix));
}

}  // namespace contactlaws
