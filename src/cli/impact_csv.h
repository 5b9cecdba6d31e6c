// Copyright contactlaws authors.
//
// The impact log as CSV fields, and numbers as the CSV files write them.

#ifndef CONTACTLAWS_CLI_IMPACT_CSV_H_
#define CONTACTLAWS_CLI_IMPACT_CSV_H_

#include <optional>
#include <string>
#include <vector>

#include "contactlaws/contactlaws.h"

namespace contactlaws::cli {

// The rows of an impact log: one per impact of a pair (its first point
// touching to its last point leaving), or one per contact episode of each
// point (--impacts-per-point).
enum class ImpactRows { kImpacts, kPointEpisodes };

// The impacts of contacts in those rows.
const std::vector<Episode>& ImpactsOf(const ContactData& contacts, ImpactRows rows);

// The impact-log CSV: its columns, and the fields of one impact.
std::vector<std::string> ImpactColumns();
std::vector<std::string> ImpactFields(const Simulation& sim, const Episode& impact);

// A number in its shortest exact form; an empty field for nullopt.
std::string Field(double value);
std::string Field(const std::optional<double>& value);

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_IMPACT_CSV_H_
