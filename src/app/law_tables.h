// Copyright contactlaws authors.
//
// The laws and friction models as tables (what `contactlaws laws` prints and
// writes): each law's and model's name, formula, parameters and reference,
// and each law's hysteresis coefficient a(e) and first rebound per
// restitution.

#ifndef CONTACTLAWS_APP_LAW_TABLES_H_
#define CONTACTLAWS_APP_LAW_TABLES_H_

#include <string_view>
#include <vector>

#include "app/table.h"
#include "contactlaws/law.h"

namespace contactlaws::app {

// "hysteresis", "constant-dissipation" or "linear".
std::string_view FamilyName(LawFamily family);

// name, formula, parameters, reference: a row per law, in the table's order.
Table LawTable();
// name, formula, state, parameters, reference: a row per friction model.
Table FrictionTable();

// law, family, restitution, hysteresis_coefficient, effective_restitution:
// a row per law and restitution, a(e) and the rebound it gives (not known
// where the law has none, or e is outside its range, and for the
// constant-dissipation family, whose rebound depends on the impact speed).
Table EffectiveRestitutionTable(const std::vector<double>& restitutions);

}  // namespace contactlaws::app

#endif  // CONTACTLAWS_APP_LAW_TABLES_H_
