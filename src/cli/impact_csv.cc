// Copyright contactlaws authors.

#include "cli/impact_csv.h"

#include <cmath>

#include <fmt/format.h>

#include "cli/csv_file.h"

namespace contactlaws::cli {

const std::vector<Episode>& ImpactsOf(const ContactData& contacts, ImpactRows rows) {
  return rows == ImpactRows::kPointEpisodes ? contacts.point_episodes() : contacts.impacts();
}

std::vector<std::string> ImpactColumns() {
  return {"law",           "restitution",         "pair",
          "geom1",         "geom2",               "index",
          "points",        "time_contact",        "time_separation",
          "impact_velocity", "separation_velocity", "max_approach_velocity",
          "restitution_post", "chained",          "max_depth",
          "max_force",
          // the tangential side (friction): slip speed along the first slip's
          // direction, spin about n x t, before and after
          "tangential_impact_velocity", "tangential_separation_velocity",
          "tangential_restitution", "spin_before", "spin_after"};
}

std::string Field(double value) {
  // no -0, inf or nan in a CSV: -0 is 0, and what is not finite is not known
  if (!std::isfinite(value)) return "";
  std::string field;
  AppendShortest(&field, value == 0 ? 0.0 : value);
  return field;
}

std::string Field(const std::optional<double>& value) { return value ? Field(*value) : ""; }

std::vector<std::string> ImpactFields(const Simulation& sim, const Episode& impact) {
  const ContactModel& cm = sim.contact_model();
  const PairTag& tag = cm.tags()[impact.tag];
  const GeomPair& pair = cm.pairs()[impact.pair];
  const bool closed = !impact.open;
  auto if_closed = [closed](double v) { return closed ? Field(v) : std::string(); };
  return {std::string(LawName(tag.law)),
          Field(ReportedRestitution(tag.law, pair.params.restitution)),
          tag.label,
          ObjectName(sim.model(), mjOBJ_GEOM, pair.named[0]),
          ObjectName(sim.model(), mjOBJ_GEOM, pair.named[1]),
          Field(impact.index),
          Field(impact.points),
          Field(impact.time_contact),
          if_closed(impact.time_separation),
          Field(impact.impact_velocity),
          if_closed(impact.separation_velocity),
          Field(impact.max_approach_velocity),
          if_closed(impact.restitution_post()),
          impact.chained() ? "1" : "0",
          Field(impact.max_depth),
          Field(impact.max_force),
          Field(impact.tangential_impact_velocity),
          if_closed(impact.tangential_separation_velocity),
          if_closed(impact.tangential_restitution()),
          Field(impact.spin_before),
          if_closed(impact.spin_after)};
}

}  // namespace contactlaws::cli
