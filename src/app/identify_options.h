// Copyright contactlaws authors.
//
// The options of replay and fit as users give them, read into their
// requests (app/replay_job.h, app/fit_job.h) by the option grammar
// (app/options.h), each refusal naming the option as its front-end spells
// it (docs/identification.md).

#ifndef CONTACTLAWS_APP_IDENTIFY_OPTIONS_H_
#define CONTACTLAWS_APP_IDENTIFY_OPTIONS_H_

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/fit_job.h"
#include "app/options.h"
#include "app/replay_job.h"
#include "contactlaws/contactlaws.h"

namespace contactlaws::app {

// replay's options; fit takes them all. The common ones (CommonInput) but
// duration, sample_rate, columns and contact_steps, which replay does not
// read.
struct ReplayInput : CommonInput {
  std::string start = "first";     // first or refit
  std::optional<Value> refit_height;  // m
  Value refit_lead = 3.0;          // samples
  Value refit_min_samples = 4.0;   // samples
  std::string metric = "e_q";
  std::optional<std::string> weights;  // P,A[,J] of the weighted metric
  std::optional<Value> length;     // e_q's L, m
  std::optional<Value> jobs;
  std::optional<std::string> law;
  std::optional<Value> restitution;
  std::vector<std::string> set;    // KEY=VALUE on every tag
  Value seed = 1.0;                // the bootstrap's (and fit's search and folds)
};

struct FitInput : ReplayInput {
  std::string params;                    // KEY=LO:HI[:log],...
  std::optional<std::string> initial;    // KEY=VALUE,...: where the search starts
  std::optional<std::string> laws;       // L1,L2,... or all
  std::optional<std::string> frictions;  // M1,M2,... or all
  Value budget = 200.0;
  std::optional<Value> folds;            // K-fold cross-validation over the trajectories
  std::optional<Value> trim;             // the share of worst trajectories a score leaves out
  std::optional<std::string> profile;    // all or KEY,...: the winner's profile along them
  std::optional<Value> profile_points;   // per parameter
  std::optional<Value> profile_budget;   // the others re-fitted at each point
};

// The replay options of input (the scene's tags read later, by Replay::Run):
// the law and friction overrides, set, the timestep (auto unless a timestep
// is given or the scene has no contactlaw tag), the start rule, the weights,
// the jobs; no spread. metric: the metric chosen.
ReplayOptions ReadReplayOptions(const OptionReader& reader, const ReplayInput& input,
                                const Scene& scene, Metric* metric);

// seed: a whole number in [0, 4294967295].
uint64_t ReadSeed(const OptionReader& reader, const Value& seed);

// The measured data of path (the option key's), bound to a scene by
// Replay's constructor.
MeasuredData ReadData(const OptionReader& reader, std::string_view key, const std::string& path);

// fit's request of input (every option but the stop and the progress): the
// parameters (GEOM.offset=rest bounded by the data's estimate, whose lines
// go to offset_lines), the combinations, the budget, folds, trim, profile.
FitRequest ReadFitRequest(const OptionReader& reader, const FitInput& input, const Scene& scene,
                          const MeasuredData& train_data, std::vector<std::string>* offset_lines);

// The job of request, its refusals under params.
FitJob CheckedFitJob(const OptionReader& reader, const Scene& scene, const MeasuredData& train,
                     const MeasuredData* validate, FitRequest request);

}  // namespace contactlaws::app

#endif  // CONTACTLAWS_APP_IDENTIFY_OPTIONS_H_
