// Copyright contactlaws authors.
//
// contactlaws simulate SCENE [--law L] [--restitution E] [--friction M] [--mu X]
// [--accuracy TOL | --contact-steps auto|N] [--settle]: MuJoCo's own viewer,
// mujoco-simulate, with libcontactlaws_plugin.so preloaded and the overrides
// in its environment (--accuracy as CONTACTLAWS_ACCURACY: the plugin sets the
// auto timestep before each step; --contact-steps as
// CONTACTLAWS_CONTACT_STEPS; --settle as CONTACTLAWS_SETTLE=1). The scene's tags, the
// overrides and the settling are checked first, as run checks them, so a
// refusal is the same line and no window opens.

#include <unistd.h>

#include <cstdlib>
#include <string>

#include <fmt/format.h>

#include "cli/commands.h"
#include "cli/options.h"
#include "cli/programs.h"

namespace contactlaws::cli {
namespace {

// Sets (or, for nullopt, removes) an environment variable of the viewer.
void SetVariable(const char* name, const std::optional<std::string>& value) {
  if (value) {
    setenv(name, value->c_str(), 1);
  } else {
    unsetenv(name);
  }
}

}  // namespace

int SimulateCommand(const SimulateArgs& args) {
  SimulationOptions options;
  ParseLawOverrides(args.law, args.restitution, &options.overrides);
  ParseFrictionOverrides(args.friction, args.mu, &options.overrides);
  if (args.accuracy) ParseAccuracy(*args.accuracy, std::nullopt);
  if (args.contact_steps) {
    if (args.accuracy) Refuse("--contact-steps", *args.contact_steps, "goes with a fixed timestep");
    ParseContactStepsOption(*args.contact_steps);
  }
  options.settle = args.settle;
  Scene(args.scene).Make(options);  // refuses what run refuses, before any window
  const std::string viewer = RequireProgram("simulate", "mujoco-simulate", "libmujoco-samples");
  const std::string plugin = FindPlugin();

  // the plugin first, before whatever the user preloads
  const char* preloaded = std::getenv("LD_PRELOAD");
  SetVariable("LD_PRELOAD", preloaded && *preloaded ? plugin + ":" + preloaded : plugin);
  SetVariable("CONTACTLAWS_LAW", args.law);
  SetVariable("CONTACTLAWS_RESTITUTION", args.restitution);
  SetVariable("CONTACTLAWS_FRICTION", args.friction);
  SetVariable("CONTACTLAWS_MU", args.mu);
  SetVariable("CONTACTLAWS_ACCURACY", args.accuracy);
  SetVariable("CONTACTLAWS_CONTACT_STEPS", args.contact_steps);
  SetVariable("CONTACTLAWS_SETTLE", args.settle ? std::optional<std::string>("1") : std::nullopt);
  SetVariable("CONTACTLAWS_LOOK", args.plain ? std::nullopt : std::optional<std::string>("1"));
  const char* argv[] = {viewer.c_str(), args.scene.c_str(), nullptr};
  execv(viewer.c_str(), const_cast<char* const*>(argv));
  throw Error(fmt::format("simulate: could not start {}", viewer));
}

}  // namespace contactlaws::cli
