// Copyright contactlaws authors.

#include "cli/fit_ranking.h"

#include <algorithm>

#include <fmt/format.h>

#include "cli/identify.h"
#include "cli/impact_csv.h"

namespace contactlaws::cli {

namespace {

std::vector<double> Values(const std::vector<ReplayedTrajectory>& set, Metric metric) {
  std::vector<double> values;
  for (const ReplayedTrajectory& r : set) values.push_back(r.score.Of(metric));
  return values;
}

// The sets of f that were scored, with their data: (name, trajectories, data).
struct Set {
  const char* name;
  const std::vector<ReplayedTrajectory>* scored;
  const MeasuredData* data;
};
std::vector<Set> Sets(const Fitted& f, const ScoredData& data) {
  std::vector<Set> sets = {{"train", &f.train, data.train}, {"validate", &f.validate, data.validate}};
  if (data.folds) sets.push_back({"cv", &f.cv, data.train});
  return sets;
}

// ranking.csv's columns of one score array of a set: NAME_mean, _lo, _hi,
// NAME_median, _lo, _hi, NAME_p90 (a share: NAME, _lo, _hi)
std::vector<std::string> Columns(const std::string& set, const ScoreArray& a) {
  const std::string stem = set + "_" + (a.name.empty() ? "" : a.name + "_");
  if (a.share) return {set + "_" + a.name, set + "_" + a.name + "_lo", set + "_" + a.name + "_hi"};
  return {stem + "mean",   stem + "mean_lo",   stem + "mean_hi", stem + "median",
          stem + "median_lo", stem + "median_hi", stem + "p90"};
}
std::vector<std::string> Fields(const ScoreArray& a, uint64_t seed, bool empty) {
  const size_t count = a.share ? 3 : 7;
  if (empty) return std::vector<std::string>(count);
  const Summary s = Summarize(a.values, seed);
  if (a.share) return {Field(s.value.mean), Field(s.mean.lo), Field(s.mean.hi)};
  return {Field(s.value.mean),   Field(s.mean.lo),   Field(s.mean.hi), Field(s.value.median),
          Field(s.median.lo), Field(s.median.hi), Field(s.value.p90)};
}

std::string LawOf(const Fitted& f) {
  return f.combination ? std::string(LawName(f.combination->law)) : "mujoco";
}
std::string FrictionOf(const Fitted& f) {
  return f.combination ? std::string(FrictionName(f.combination->friction)) : "";
}

}  // namespace

std::optional<double> ValueOf(const Fitted& f, size_t i) {
  for (size_t k = 0; k < f.place.size(); ++k) {
    if (f.place[k] == i) return f.fit.values[k];
  }
  return std::nullopt;
}

const std::vector<ReplayedTrajectory>& Ranked(const Fitted& f, bool folds) {
  return folds ? f.cv : f.train;
}

void Rank(std::vector<Fitted>* fitted, Metric metric, const ScoredData& data, uint64_t seed) {
  // ranked by the training (or cross-validated) mean: choosing by the
  // held-out --validate scores would fit the choice to them
  const bool folds = data.folds;
  auto key = [&](const Fitted& f) { return TrimmedMeanScore(Ranked(f, folds), metric, data.trim); };
  std::stable_sort(fitted->begin(), fitted->end(),
                   [&](const Fitted& a, const Fitted& b) { return key(a) < key(b); });
  const std::vector<double> winner = Values(Ranked(fitted->front(), folds), metric);
  for (Fitted& f : *fitted) {
    f.versus_winner =
        ComparePairedTrimmed(Values(Ranked(f, folds), metric), winner, data.trim, seed);
  }
}

void WriteRanking(const std::vector<Fitted>& fitted, const std::vector<FitParameter>& parameters,
                  Metric metric, const ScoredData& data, uint64_t seed, CsvFile* ranking,
                  CsvFile* errors) {
  std::vector<std::string> header = {"law", "friction"};
  for (const FitParameter& p : parameters) header.push_back(p.key);
  for (const Set& set : Sets(fitted.front(), data)) {
    for (const ScoreArray& a : ReadableScores(*data.train, {}, metric)) {
      for (std::string& c : Columns(set.name, a)) header.push_back(std::move(c));
    }
    if (data.trim > 0) {
      for (const char* c : {"_trimmed_mean", "_trimmed_mean_lo", "_trimmed_mean_hi"}) {
        header.push_back(set.name + std::string(c));
      }
    }
  }
  for (const char* column : {"versus_winner", "versus_winner_lo", "versus_winner_hi",
                             "distinguishable", "evaluations", "wall_seconds", "status"}) {
    header.emplace_back(column);
  }
  ranking->Header(header);
  std::vector<std::string> error_header = {"law", "friction", "set"};
  for (const std::string& column : ReplayColumns()) error_header.push_back(column);
  errors->Header(error_header);
  for (const Fitted& f : fitted) {
    std::vector<std::string> row = {LawOf(f), FrictionOf(f)};
    for (size_t i = 0; i < parameters.size(); ++i) {
      const std::optional<double> v = ValueOf(f, i);
      row.push_back(v ? Field(*v) : "");
    }
    for (const Set& set : Sets(f, data)) {
      const std::vector<ScoreArray> arrays =
          set.data ? ReadableScores(*set.data, *set.scored, metric)
                   : ReadableScores(*data.train, {}, metric);
      for (const ScoreArray& a : arrays) {
        for (std::string& field : Fields(a, seed, set.scored->empty())) row.push_back(std::move(field));
      }
      if (data.trim > 0) {
        if (set.scored->empty()) {
          row.insert(row.end(), 3, "");
        } else {
          const Estimate e = SummarizeTrimmed(Values(*set.scored, metric), data.trim, seed);
          for (double v : {e.value, e.interval.lo, e.interval.hi}) row.push_back(Field(v));
        }
      }
    }
    const PairedDifference& d = f.versus_winner;
    for (double v : {d.mean, d.interval.lo, d.interval.hi}) row.push_back(Field(v));
    row.push_back(&f == &fitted.front() ? "winner" : d.Distinguishable() ? "yes" : "no");
    row.push_back(fmt::format("{}", f.fit.evaluations));
    row.push_back(fmt::format("{:.3f}", f.fit.wall_seconds));
    row.push_back(f.fit.interrupted ? "interrupted" : "complete");
    ranking->Fields(row);
    for (const Set& set : Sets(f, data)) {
      const app::ReplayScores scores = app::ScoresOf(*set.data, *set.scored);
      for (size_t i = 0; i < set.scored->size(); ++i) {
        std::vector<std::string> fields = {LawOf(f), FrictionOf(f), set.name};
        for (std::string& field : ScoreFields(scores, i)) {
          fields.push_back(std::move(field));
        }
        errors->Fields(fields);
      }
    }
  }
}

void PrintRanking(const std::vector<Fitted>& fitted, const std::vector<FitParameter>& parameters,
                  Metric metric, const ScoredData& data, uint64_t seed, std::FILE* out) {
  const char* ranked = data.folds ? "cv" : "train";
  fmt::print(out, "{:<32}", "law/friction");
  for (const FitParameter& p : parameters) fmt::print(out, " {:>13}", p.key.substr(0, 13));
  fmt::print(out, " {:>26} {:>10}", "train mean [95%]", "median");
  if (data.folds) fmt::print(out, " {:>26} {:>10}", "cv mean [95%]", "median");
  if (data.validate) fmt::print(out, " {:>10} {:>10} {:>10}", "valid. mean", "median", "p90");
  if (data.trim > 0) fmt::print(out, " {:>26}", fmt::format("{} trimmed [95%]", ranked));
  fmt::print(out, " {:>28} {:>6} {:>8}\n", fmt::format("- winner's {} [95%]", ranked), "evals",
             "wall s");
  auto cell = [](const Summary& s) {
    return fmt::format("{:.4g} [{:.4g}, {:.4g}]", s.value.mean, s.mean.lo, s.mean.hi);
  };
  std::vector<std::string> apart, together;
  for (const Fitted& f : fitted) {
    fmt::print(out, "{:<32}", f.label + (f.fit.interrupted ? " (interrupted)" : ""));
    for (size_t i = 0; i < parameters.size(); ++i) {
      const std::optional<double> v = ValueOf(f, i);
      fmt::print(out, " {:>13}", v ? fmt::format("{:.6g}", *v) : "-");
    }
    const Summary t = Summarize(Values(f.train, metric), seed);
    fmt::print(out, " {:>26} {:>10.4g}", cell(t), t.value.median);
    if (data.folds) {
      const Summary c = Summarize(Values(f.cv, metric), seed);
      fmt::print(out, " {:>26} {:>10.4g}", cell(c), c.value.median);
    }
    if (data.validate) {
      const Distribution v = Distribute(Values(f.validate, metric));
      fmt::print(out, " {:>10.4g} {:>10.4g} {:>10.4g}", v.mean, v.median, v.p90);
    }
    if (data.trim > 0) {
      const Estimate e = SummarizeTrimmed(Values(Ranked(f, data.folds), metric), data.trim, seed);
      fmt::print(out, " {:>26}",
                 fmt::format("{:.4g} [{:.4g}, {:.4g}]", e.value, e.interval.lo, e.interval.hi));
    }
    const PairedDifference& d = f.versus_winner;
    const bool winner = &f == &fitted.front();
    if (!winner) (d.Distinguishable() ? apart : together).push_back(f.label);
    fmt::print(out, " {:>28} {:>6} {:>8.1f}\n",
               winner ? "winner"
                      : fmt::format("{:+.3g} [{:+.3g}, {:+.3g}]{}", d.mean, d.interval.lo,
                                    d.interval.hi, d.Distinguishable() ? "" : " ="),
               f.fit.evaluations, f.fit.wall_seconds);
  }
  auto list = [](const std::vector<std::string>& v) {
    std::string s;
    for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
    return v.empty() ? std::string("none") : s;
  };
  const std::string score =
      data.trim > 0 ? fmt::format("{} mean of the best {:g}%", MetricName(metric), 100 * (1 - data.trim))
                    : std::string(MetricName(metric));
  fmt::print(out,
             "the data ({} {}, paired 95% bootstrap over {} trajectories) tell {} apart from: "
             "{}; not from (=): {}\n",
             ranked, score, Ranked(fitted.front(), data.folds).size(), fitted.front().label,
             list(apart), list(together));
}

}  // namespace contactlaws::cli
