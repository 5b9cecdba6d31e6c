// Copyright contactlaws authors.

#include "cli/sweep.h"

#include <unistd.h>

#include <filesystem>

#include <fmt/format.h>

#include "cli/cluster.h"
#include "cli/commands.h"
#include "cli/mujoco_warnings.h"
#include "cli/report.h"

namespace contactlaws::cli {

app::SweepInput InputOf(const SweepArgs& args) {
  app::SweepInput input;
  static_cast<app::CommonInput&>(input) = InputOf(static_cast<const CommonArgs&>(args));
  input.laws = args.laws;
  input.restitution = ValueOf(args.restitution);
  input.frictions = args.frictions;
  input.jobs = ValueOf(args.jobs);
  return input;
}

ProgramMonitor::ProgramMonitor(bool quiet) : progress_(!quiet && isatty(STDERR_FILENO)) {}

ProgramMonitor::~ProgramMonitor() { EndProgress(); }

void ProgramMonitor::EndProgress() {
  if (progress_ && started_) fmt::print(stderr, "\r\033[K");
  started_ = false;
}

void ProgramMonitor::Warn(const std::string& scene, const std::string& what) {
  EndProgress();
  cli::Warn(scene, what);
}

void ProgramMonitor::TagWarning(const std::string& what) {
  EndProgress();
  if (WritesOutputs()) fmt::print(stderr, "contactlaws: warning: {}\n", what);
}

void ProgramMonitor::Note(const std::string& scene, const std::string& what) {
  EndProgress();
  fmt::print(stderr, "contactlaws: {}: {}\n", scene, what);
}

void ProgramMonitor::RunFailed(const std::string& scene, const std::string& run,
                               const std::string& reason) {
  EndProgress();
  if (WritesOutputs()) {
    fmt::print(stderr, "contactlaws: {}: {}: run failed: {}\n", scene, run, reason);
  }
}

void ProgramMonitor::RunDone(int k, int count, const std::string& run) {
  if (!progress_) return;
  started_ = true;
  fmt::print(stderr, "\r\033[K[{}/{}] {}", k + 1, count, run);
  std::fflush(stderr);
}

void ProgramMonitor::RunFinished(const Simulation& sim) {
  // reported with the run's warnings: not again as the program ends
  for (const MujocoWarning& w : sim.Warnings()) NoteReportedMujocoWarning(w.text);
}

void ProgramMonitor::SweepDone() { EndProgress(); }

int ExitStatus(app::SweepStatus status) {
  switch (status) {
    case app::SweepStatus::kComplete: return 0;
    case app::SweepStatus::kInterrupted:
      fmt::print(stderr, "contactlaws: interrupted: the finished runs are written\n");
      return kExitInterrupted;
    // a sweep ends complete, failed or interrupted (Sweep); its runs diverge
    case app::SweepStatus::kFailed:
    case app::SweepStatus::kDiverged:
    case app::SweepStatus::kNotRun: return kExitIncomplete;
  }
  return kExitIncomplete;
}

std::string CreateDirectory(const std::string& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) {
    throw Error(fmt::format("{}: cannot create the output directory ({})", dir, error.message()));
  }
  return dir;
}

}  // namespace contactlaws::cli
