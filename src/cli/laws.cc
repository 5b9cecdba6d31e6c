// Copyright contactlaws authors.

#include "cli/commands.h"

#include <fmt/format.h>

#include "cli/csv_file.h"
#include "cli/impact_csv.h"

namespace contactlaws::cli {
namespace {

// The restitutions of `laws --format csv` when none are given.
constexpr char kDefaultRestitutions[] = "0.9,0.7,0.5,0.3,0.1";

std::string_view FamilyName(LawFamily family) {
  return family == LawFamily::kHysteresis ? "hysteresis" : "linear";
}

void PrintText() {
  fmt::print("Convention: depth d > 0 in contact (m), depth rate d' > 0 approaching (m/s),\n"
             "v0 = d' at first touch (m/s, floored by min_impact_velocity, default {} m/s),\n"
             "force F >= 0 pushes apart (N); F = 0 for d <= 0; clamped to F >= 0 unless\n"
             "allow_tension=true.\n",
             kDefaultMinImpactVelocity);
  for (const LawInfo& law : Laws()) {
    fmt::print("\n{}\n  {}\n  parameters: {}\n  reference:  {}\n", law.name, law.formula,
               law.parameters, law.reference);
  }
}

// One row per law and restitution: a(e) and the rebound it gives (empty
// where the law has none, or e is outside its range).
void PrintCsv(const std::vector<double>& restitutions) {
  CsvFile out("-");
  out.Header({"law", "family", "restitution", "hysteresis_coefficient",
              "effective_restitution"});
  for (const LawInfo& law : Laws()) {
    for (const double e : restitutions) {
      const std::optional<double> effective = EffectiveRestitution(law.kind, e);
      out.Fields({std::string(law.name), std::string(FamilyName(law.family)), Field(e),
                  effective ? Field(HysteresisCoefficient(law.kind, e)) : std::string(),
                  Field(effective)});
    }
  }
  out.Commit();
}

}  // namespace

int LawsCommand(const LawsArgs& args) {
  if (args.format == "text") {
    if (args.restitution) Refuse("--restitution", *args.restitution, "goes with --format csv");
    PrintText();
  } else if (args.format == "csv") {
    PrintCsv(ParseRestitutionList("--restitution", args.restitution.value_or(kDefaultRestitutions)));
  } else {
    Refuse("--format", args.format, "must be text or csv");
  }
  return 0;
}

}  // namespace contactlaws::cli
