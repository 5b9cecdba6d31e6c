// Copyright contactlaws authors.

#include "cli/commands.h"

#include <fmt/format.h>

#include "app/law_tables.h"
#include "cli/csv_file.h"
#include "cli/identify.h"

namespace contactlaws::cli {
namespace {


// "e = 0.9: 0.9009, ...": the rebound of the law's a(e), or why it has none.
std::string EffectiveLine(const LawInfo& law, const std::vector<double>& restitutions) {
  if (law.family == LawFamily::kLinear) return "no closed form (clamped at F = 0)";
  if (!ReadsRestitution(law.id) && !IsElastic(law.id)) {
    return "reads no e: ExactRebound(c v0), set by the impact speed";
  }
  std::string line;
  for (const double e : restitutions) {
    const std::optional<double> effective = EffectiveRestitution(law.id, e);
    line += fmt::format("{}{}: {}", line.empty() ? "" : ", ", e,
                        effective ? fmt::format("{:.4f}", *effective) : "-");
  }
  return line;
}

void PrintText(std::FILE* out) {
  const std::vector<double> restitutions =
      ParseRestitutionList("--restitution", kDefaultRestitutions);
  fmt::print(out,
             "Convention: depth d > 0 in contact (m), depth rate d' > 0 approaching (m/s),\n"
             "v0 = d' at first touch (m/s, floored by min_impact_velocity, default {} m/s),\n"
             "force F >= 0 pushes apart (N); F = 0 for d <= 0; clamped to F >= 0 unless\n"
             "allow_tension=true. effective e: the first rebound, gravity neglected, of a\n"
             "first impact at e (a (1 + e_post) = ln((1 + a)/(1 - a e_post))).\n",
             kDefaultMinImpactVelocity);
  for (const LawInfo& law : Laws()) {
    fmt::print(out, "\n{}\n  {}\n  parameters: {}\n  effective e: {}\n  reference:  {}\n", law.name,
               law.formula, law.parameters, EffectiveLine(law, restitutions), law.reference);
  }
  fmt::print(out,
             "\nFriction models (tag key friction=, --friction; docs/friction.md). Convention:\n"
             "slip v of geom2's body relative to geom1's at the contact point, force F on it\n"
             "opposing the slip, normal force F_n from the law; default coulomb when the pair\n"
             "has friction (condim > 1), mu from the geoms' friction (the larger, as MuJoCo).\n"
             "Every model but none adds, as MuJoCo's condim has them, a torsional torque\n"
             "capped at torsional_friction x F_n (condim >= 4) and a rolling torque capped at\n"
             "rolling_friction x F_n (condim 6): tag keys, m >= 0 (default: the geoms' second\n"
             "and third friction coefficients, the larger), sticking as sliding does.\n");
  for (const FrictionInfo& model : FrictionModels()) {
    fmt::print(out, "\n{}\n  {}\n  state:      {}\n  parameters: {}\n  reference:  {}\n",
               model.name, model.formula, model.state, model.parameters, model.reference);
  }
}

void PrintCsv(const std::vector<double>& restitutions, const std::string& output) {
  CsvFile out(output);
  WriteTable(app::EffectiveRestitutionTable(restitutions), &out);
  out.Commit();
}

}  // namespace

int LawsCommand(const LawsArgs& args) {
  if (args.format == "text") {
    if (args.restitution) Refuse("--restitution", *args.restitution, "goes with --format csv");
    PrintText(args.report);
  } else if (args.format == "csv") {
    PrintCsv(ParseRestitutionList("--restitution", args.restitution.value_or(kDefaultRestitutions)),
             args.output);
  } else {
    Refuse("--format", args.format, "must be text or csv");
  }
  return 0;
}

}  // namespace contactlaws::cli
