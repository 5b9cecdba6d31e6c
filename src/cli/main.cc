// Copyright contactlaws authors.
//
// contactlaws: the command line.
//   contactlaws run SCENE          one simulation: trajectory and impact CSV
//   contactlaws compare SCENE      laws x restitutions: trajectories, impacts, summary
//   contactlaws restitution SCENE  the first impact per law and e (paper Fig. 7)
//   contactlaws check SCENE        the resolved tags, contact estimates, timestep
//   contactlaws laws               every law: formula, parameters, citation
//   contactlaws simulate SCENE     mujoco-simulate with the plugin preloaded
//   contactlaws render SCENE       the run drawn offscreen: MP4, GIF or PNG files
//   contactlaws replay SCENE       measured trajectories simulated and scored
//   contactlaws fit SCENE          parameters identified from measured trajectories
// Exit status: 0 done; 2 refused input (one line on stderr naming the file,
// tag, key and value); 3 a run did not give what was asked; 1 anything else.

#include <signal.h>

#include <algorithm>
#include <iterator>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli/cluster.h"
#include "cli/commands.h"
#include "cli/mujoco_warnings.h"
#include "contactlaws/contactlaws.h"
#include "sim/spelling.h"

namespace contactlaws::cli {
namespace {

void AddSweep(CLI::App* cmd, SweepArgs* args, const char* restitution_help) {
  AddCommon(cmd, args, true);
  cmd->add_option("--laws", args->laws,
                  fmt::format("L1,L2,... or all ({})", LawNameList()))
      ->capture_default_str();
  cmd->add_option("--restitution", args->restitution, restitution_help);
  cmd->add_flag("--quiet", args->quiet, "no progress on stderr");
  cmd->add_option("--jobs", args->jobs,
                  "runs at a time, >= 1 (default: the number of cores); the output does not "
                  "depend on it")
      ->type_name("INT");
}

// Ctrl-C (or SIGTERM): the runs stop after their current step and the
// finished ones are written. The handler resets itself, so a second Ctrl-C
// ends the program at once.
extern "C" void OnStopSignal(int) { stop_signal.store(true, std::memory_order_relaxed); }

void InstallStopHandler() {
  struct sigaction action = {};
  action.sa_handler = OnStopSignal;
  action.sa_flags = SA_RESETHAND;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

// MuJoCo's warnings not reported with a run's, once each.
void ReportOtherMujocoWarnings() {
  for (const MujocoWarning& w : UnreportedMujocoWarnings()) {
    fmt::print(stderr, "contactlaws: warning: MuJoCo: {} ({} time{})\n", w.text, w.count,
               w.count == 1 ? "" : "s");
  }
}

// Every command's arguments, and the subcommand that takes them.
struct Commands {
  RunArgs run;
  SweepArgs compare;
  SweepArgs restitution;
  CheckArgs check;
  LawsArgs laws;
  SimulateArgs simulate;
  RenderArgs render;
  ReplayArgs replay;
  FitArgs fit;
  CLI::App* replay_cmd = nullptr;
  CLI::App* fit_cmd = nullptr;
  CLI::App* run_cmd = nullptr;
  CLI::App* compare_cmd = nullptr;
  CLI::App* restitution_cmd = nullptr;
  CLI::App* check_cmd = nullptr;
  CLI::App* laws_cmd = nullptr;
  CLI::App* simulate_cmd = nullptr;
  CLI::App* render_cmd = nullptr;
};

void AddRun(CLI::App* app, Commands* c) {
  c->run_cmd = app->add_subcommand("run", "simulate one tagged scene");
  AddCommon(c->run_cmd, &c->run, true);
  AddOverrides(c->run_cmd, &c->run.law, &c->run.restitution);
  c->run_cmd->add_option("--output", c->run.output,
                         "trajectory CSV ('-' for stdout), or NumPy's archive for FILE.npz "
                         "(numpy.load: rows and columns; the same doubles, no digits); none if "
                         "absent");
  c->run_cmd->add_option("--impacts", c->run.impacts,
                         "impact log CSV, one row per collision of a pair");
  c->run_cmd->add_flag("--impacts-per-point", c->run.impacts_per_point,
                       "the impact log with a row per contact episode of each contact point");
}

void AddCompare(CLI::App* app, Commands* c) {
  c->compare_cmd = app->add_subcommand(
      "compare", "every law x restitution on a scene: trajectories, impacts and summary CSV");
  AddSweep(c->compare_cmd, &c->compare,
           "E1,E2,... or start:stop:step, each in [0, 1] (default: the scene's)");
  c->compare_cmd->add_option("--output-dir", c->compare.output_dir,
                             "writes trajectories.csv, impacts.csv, summary.csv")
      ->capture_default_str();
  c->compare_cmd->add_option(
      "--frictions", c->compare.frictions,
      fmt::format("M1,M2,... or all ({}): each run with each friction model (a friction column "
                  "in the files); not with --friction",
                  FrictionNameList()));
  c->compare_cmd->add_flag("--impacts-per-point", c->compare.impacts_per_point,
                           "impacts.csv with a row per contact episode of each contact point");
}

void AddRestitution(CLI::App* app, Commands* c) {
  c->restitution_cmd = app->add_subcommand(
      "restitution", "the first impact of every law x restitution: e_post (paper Fig. 7)");
  AddSweep(c->restitution_cmd, &c->restitution,
           "E1,E2,... or start:stop:step, each in [0, 1] (default 0.1:1.0:0.1)");
  c->restitution_cmd->add_option("--output", c->restitution.output, "CSV, '-' for stdout")
      ->capture_default_str();
}

void AddCheck(CLI::App* app, Commands* c) {
  c->check_cmd = app->add_subcommand(
      "check", "the scene's tags resolved, contact estimates and the timestep they need");
  c->check_cmd->add_option("scene", c->check.scene, "MJCF scene with contactlaw tags")
      ->required();
  c->check_cmd->add_option("--law", c->check.law,
                           fmt::format("override every tag's law: {}", LawNameList()));
  AddNumber(c->check_cmd, "--restitution", &c->check.restitution,
            "override every tag's restitution");
  AddDissipation(c->check_cmd, &c->check.dissipation);
  AddFriction(c->check_cmd, &c->check.friction, &c->check.mu);
  c->check_cmd->add_option("--timestep", c->check.timestep,
                           "s (default: the scene's), or auto: the steps it would take");
  AddNumber(c->check_cmd, "--accuracy", &c->check.accuracy,
            "with --timestep auto (implied): the accuracy whose steps to show, in (0, 0.1] "
            "(default 0.001)");
  AddNumber(c->check_cmd, "--impact-velocity", &c->check.impact_velocity,
            "m/s (default: estimated from the scene's initial state)");
}

void AddLaws(CLI::App* app, Commands* c) {
  c->laws_cmd = app->add_subcommand("laws", "list the laws: formula, parameters, units, citation");
  c->laws_cmd
      ->add_option("--format", c->laws.format,
                   "text, or csv: each law's hysteresis coefficient a(e) and the restitution "
                   "it rebounds with, per restitution")
      ->capture_default_str();
  c->laws_cmd->add_option("--restitution", c->laws.restitution,
                          "with --format csv: E1,E2,... or start:stop:step (default "
                          "0.9,0.7,0.5,0.3,0.1)");
}

// --plain of render and simulate
void AddPlain(CLI::App* cmd, bool* plain) {
  cmd->add_flag("--plain", *plain,
                "MuJoCo's default look (default: what the scene lacks of a sky, a light, a "
                "floor's checker and body colours is MuJoCo's samples', docs/render.md)");
}

void AddSimulate(CLI::App* app, Commands* c) {
  c->simulate_cmd = app->add_subcommand(
      "simulate", "MuJoCo's viewer (mujoco-simulate) with the laws acting: the plugin preloaded");
  c->simulate_cmd->add_option("scene", c->simulate.scene, "MJCF scene with contactlaw tags")
      ->required();
  AddOverrides(c->simulate_cmd, &c->simulate.law, &c->simulate.restitution);
  AddFriction(c->simulate_cmd, &c->simulate.friction, &c->simulate.mu);
  AddNumber(c->simulate_cmd, "--accuracy", &c->simulate.accuracy,
            "step with the contact-aware timestep (docs/timestep.md) at this relative error in a "
            "collision's rebound, peak force and duration, in (0, 0.1] (default: the scene's "
            "fixed timestep)");
  c->simulate_cmd->add_option(
      "--contact-steps", c->simulate.contact_steps,
      "auto or N: integrate the contacts inside each of the scene's fixed steps, in sub-steps "
      "per contact (auto) or N of them (docs/timestep.md, \"Contact steps\"); default: off");
  AddSettle(c->simulate_cmd, &c->simulate.settle);
  AddPlain(c->simulate_cmd, &c->simulate.plain);
}

void AddRender(CLI::App* app, Commands* c) {
  CLI::App* cmd = c->render_cmd = app->add_subcommand(
      "render", "the run drawn offscreen (no window): a video, a GIF or PNG files");
  RenderArgs& r = c->render;
  AddCommon(cmd, &r, false);
  AddOverrides(cmd, &r.law, &r.restitution);
  cmd->add_option("--output", r.output, "FILE.mp4, FILE.gif, or DIR/ (one PNG per frame)")
      ->required();
  AddNumber(cmd, "--fps", &r.fps, "frames per second of video")->capture_default_str();
  cmd->add_option("--width", r.width, "pixels")->capture_default_str();
  cmd->add_option("--height", r.height, "pixels")->capture_default_str();
  AddNumber(cmd, "--slowmo", &r.slowmo,
            "K: one simulated second lasts K seconds of video (a contact lasts a millisecond)")
      ->capture_default_str();
  cmd->add_option("--camera", r.camera,
                  "track (the default: follows and frames the moving bodies), free (MuJoCo's "
                  "free camera of the model) or a camera of the scene");
  AddNumber(cmd, "--force-scale", &r.force_scale,
            "force arrows, m/N (default: a body's weight as long as the body, at most 3 "
            "times)");
  AddPlain(cmd, &r.plain);
}

// The options replay and fit share.
void AddReplayOptions(CLI::App* cmd, ReplayArgs* args) {
  cmd->add_option("scene", args->scene, "MJCF scene with contactlaw tags (or none: MuJoCo's own "
                  "contact)")->required();
  cmd->add_option("--data", args->data,
                  "measured trajectories, CSV (docs/identification.md)")->required();
  cmd->add_option("--start", args->start,
                  "first: each trajectory's first sample; refit: the published cube-toss rule "
                  "(docs/identification.md)")->capture_default_str();
  AddNumber(cmd, "--refit-height", &args->refit_height,
            "with --start refit: the height (m) whose first crossing the start precedes "
            "(default: the body's bounding radius)");
  cmd->add_option("--refit-lead", args->refit_lead,
                  "with --start refit: samples before that crossing")->capture_default_str();
  cmd->add_option("--refit-min-samples", args->refit_min_samples,
                  "with --start refit: velocities refit when the start is at least this sample")
      ->capture_default_str();
  cmd->add_option("--metric", args->metric,
                  "e_q (published), position_rms (m), angle_rms (rad), or weighted")
      ->capture_default_str();
  cmd->add_option("--weights", args->weights,
                  "with --metric weighted: P,A[,J]: P position_rms + A angle_rms + J joint_rms");
  AddNumber(cmd, "--length", &args->length,
            "e_q's length, m (default: each body's smallest geom size, a box's half side)");
  cmd->add_option("--timestep", args->timestep,
                  "s, or auto (default: auto for a tagged scene, else the scene's)");
  AddNumber(cmd, "--max-timestep", &args->max_timestep,
            "s, with --timestep auto: an optional cap on every step");
  AddNumber(cmd, "--accuracy", &args->accuracy,
            "with --timestep auto: the relative error accepted in a collision, in (0, 0.1]");
  cmd->add_option("--integrator", args->integrator, "euler, rk4 or implicit (default: the scene's)");
  AddOverrides(cmd, &args->law, &args->restitution);
  AddDissipation(cmd, &args->dissipation);
  AddFriction(cmd, &args->friction, &args->mu);
  cmd->add_option("--set", args->set, "KEY=VALUE: set a contactlaw tag key on every tag "
                  "(repeatable)");
  AddSettle(cmd, &args->settle);
  cmd->add_option("--seed", args->seed,
                  "the seed of the bootstrap intervals (and of fit's search and folds): the same "
                  "seed, the same result")
      ->capture_default_str();
  cmd->add_option("--jobs", args->jobs,
                  "threads, >= 1 (default: the number of cores); the results do not depend on it")
      ->type_name("INT");
  cmd->add_flag("--quiet", args->quiet, "no progress on stderr");
}

void AddReplay(CLI::App* app, Commands* c) {
  c->replay_cmd = app->add_subcommand(
      "replay", "simulate measured trajectories from their start state and score them");
  AddReplayOptions(c->replay_cmd, &c->replay);
  c->replay_cmd->add_option("--output", c->replay.output,
                            "DIR: writes replay.csv (scores) and trajectories.csv (simulated)");
  c->replay_cmd->add_option("--rest-plane", c->replay.rest_plane,
                            "GEOM: the plane's offset that puts it where the data rest");
}

void AddFit(CLI::App* app, Commands* c) {
  c->fit_cmd = app->add_subcommand(
      "fit", "identify tag and model parameters from measured trajectories (NLopt)");
  FitArgs& f = c->fit;
  AddReplayOptions(c->fit_cmd, &f);
  c->fit_cmd->add_option("--params", f.params,
                         "KEY=LO:HI[:log],...: tag keys, BODY.mass_scale, BODY.inertia_scale, "
                         "GEOM.offset (or GEOM.offset=rest: within the interval of where the data rest), "
                         "mujoco.timeconst|dampratio|dmin|dmax|width|friction")
      ->required();
  c->fit_cmd->add_option("--initial", f.initial,
                         "KEY=VALUE,...: where the search starts, keys of --params (the others at "
                         "the middle of their range, sqrt(LO HI) for :log); every --laws/--frictions "
                         "combination starts there");
  c->fit_cmd->add_option("--laws", f.laws, fmt::format("L1,L2,... or all ({})", LawNameList()));
  c->fit_cmd->add_option("--frictions", f.frictions,
                         fmt::format("M1,M2,... or all ({})", FrictionNameList()));
  c->fit_cmd->add_option("--validate", f.validate,
                         "measured trajectories the fit does not see, scored at the fitted values");
  c->fit_cmd->add_option("--budget", f.budget, "evaluations per combination")
      ->capture_default_str();
  c->fit_cmd->add_option("--folds", f.folds,
                         "K: K-fold cross-validation over the trajectories (seeded), ranked by "
                         "the held-out score");
  c->fit_cmd->add_option("--trim", f.trim,
                         "F in [0, 0.5): minimise and rank by the mean of the best (1 - F) share "
                         "of the trajectories (a trimmed mean; default 0: the mean)");
  c->fit_cmd->add_option("--profile", f.profile,
                         "all or KEY,...: the winner's score along each of these keys of --params "
                         "across its range, the others at their fitted values: profile.csv, and "
                         "whether the data determine each");
  c->fit_cmd->add_option("--profile-points", f.profile_points,
                         "N: points per parameter of --profile, 3 to 200 (default 9), and the "
                         "fitted value");
  c->fit_cmd->add_option("--profile-budget", f.profile_budget,
                         "N: with --profile, the other parameters re-fitted at each point over N "
                         "evaluations (default: held at their fitted values)");
  c->fit_cmd->add_option("--output", f.output,
                         "DIR (default fit): ranking.csv, errors.csv, best_trajectories.csv, "
                         "best_tag.txt");
}

// The subcommands, in the order the help lists them.
struct Subcommand {
  const char* name;
  void (*add)(CLI::App* app, Commands* c);
};
constexpr Subcommand kSubcommands[] = {
    {"run", AddRun},         {"compare", AddCompare}, {"restitution", AddRestitution},
    {"check", AddCheck},     {"laws", AddLaws},       {"simulate", AddSimulate},
    {"render", AddRender},   {"replay", AddReplay},   {"fit", AddFit}};

bool IsSubcommand(std::string_view word) {
  return std::any_of(std::begin(kSubcommands), std::end(kSubcommands),
                     [&](const Subcommand& s) { return word == s.name; });
}

// Adds to app the subcommand named first on the command line, alone, when
// nothing after it could reach another (another command's name, --help-all),
// so that a run does not build every command's options (start-up, issue
// 15); every subcommand otherwise. The parse is the same either way.
void AddSubcommands(CLI::App* app, Commands* c, int argc, char** argv) {
  bool alone = argc > 1 && IsSubcommand(argv[1]);
  for (int i = 2; alone && i < argc; ++i) {
    const std::string_view word = argv[i];
    alone = !IsSubcommand(word) && word.rfind("--help-all", 0) != 0;
  }
  for (const Subcommand& s : kSubcommands) {
    if (!alone || argv[1] == std::string_view(s.name)) s.add(app, c);
  }
}

bool Parsed(const CLI::App* cmd) { return cmd && cmd->parsed(); }

// Runs the command that was parsed; its exit status.
int Dispatch(const Commands& c) {
  try {
    if (Parsed(c.run_cmd)) return RunCommand(c.run);
    if (Parsed(c.compare_cmd)) return CompareCommand(c.compare);
    if (Parsed(c.restitution_cmd)) return RestitutionCommand(c.restitution);
    if (Parsed(c.check_cmd)) return CheckCommand(c.check);
    if (Parsed(c.laws_cmd)) return LawsCommand(c.laws);
    if (Parsed(c.simulate_cmd)) return SimulateCommand(c.simulate);
    if (Parsed(c.render_cmd)) return RenderCommand(c.render);
    if (Parsed(c.replay_cmd)) return ReplayCommand(c.replay);
    if (Parsed(c.fit_cmd)) return FitCommand(c.fit);
  } catch (const OptionError& e) {
    fmt::print(stderr, "contactlaws: {}\n", Spelled(e, kCommandLineSpelling));
    return kExitRefused;
  } catch (const Error& e) {
    fmt::print(stderr, "contactlaws: {}\n", e.what());
    return kExitRefused;
  } catch (const std::exception& e) {
    fmt::print(stderr, "contactlaws: internal error: {}\n", e.what());
  }
  return 1;
}

int Main(int argc, char** argv) {
  CLI::App app{"contactlaws: continuous contact force laws (Flores et al. 2011) in MuJoCo 2.2",
               "contactlaws"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "help for every command");
  app.set_version_flag("--version",
                       fmt::format("contactlaws {} (MuJoCo {}.{}.{})", LibraryVersion(),
                                   MujocoVersion() / 100, MujocoVersion() / 10 % 10,
                                   MujocoVersion() % 10),
                       "the library's version and MuJoCo's");
  Commands commands;
  commands.restitution.duration = "2";
  AddSubcommands(&app, &commands, argc, argv);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::string message = e.what();
    for (char& c : message) {
      if (c == '\n') c = ' ';
    }
    fmt::print(stderr, "contactlaws: {}\n", message);
    return kExitRefused;
  }

  // MuJoCo would print its warnings to stdout (and MUJOCO_LOG.TXT)
  mju_user_warning = RecordMujocoWarning;
  InstallStopHandler();
  const int status = Dispatch(commands);
  ReportOtherMujocoWarnings();
  return status;
}

}  // namespace
}  // namespace contactlaws::cli

int main(int argc, char** argv) {
  using namespace contactlaws::cli;
  if (!JoinCluster()) return kExitRefused;
  const int status = Main(argc, argv);
  LeaveCluster(status);
  return status;
}
