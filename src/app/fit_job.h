// Copyright contactlaws authors.
//
// fit as users ask for it (docs/identification.md): the parameters fitted
// for every law x friction model asked, each combination cross-validated
// over folds of the training trajectories when asked, ranked by its
// (trimmed) mean score, compared with the winner by a paired bootstrap;
// the winner's simulated trajectories, its tag line and, when asked, its
// profile along the parameters. The results are tables of numbers and names
// (ranking, errors, folds, profile) and the lines said to a person.

#ifndef CONTACTLAWS_APP_FIT_JOB_H_
#define CONTACTLAWS_APP_FIT_JOB_H_

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/replay_job.h"
#include "app/stop.h"
#include "app/table.h"
#include "contactlaws/contactlaws.h"

namespace contactlaws::app {

// One law x friction model fitted, and its scores.
struct Fitted {
  std::optional<LawId> law;
  std::optional<FrictionKind> friction;
  // the parameters its tags read, and each one's place in the request's
  std::vector<FitParameter> parameters;
  std::vector<size_t> place;
  FitResult fit;
  std::vector<ReplayedTrajectory> train, validate;
  // with folds: each training trajectory scored by the fit of the folds
  // that left it out, in the data's order
  std::vector<ReplayedTrajectory> cv;
  std::string label;  // "flores/coulomb"
  std::optional<Combination> combination;  // the label's law and friction; none: "mujoco"
  // against the winner, on the ranking's per-trajectory scores
  PairedDifference versus_winner;
};

// The winner's profile asked for: the parameters (places in the request's)
// and how.
struct ProfileRequest {
  std::vector<size_t> keys;
  ProfileOptions options;
};

struct FitRequest {
  ReplayOptions base;  // every combination's, before its law and friction
  Metric metric = Metric::kEq;
  std::vector<FitParameter> parameters;
  // where the search starts, per parameter (nullopt: its range's middle);
  // empty: every one at its middle
  std::vector<std::optional<double>> initial;
  // the combinations: each law with each friction model (nullopt: the tags')
  std::vector<std::optional<LawId>> laws = {std::nullopt};
  std::vector<std::optional<FrictionKind>> frictions = {std::nullopt};
  int budget = 200;           // evaluations per fit
  std::optional<int> folds;   // K-fold cross-validation, K in [2, trajectories]
  double trim = 0;            // the share of worst trajectories a score leaves out
  uint64_t seed = 1;          // the search's, the folds', the bootstraps'
  std::optional<ProfileRequest> profile;
  StopToken stop;
  // Lines of progress (an evaluation, a profile started); none when empty.
  std::function<void(const std::string&)> progress;
};

// The fit's results: the ranked combinations and their tables.
struct FitOutcome {
  // stopped before any combination's first evaluation: nothing else is set
  bool nothing = false;
  bool interrupted = false;  // stopped: the best so far
  std::vector<Fitted> fitted;  // ranked, the winner first
  Table ranking, errors, folds, profile;  // folds, profile: when asked
  bool profiled = false;
  SimulatedSamples best_trajectories;  // the winner's, on the validation data if any
  std::string best_tag;                // the winner's tag line, to paste into the scene
  std::string report;                  // the ranking, the winner read in units, the profile
};

class FitJob {
 public:
  // Checks every combination's parameters against its tags (Error naming
  // the key) and splits the folds: every refusal before any fit. Keeps
  // references to scene and the data.
  FitJob(const Scene& scene, const MeasuredData& train, const MeasuredData* validate,
         FitRequest request);
  ~FitJob();
  FitJob(const FitJob&) = delete;
  FitJob& operator=(const FitJob&) = delete;

  // Runs the fits. Between its collective steps, ranks of a cluster job
  // (ReplayOptions::spread) all call it.
  FitOutcome Run() const;

 private:
  struct Combo {
    Fitted fitted;
    ReplayOptions options;
  };
  const Scene& scene_;
  const MeasuredData& train_data_;
  const MeasuredData* validate_data_;
  const FitRequest request_;
  const Replay train_;
  std::optional<Replay> validate_;
  std::vector<Combo> combos_;
  std::vector<int> fold_of_;
  std::vector<MeasuredData> fold_train_, fold_held_;
};

}  // namespace contactlaws::app

#endif  // CONTACTLAWS_APP_FIT_JOB_H_
