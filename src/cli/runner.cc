// Copyright contactlaws authors.

#include "cli/runner.h"

#include <fmt/format.h>

namespace contactlaws::cli {

Scene::Scene(std::string path) : path_(std::move(path)), model_(LoadModelFile(path_)) {}

Scene::Scene(std::string name, UniqueModel model)
    : path_(std::move(name)), model_(std::move(model)) {}

std::unique_ptr<Simulation> Scene::Make(const SimulationOptions& options) const {
  UniqueModel copy(mj_copyModel(nullptr, model_.get()));
  if (!copy) throw Error(fmt::format("{}: MuJoCo could not copy the model", path_));
  return std::make_unique<Simulation>(std::move(copy), path_, options);
}

double ReportedRestitution(LawKind law, double restitution) {
  return law == LawKind::kHertz ? 1.0 : restitution;
}

void Advance(Simulation* sim, const AdvanceOptions& options,
             const std::function<void(const std::vector<double>&)>& on_row) {
  const double dt = sim->model()->opt.timestep;
  const bool sampling = options.sample_rate > 0 && on_row;
  const double period = sampling ? 1.0 / options.sample_rate : 0.0;
  std::vector<double> row;

  // sample at the first step that reaches each grid time k * period (within
  // half a step, so that rounding of the time does not skip or repeat a row)
  long next = 0;
  auto sample_if_due = [&] {
    if (!sampling || sim->time() < next * period - 0.5 * dt) return;
    sim->Sample(&row);
    on_row(row);
    while (next * period - 0.5 * dt <= sim->time()) ++next;
  };
  auto first_episode_over = [&] {
    for (const Impact& impact : sim->contacts().impacts()) {
      if (impact.tag == 0) return !impact.open;
    }
    return false;
  };

  sample_if_due();
  while (sim->time() < options.duration - 0.5 * dt) {
    sim->Step();
    sample_if_due();
    if (options.until_first_episode && first_episode_over()) break;
  }
}

std::vector<std::string> ImpactColumns() {
  return {"law", "restitution", "pair", "geom1", "geom2", "index", "time_contact",
          "time_separation", "impact_velocity", "separation_velocity", "restitution_post",
          "max_depth", "max_force"};
}

std::string Field(double value) { return fmt::format("{}", value); }

std::string Field(const std::optional<double>& value) { return value ? Field(*value) : ""; }

std::vector<std::string> ImpactFields(const Simulation& sim, const Impact& impact) {
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
          Field(impact.time_contact),
          if_closed(impact.time_separation),
          Field(impact.impact_velocity),
          if_closed(impact.separation_velocity),
          if_closed(impact.restitution_post()),
          Field(impact.max_depth),
          Field(impact.max_force)};
}

}  // namespace contactlaws::cli
