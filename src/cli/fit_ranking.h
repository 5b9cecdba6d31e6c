// Copyright contactlaws authors.
//
// fit's combinations once fitted: how they are ranked (by the held-out
// cross-validated score with --folds, else the training score), compared
// with the winner (a paired bootstrap of per-trajectory differences), and
// written (ranking.csv, errors.csv) and printed (docs/identification.md).

#ifndef CONTACTLAWS_CLI_FIT_RANKING_H_
#define CONTACTLAWS_CLI_FIT_RANKING_H_

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "cli/csv_file.h"
#include "contactlaws/contactlaws.h"

namespace contactlaws::cli {

// One law x friction model fitted, and its scores.
struct Fitted {
  std::optional<LawId> law;
  std::optional<FrictionKind> friction;
  // the parameters its tags read, and each one's place in --params
  std::vector<FitParameter> parameters;
  std::vector<size_t> place;
  FitResult fit;
  std::vector<ReplayedTrajectory> train, validate;
  // with --folds: each training trajectory scored by the fit of the folds
  // that left it out, in the data's order
  std::vector<ReplayedTrajectory> cv;
  std::string label;  // "flores/coulomb"
  std::optional<Combination> combination;  // the label's law and friction; none: "mujoco"
  // against the winner, on the ranking's per-trajectory scores
  PairedDifference versus_winner;
};

// f's value of --params' parameter i, nullopt when its tags do not read it.
std::optional<double> ValueOf(const Fitted& f, size_t i);

// The trajectories the ranking reads: cv with folds, else train.
const std::vector<ReplayedTrajectory>& Ranked(const Fitted& f, bool folds);

// The data the scores of each set are of.
struct ScoredData {
  const MeasuredData* train = nullptr;
  const MeasuredData* validate = nullptr;  // null without --validate
  bool folds = false;
  double trim = 0;  // --trim: the ranking's and the comparison's trimmed mean
};

// Sorts fitted by the (trimmed) mean of metric over Ranked (stable: ties
// keep the command line's order) and compares each with the first.
void Rank(std::vector<Fitted>* fitted, Metric metric, const ScoredData& data, uint64_t seed);

// ranking.csv and errors.csv of the ranked combinations.
void WriteRanking(const std::vector<Fitted>& fitted, const std::vector<FitParameter>& parameters,
                  Metric metric, const ScoredData& data, uint64_t seed, CsvFile* ranking,
                  CsvFile* errors);

// The table, then the line of what the data tell apart.
void PrintRanking(const std::vector<Fitted>& fitted, const std::vector<FitParameter>& parameters,
                  Metric metric, const ScoredData& data, uint64_t seed, std::FILE* out);

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_FIT_RANKING_H_
