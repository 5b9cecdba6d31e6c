// Copyright contactlaws authors.
//
// The impact log as a table (run's --impacts, compare's impacts.csv,
// Python's .impacts): a row per impact of a pair, its first point touching
// to its last point leaving, or per contact episode of each point.

#ifndef CONTACTLAWS_APP_IMPACT_TABLE_H_
#define CONTACTLAWS_APP_IMPACT_TABLE_H_

#include <vector>

#include "app/table.h"
#include "contactlaws/contactlaws.h"

namespace contactlaws::app {

// The rows of an impact log: one per impact of a pair, or one per contact
// episode of each point (--impacts-per-point).
enum class ImpactRows { kImpacts, kPointEpisodes };

// The impacts of contacts in those rows: the point episodes without those
// that closed with their depth never resolved (Episode::resolved), each
// tag's numbered again, as the impacts are.
std::vector<Episode> ImpactsOf(const ContactData& contacts, ImpactRows rows);

// law, restitution, pair, geom1, geom2, index, points, time_contact (s),
// time_separation (s), impact_velocity, separation_velocity,
// max_approach_velocity (m/s), restitution_post, chained (1 or 0),
// max_depth (m), max_force (N), and the tangential side (friction): slip
// speed along the first slip's direction before and after (m/s), its
// restitution, spin about n x t before and after (rad/s). A contact still
// closed at the end has no separation, no rebound and no "after".
Table ImpactTable(const Simulation& sim, const std::vector<Episode>& impacts);

}  // namespace contactlaws::app

#endif  // CONTACTLAWS_APP_IMPACT_TABLE_H_
