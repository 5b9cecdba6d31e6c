// Copyright contactlaws authors.

#include "app/law_tables.h"

#include <limits>
#include <optional>
#include <string>

#include "contactlaws/friction.h"

namespace contactlaws::app {

std::string_view FamilyName(LawFamily family) {
  switch (family) {
    case LawFamily::kHysteresis: return "hysteresis";
    case LawFamily::kConstantDissipation: return "constant-dissipation";
    case LawFamily::kLinear: return "linear";
  }
  return "?";
}

Table LawTable() {
  using Kind = Column::Kind;
  Table table({{"name", Kind::kText},
               {"formula", Kind::kText},
               {"parameters", Kind::kText},
               {"reference", Kind::kText}});
  for (const LawInfo& law : Laws()) {
    table.AddRow({Text(std::string(law.name)), Text(std::string(law.formula)),
                  Text(std::string(law.parameters)), Text(std::string(law.reference))});
  }
  return table;
}

Table FrictionTable() {
  using Kind = Column::Kind;
  Table table({{"name", Kind::kText},
               {"formula", Kind::kText},
               {"state", Kind::kText},
               {"parameters", Kind::kText},
               {"reference", Kind::kText}});
  for (const FrictionInfo& model : FrictionModels()) {
    table.AddRow({Text(std::string(model.name)), Text(std::string(model.formula)),
                  Text(std::string(model.state)), Text(std::string(model.parameters)),
                  Text(std::string(model.reference))});
  }
  return table;
}

Table EffectiveRestitutionTable(const std::vector<double>& restitutions) {
  using Kind = Column::Kind;
  Table table({{"law", Kind::kText},
               {"family", Kind::kText},
               {"restitution", Kind::kNumber},
               {"hysteresis_coefficient", Kind::kNumber},
               {"effective_restitution", Kind::kNumber}});
  for (const LawInfo& law : Laws()) {
    for (const double e : restitutions) {
      const std::optional<double> effective = EffectiveRestitution(law.id, e);
      table.AddRow({Text(std::string(law.name)), Text(std::string(FamilyName(law.family))),
                    Number(e), effective ? Number(HysteresisCoefficient(law.id, e)) : Unknown(),
                    effective ? Number(*effective) : Unknown()});
    }
  }
  return table;
}

}  // namespace contactlaws::app
