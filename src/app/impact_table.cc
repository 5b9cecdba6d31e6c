// Copyright contactlaws authors.

#include "app/impact_table.h"

#include <map>
#include <string>

namespace contactlaws::app {

std::vector<Episode> ImpactsOf(const ContactData& contacts, ImpactRows rows) {
  if (rows == ImpactRows::kImpacts) return contacts.impacts();
  std::vector<Episode> points;
  std::map<int, int> count;  // tag -> its points so far
  for (const Episode& point : contacts.point_episodes()) {
    if (!point.open && !point.resolved) continue;
    points.push_back(point);
    points.back().index = ++count[point.tag];
  }
  return points;
}

Table ImpactTable(const Simulation& sim, const std::vector<Episode>& impacts) {
  using Kind = Column::Kind;
  Table table({{"law", Kind::kText},
               {"restitution", Kind::kNumber},
               {"pair", Kind::kText},
               {"geom1", Kind::kText},
               {"geom2", Kind::kText},
               {"index", Kind::kCount},
               {"points", Kind::kCount},
               {"time_contact", Kind::kNumber},
               {"time_separation", Kind::kNumber},
               {"impact_velocity", Kind::kNumber},
               {"separation_velocity", Kind::kNumber},
               {"max_approach_velocity", Kind::kNumber},
               {"restitution_post", Kind::kNumber},
               {"chained", Kind::kCount},
               {"max_depth", Kind::kNumber},
               {"max_force", Kind::kNumber},
               {"tangential_impact_velocity", Kind::kNumber},
               {"tangential_separation_velocity", Kind::kNumber},
               {"tangential_restitution", Kind::kNumber},
               {"spin_before", Kind::kNumber},
               {"spin_after", Kind::kNumber}});
  const ContactModel& cm = sim.contact_model();
  for (const Episode& impact : impacts) {
    const PairTag& tag = cm.tags()[impact.tag];
    const GeomPair& pair = cm.pairs()[impact.pair];
    const bool closed = !impact.open;
    auto if_closed = [closed](double v) { return closed ? Number(v) : Unknown(); };
    const std::optional<double> restitution =
        ReportedRestitution(tag.law, pair.params.restitution);
    table.AddRow({Text(std::string(LawName(tag.law))),
                  restitution ? Number(*restitution) : Unknown(),
                  Text(tag.label),
                  Text(ObjectName(sim.model(), mjOBJ_GEOM, pair.named[0])),
                  Text(ObjectName(sim.model(), mjOBJ_GEOM, pair.named[1])),
                  Count(impact.index),
                  Count(impact.points),
                  Number(impact.time_contact),
                  if_closed(impact.time_separation),
                  Number(impact.impact_velocity),
                  if_closed(impact.separation_velocity),
                  Number(impact.max_approach_velocity),
                  if_closed(impact.restitution_post()),
                  Count(impact.chained() ? 1 : 0),
                  Number(impact.max_depth),
                  Number(impact.max_force),
                  Number(impact.tangential_impact_velocity),
                  if_closed(impact.tangential_separation_velocity),
                  if_closed(impact.tangential_restitution()),
                  Number(impact.spin_before),
                  if_closed(impact.spin_after)});
  }
  return table;
}

}  // namespace contactlaws::app
