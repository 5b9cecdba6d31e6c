// Copyright contactlaws authors.

#include "cli/commands.h"

#include <cstdio>
#include <memory>
#include <set>

#include "app/check_job.h"
#include "cli/report.h"

namespace contactlaws::cli {
namespace {

app::CheckInput InputOf(const CheckArgs& args) {
  app::CheckInput input;
  input.law = args.law;
  input.restitution = ValueOf(args.restitution);
  input.dissipation = ValueOf(args.dissipation);
  input.friction = args.friction;
  input.mu = ValueOf(args.mu);
  input.timestep = ValueOf(args.timestep);
  input.accuracy = ValueOf(args.accuracy);
  input.impact_velocity = ValueOf(args.impact_velocity);
  return input;
}

}  // namespace

int CheckCommand(const CheckArgs& args) {
  const app::CheckRequest request = app::ReadCheck(Flags(), InputOf(args));
  const Scene scene(args.scene);
  std::unique_ptr<Simulation> sim = scene.Make(request.options);
  std::set<std::string> warned;
  WarnAboutTags(sim->contact_model(), &warned);
  std::fputs(app::Check(sim.get(), request, Flags()).text.c_str(), args.report);
  return 0;
}

}  // namespace contactlaws::cli
