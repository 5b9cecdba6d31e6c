// Copyright contactlaws authors.
//
// compare and restitution on the command line: their options as given,
// read by the application's sweep (app/sweep.h), and what the sweep says as
// it goes printed on stderr.

#ifndef CONTACTLAWS_CLI_SWEEP_H_
#define CONTACTLAWS_CLI_SWEEP_H_

#include <cstdio>
#include <optional>
#include <string>

#include "app/sweep.h"
#include "cli/options.h"

namespace contactlaws::cli {

// The options of compare and restitution as given.
struct SweepArgs : CommonArgs {
  std::string laws = "all";
  std::optional<std::string> restitution;  // list or range
  std::optional<std::string> frictions;    // compare: M1,M2,... or all
  std::string output_dir = "results";      // compare
  std::string output = "-";                // restitution
  bool quiet = false;
  std::optional<std::string> jobs;         // default: the number of cores
  bool impacts_per_point = false;          // compare
  std::FILE* report = stdout;              // where the table is printed
};

// The options as the sweep reads them: the same text.
app::SweepInput InputOf(const SweepArgs& args);

// What a sweep says, on stderr: warnings (rank 0 of a cluster job alone),
// the settled line, failed runs, and a progress line when stderr
// is a terminal and not quiet.
class ProgramMonitor : public app::SweepMonitor {
 public:
  explicit ProgramMonitor(bool quiet);
  ~ProgramMonitor() override;
  ProgramMonitor(const ProgramMonitor&) = delete;
  ProgramMonitor& operator=(const ProgramMonitor&) = delete;

  void Warn(const std::string& scene, const std::string& what) override;
  void TagWarning(const std::string& what) override;
  void Note(const std::string& scene, const std::string& what) override;
  void RunFailed(const std::string& scene, const std::string& run,
                 const std::string& reason) override;
  void RunDone(int k, int count, const std::string& run) override;
  void RunFinished(const Simulation& sim) override;
  void SweepDone() override;

 private:
  // Ends the progress line, before anything else is printed.
  void EndProgress();

  bool progress_;           // a progress line is wanted
  bool started_ = false;    // one is on the terminal
};

// The exit status of a sweep: 0, kExitIncomplete when a run failed,
// kExitInterrupted after a stop request (saying so on stderr).
int ExitStatus(app::SweepStatus status);

// Creates dir (and its parents); throws Error naming it when it cannot.
std::string CreateDirectory(const std::string& dir);

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_SWEEP_H_
