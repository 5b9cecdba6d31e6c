// Copyright contactlaws authors.
//
// The commands of the contactlaws program. Each returns the exit status and
// throws Error for refused input (the caller prints it and exits 2).

#ifndef CONTACTLAWS_CLI_COMMANDS_H_
#define CONTACTLAWS_CLI_COMMANDS_H_

#include <atomic>
#include <cstdio>
#include <optional>
#include <string>

#include "cli/identify.h"
#include "cli/options.h"
#include "cli/sweep.h"

namespace contactlaws::cli {

inline constexpr int kExitRefused = 2;     // bad input: nothing was run
inline constexpr int kExitIncomplete = 3;  // a run did not give what was asked
inline constexpr int kExitInterrupted = 130;  // Ctrl-C (128 + SIGINT), as shells do

// The program's stop flag: set by Ctrl-C or SIGTERM (main.cc), given to every
// run the commands start (AdvanceOptions::stop), which then stop after their
// current step; a sweep starts no more runs.
inline std::atomic<bool> stop_signal{false};

struct RunArgs : CommonArgs {
  std::optional<std::string> law;
  std::optional<std::string> restitution;
  std::optional<std::string> output;
  std::optional<std::string> impacts;
  bool impacts_per_point = false;  // the impact log per contact point
};

struct CheckArgs {
  std::string scene;
  std::optional<std::string> law;
  std::optional<std::string> restitution;
  std::optional<std::string> dissipation;
  std::optional<std::string> friction;
  std::optional<std::string> mu;
  std::optional<std::string> timestep;
  std::optional<std::string> accuracy;  // auto's accuracy; implies --timestep auto
  std::optional<std::string> impact_velocity;
  std::FILE* report = stdout;  // where the report is printed
};

// contactlaws simulate: mujoco-simulate with the plugin preloaded.
struct SimulateArgs {
  std::string scene;
  std::optional<std::string> law;
  std::optional<std::string> restitution;
  std::optional<std::string> friction;
  std::optional<std::string> mu;
  std::optional<std::string> accuracy;  // the plugin steps with the auto timestep
  std::optional<std::string> contact_steps;  // the plugin integrates contacts inside the step
  bool settle = false;  // the plugin starts the bodies in contact settled
  bool plain = false;   // MuJoCo's default look, not render/scene_look.h's
};

// contactlaws render: the run drawn offscreen into a video or PNG files.
struct RenderArgs : CommonArgs {
  std::optional<std::string> law;
  std::optional<std::string> restitution;
  std::string output;
  std::string fps = "30";
  std::string width = "640";
  std::string height = "480";
  std::string slowmo = "1";
  std::optional<std::string> camera;
  std::optional<std::string> force_scale;
  bool plain = false;  // MuJoCo's default look, not render/scene_look.h's
};

int RunCommand(const RunArgs& args);
int SimulateCommand(const SimulateArgs& args);
int RenderCommand(const RenderArgs& args);
int CompareCommand(const SweepArgs& args);
int RestitutionCommand(const SweepArgs& args);
int CheckCommand(const CheckArgs& args);
struct LawsArgs {
  std::string format = "text";             // text or csv
  std::optional<std::string> restitution;  // csv: E1,E2,... or start:stop:step
  std::string output = "-";                // csv: the file, "-" for stdout
  std::FILE* report = stdout;              // text: where the tables are printed
};

int LawsCommand(const LawsArgs& args);
int ReplayCommand(const ReplayArgs& args);
int FitCommand(const FitArgs& args);

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_COMMANDS_H_
