// Copyright contactlaws authors.

#include "app/fit_job.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

#include <fmt/format.h>

#include "scene/number.h"
#include "scene/tag_keys.h"
#include "scene/tags.h"

namespace contactlaws::app {
namespace {

std::vector<double> Values(const std::vector<ReplayedTrajectory>& set, Metric metric) {
  std::vector<double> values;
  for (const ReplayedTrajectory& r : set) values.push_back(r.score.Of(metric));
  return values;
}

// The data the scores of each set are of.
struct ScoredData {
  const MeasuredData* train = nullptr;
  const MeasuredData* validate = nullptr;  // null without validation data
  bool folds = false;
  double trim = 0;  // the ranking's and the comparison's trimmed mean
};

// The trajectories the ranking reads: cv with folds, else train.
const std::vector<ReplayedTrajectory>& Ranked(const Fitted& f, bool folds) {
  return folds ? f.cv : f.train;
}

// f's value of the request's parameter i, nullopt when its tags do not read it.
std::optional<double> ValueOf(const Fitted& f, size_t i) {
  for (size_t k = 0; k < f.place.size(); ++k) {
    if (f.place[k] == i) return f.fit.values[k];
  }
  return std::nullopt;
}

// Sorts fitted by the (trimmed) mean of metric over Ranked (stable: ties
// keep the request's order) and compares each with the first.
void Rank(std::vector<Fitted>* fitted, Metric metric, const ScoredData& data, uint64_t seed) {
  // ranked by the training (or cross-validated) mean: choosing by the
  // held-out validation scores would fit the choice to them
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

// The sets of f that were scored, with their data.
struct Set {
  const char* name;
  const std::vector<ReplayedTrajectory>* scored;
  const MeasuredData* data;
};
std::vector<Set> Sets(const Fitted& f, const ScoredData& data) {
  std::vector<Set> sets = {{"train", &f.train, data.train},
                           {"validate", &f.validate, data.validate}};
  if (data.folds) sets.push_back({"cv", &f.cv, data.train});
  return sets;
}

// The ranking's columns of one score array of a set: NAME_mean, _lo, _hi,
// NAME_median, _lo, _hi, NAME_p90 (a share: NAME, _lo, _hi)
std::vector<std::string> SummaryColumns(const std::string& set, const ScoreArray& a) {
  const std::string stem = set + "_" + (a.name.empty() ? "" : a.name + "_");
  if (a.share) return {set + "_" + a.name, set + "_" + a.name + "_lo", set + "_" + a.name + "_hi"};
  return {stem + "mean",   stem + "mean_lo",   stem + "mean_hi", stem + "median",
          stem + "median_lo", stem + "median_hi", stem + "p90"};
}
std::vector<Cell> SummaryCells(const ScoreArray& a, uint64_t seed, bool empty) {
  const size_t count = a.share ? 3 : 7;
  if (empty) return std::vector<Cell>(count, Unknown());
  const Summary s = Summarize(a.values, seed);
  if (a.share) return {Number(s.value.mean), Number(s.mean.lo), Number(s.mean.hi)};
  return {Number(s.value.mean),   Number(s.mean.lo),   Number(s.mean.hi), Number(s.value.median),
          Number(s.median.lo), Number(s.median.hi), Number(s.value.p90)};
}

std::string LawOf(const Fitted& f) {
  return f.combination ? std::string(LawName(f.combination->law)) : "mujoco";
}
std::string FrictionOf(const Fitted& f) {
  return f.combination ? std::string(FrictionName(f.combination->friction)) : "";
}

using Header = std::vector<std::pair<std::string, Column::Kind>>;

// A value with its 95% interval: the columns NAME, NAME_lo, NAME_hi.
void AddIntervalColumns(const std::string& name, Header* header) {
  for (const char* suffix : {"", "_lo", "_hi"}) {
    header->emplace_back(name + suffix, Column::Kind::kNumber);
  }
}
void AddIntervalCells(double value, const Interval& interval, std::vector<Cell>* row) {
  for (double v : {value, interval.lo, interval.hi}) row->push_back(Number(v));
}

// wall_seconds: to the millisecond, a time that differs run to run
double Milliseconds(double seconds) { return std::round(seconds * 1e3) / 1e3; }

Table RankingTable(const std::vector<Fitted>& fitted, const std::vector<FitParameter>& parameters,
                   Metric metric, const ScoredData& data, uint64_t seed) {
  using Kind = Column::Kind;
  Header header = {{"law", Kind::kText}, {"friction", Kind::kText}};
  for (const FitParameter& p : parameters) header.emplace_back(p.key, Kind::kNumber);
  for (const Set& set : Sets(fitted.front(), data)) {
    for (const ScoreArray& a : ReadableScores(*data.train, {}, metric)) {
      for (std::string& c : SummaryColumns(set.name, a)) header.emplace_back(c, Kind::kNumber);
    }
    if (data.trim > 0) {
      AddIntervalColumns(set.name + std::string("_trimmed_mean"), &header);
    }
  }
  AddIntervalColumns("versus_winner", &header);
  header.emplace_back("distinguishable", Kind::kText);
  header.emplace_back("evaluations", Kind::kCount);
  header.emplace_back("wall_seconds", Kind::kNumber);
  header.emplace_back("status", Kind::kText);
  Table ranking(std::move(header));
  for (const Fitted& f : fitted) {
    std::vector<Cell> row = {Text(LawOf(f)), Text(FrictionOf(f))};
    for (size_t i = 0; i < parameters.size(); ++i) {
      const std::optional<double> v = ValueOf(f, i);
      row.push_back(v ? Number(*v) : Unknown());
    }
    for (const Set& set : Sets(f, data)) {
      const std::vector<ScoreArray> arrays =
          set.data ? ReadableScores(*set.data, *set.scored, metric)
                   : ReadableScores(*data.train, {}, metric);
      for (const ScoreArray& a : arrays) {
        for (Cell& c : SummaryCells(a, seed, set.scored->empty())) row.push_back(std::move(c));
      }
      if (data.trim > 0) {
        if (set.scored->empty()) {
          row.insert(row.end(), 3, Unknown());
        } else {
          const Estimate e = SummarizeTrimmed(Values(*set.scored, metric), data.trim, seed);
          AddIntervalCells(e.value, e.interval, &row);
        }
      }
    }
    const PairedDifference& d = f.versus_winner;
    AddIntervalCells(d.mean, d.interval, &row);
    row.push_back(Text(&f == &fitted.front() ? "winner" : d.Distinguishable() ? "yes" : "no"));
    row.push_back(Count(f.fit.evaluations));
    row.push_back(Number(Milliseconds(f.fit.wall_seconds)));
    row.push_back(Text(f.fit.interrupted ? "interrupted" : "complete"));
    ranking.AddRow(row);
  }
  return ranking;
}

Table ErrorsTable(const std::vector<Fitted>& fitted, const ScoredData& data) {
  Table errors;
  for (const Fitted& f : fitted) {
    for (const Set& set : Sets(f, data)) {
      if (!set.data) continue;
      const Table scores = ScoresTable(ScoresOf(*set.data, *set.scored));
      if (errors.columns().empty()) {
        std::vector<std::pair<std::string, Column::Kind>> header = {
            {"law", Column::Kind::kText}, {"friction", Column::Kind::kText},
            {"set", Column::Kind::kText}};
        for (const Column& c : scores.columns()) header.emplace_back(c.name, c.kind);
        errors = Table(std::move(header));
      }
      for (size_t i = 0; i < scores.rows(); ++i) {
        std::vector<Cell> row = {Text(LawOf(f)), Text(FrictionOf(f)), Text(set.name)};
        for (const Column& c : scores.columns()) {
          row.push_back(c.kind == Column::Kind::kText ? Text(c.text[i])
                                                      : Cell{c.kind, c.numbers[i], {}});
        }
        errors.AddRow(row);
      }
    }
  }
  return errors;
}

// The table, then the line of what the data tell apart.
std::string RankingText(const std::vector<Fitted>& fitted,
                        const std::vector<FitParameter>& parameters, Metric metric,
                        const ScoredData& data, uint64_t seed) {
  std::string text;
  auto out = std::back_inserter(text);
  const char* ranked = data.folds ? "cv" : "train";
  fmt::format_to(out, "{:<32}", "law/friction");
  for (const FitParameter& p : parameters) fmt::format_to(out, " {:>13}", p.key.substr(0, 13));
  fmt::format_to(out, " {:>26} {:>10}", "train mean [95%]", "median");
  if (data.folds) fmt::format_to(out, " {:>26} {:>10}", "cv mean [95%]", "median");
  if (data.validate) fmt::format_to(out, " {:>10} {:>10} {:>10}", "valid. mean", "median", "p90");
  if (data.trim > 0) fmt::format_to(out, " {:>26}", fmt::format("{} trimmed [95%]", ranked));
  fmt::format_to(out, " {:>28} {:>6} {:>8}\n", fmt::format("- winner's {} [95%]", ranked),
                 "evals", "wall s");
  auto cell = [](const Summary& s) {
    return fmt::format("{:.4g} [{:.4g}, {:.4g}]", s.value.mean, s.mean.lo, s.mean.hi);
  };
  std::vector<std::string> apart, together;
  for (const Fitted& f : fitted) {
    fmt::format_to(out, "{:<32}", f.label + (f.fit.interrupted ? " (interrupted)" : ""));
    for (size_t i = 0; i < parameters.size(); ++i) {
      const std::optional<double> v = ValueOf(f, i);
      fmt::format_to(out, " {:>13}", v ? fmt::format("{:.6g}", *v) : "-");
    }
    const Summary t = Summarize(Values(f.train, metric), seed);
    fmt::format_to(out, " {:>26} {:>10.4g}", cell(t), t.value.median);
    if (data.folds) {
      const Summary c = Summarize(Values(f.cv, metric), seed);
      fmt::format_to(out, " {:>26} {:>10.4g}", cell(c), c.value.median);
    }
    if (data.validate) {
      const Distribution v = Distribute(Values(f.validate, metric));
      fmt::format_to(out, " {:>10.4g} {:>10.4g} {:>10.4g}", v.mean, v.median, v.p90);
    }
    if (data.trim > 0) {
      const Estimate e = SummarizeTrimmed(Values(Ranked(f, data.folds), metric), data.trim, seed);
      fmt::format_to(out, " {:>26}",
                     fmt::format("{:.4g} [{:.4g}, {:.4g}]", e.value, e.interval.lo,
                                 e.interval.hi));
    }
    const PairedDifference& d = f.versus_winner;
    const bool winner = &f == &fitted.front();
    if (!winner) (d.Distinguishable() ? apart : together).push_back(f.label);
    fmt::format_to(out, " {:>28} {:>6} {:>8.1f}\n",
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
      data.trim > 0
          ? fmt::format("{} mean of the best {:g}%", MetricName(metric), 100 * (1 - data.trim))
          : std::string(MetricName(metric));
  fmt::format_to(out,
                 "the data ({} {}, paired 95% bootstrap over {} trajectories) tell {} apart "
                 "from: {}; not from (=): {}\n",
                 ranked, score, Ranked(fitted.front(), data.folds).size(), fitted.front().label,
                 list(apart), list(together));
  return text;
}

// The unit of a parameter's values as printed after a number ("N/m^n",
// "m"), or "" for a ratio, a scale or a unit the key table describes in
// words rather than symbols.
std::string Unit(const FitParameter& p) {
  if (!p.tag_key) {
    switch (p.edit.kind) {
      case ModelEdit::Kind::kOffset: return "m";
      case ModelEdit::Kind::kMujocoTimeconst: return "s";
      case ModelEdit::Kind::kMujocoWidth: return "m";
      default: return "";
    }
  }
  const TagKey* key = FindTagKey(p.key);
  if (!key) return "";
  // "m, the torque cap over the normal force": the symbol before the comma
  std::string unit(key->unit.substr(0, key->unit.find(',')));
  if (unit.find(':') != std::string::npos || unit.find(" over ") != std::string::npos) return "";
  return unit;
}

// The winner's profiles along the keys it reads (a key it does not read
// has none), over replay with the winner's options.
struct WinnerProfile {
  std::vector<ParameterProfile> profiles;
  std::vector<size_t> unread;  // places in the request's parameters the winner does not read
  bool interrupted = false;
};

WinnerProfile ProfileWinner(const Fitted& winner, const Replay& replay, const FitOptions& options,
                            const ProfileRequest& request,
                            const std::function<void(const std::string&)>& progress) {
  WinnerProfile out;
  for (size_t place : request.keys) {
    const auto at = std::find(winner.place.begin(), winner.place.end(), place);
    if (at == winner.place.end()) {
      out.unread.push_back(place);
      continue;
    }
    const size_t k = at - winner.place.begin();
    if (progress) {
      progress(fmt::format("profile {}: {}: {} points{}", winner.label, winner.parameters[k].key,
                           request.options.points,
                           request.options.budget > 0
                               ? fmt::format(", the others re-fitted over {} evaluations each",
                                             request.options.budget)
                               : ""));
    }
    std::vector<ParameterProfile> one =
        Profile(replay, options, winner.fit.values, {k}, request.options);
    out.interrupted = one.empty() || one.front().interrupted;
    if (out.interrupted) break;
    out.profiles.push_back(std::move(one.front()));
  }
  return out;
}

// A row per point (with trim > 0, the trimmed mean beside the mean).
Table ProfileTable(const Fitted& winner, const WinnerProfile& profile, double trim) {
  using Kind = Column::Kind;
  Header header = {{"key", Kind::kText},
                   {"scale", Kind::kText},
                   {"value", Kind::kNumber},
                   {"fitted", Kind::kText}};
  AddIntervalColumns("mean", &header);
  if (trim > 0) header.emplace_back("trimmed_mean", Kind::kNumber);
  AddIntervalColumns("versus_best", &header);
  header.emplace_back("indistinguishable", Kind::kText);
  header.emplace_back("span_lo", Kind::kNumber);
  header.emplace_back("span_hi", Kind::kNumber);
  header.emplace_back("determined", Kind::kText);
  Table table(std::move(header));
  for (const ParameterProfile& pr : profile.profiles) {
    const FitParameter& p = winner.parameters[pr.parameter];
    for (size_t k = 0; k < pr.points.size(); ++k) {
      const ProfilePoint& point = pr.points[k];
      const PairedDifference& d = point.versus_best;
      std::vector<Cell> row = {Text(p.key), Text(p.log ? "log" : "linear"), Number(point.value),
                               Text(point.fitted ? "yes" : "no")};
      AddIntervalCells(point.score.value.mean, point.score.mean, &row);
      if (trim > 0) row.push_back(Number(point.objective));
      AddIntervalCells(d.mean, d.interval, &row);
      row.push_back(Text(k == pr.best ? "best" : point.Indistinguishable() ? "yes" : "no"));
      row.push_back(Number(pr.span_lo()));
      row.push_back(Number(pr.span_hi()));
      row.push_back(Text(pr.determined ? "yes" : "no"));
      table.AddRow(row);
    }
  }
  return table;
}

// A line per profiled parameter: determined, or not, with its span.
std::string ProfileText(const Fitted& winner, const WinnerProfile& profile,
                        const std::vector<FitParameter>& parameters,
                        const ProfileRequest& request, const MeasuredData& data) {
  std::string text;
  auto out = std::back_inserter(text);
  fmt::format_to(out,
                 "profile of {} on {} ({} points per parameter and the fitted value, {}; a "
                 "point scores the same as the best when the paired 95% bootstrap interval of "
                 "its per-trajectory difference contains 0):\n",
                 winner.label, data.source, request.options.points,
                 request.options.budget > 0
                     ? fmt::format("the others re-fitted over {} evaluations at each",
                                   request.options.budget)
                     : "the others held at their fitted values");
  for (const ParameterProfile& pr : profile.profiles) {
    const FitParameter& p = winner.parameters[pr.parameter];
    const std::string unit = Unit(p);
    const std::string span = fmt::format("[{:.3g}, {:.3g}]{}", pr.span_lo(), pr.span_hi(),
                                         unit.empty() ? "" : " " + unit);
    const double best = pr.points[pr.best].value;
    const std::string at_bound = best == p.lo || best == p.hi
                                     ? fmt::format("; the best is at the range's bound {:.3g}: "
                                                   "a wider range may score better",
                                                   best)
                                     : "";
    if (pr.determined) {
      fmt::format_to(out,
                     "  {}: determined: {:.3g} {} (the values that score the same as the best, "
                     "{:.3g}){}\n",
                     p.key, winner.fit.values[pr.parameter], span, best, at_bound);
    } else {
      // how wide: decades on a log scale, the share of the range on either
      const std::string width =
          p.log ? fmt::format("{:.1f} decades", std::log10(pr.span_hi() / pr.span_lo()))
                : fmt::format("{:.0f}% of the range",
                              100 * (pr.span_hi() - pr.span_lo()) / (p.hi - p.lo));
      fmt::format_to(out,
                     "  {}: not determined by the data: any value in {} scores the same as the "
                     "best ({:.3g}): {}{}\n",
                     p.key, span, best, width, at_bound);
    }
  }
  for (size_t place : profile.unread) {
    fmt::format_to(out, "  {}: no profile: {} does not read it\n", parameters[place].key,
                   winner.label);
  }
  return text;
}

// The first contactlaw tag of the scene with the fitted values, as a line
// to paste into the scene; model parameters as comments beside it.
std::string TagLine(const Scene& scene, const Fitted& f, const ReplayOptions& options,
                    const std::vector<FitParameter>& parameters) {
  const mjModel* m = scene.model();
  std::string lines;
  for (int i = 0; i < m->ntext; ++i) {
    const std::string_view name = m->names + m->name_textadr[i];
    if (name.rfind(kPairTagPrefix, 0) != 0) continue;
    std::vector<std::pair<std::string, std::string>> keys;
    if (f.law) keys.emplace_back("law", std::string(LawName(*f.law)));
    if (f.friction) keys.emplace_back("friction", std::string(FrictionName(*f.friction)));
    const Overrides& o = options.simulation.overrides;
    if (o.restitution) keys.emplace_back("restitution", fmt::format("{}", *o.restitution));
    if (o.dissipation) keys.emplace_back("dissipation", fmt::format("{}", *o.dissipation));
    if (o.mu) keys.emplace_back("mu", fmt::format("{}", *o.mu));
    // the overrides' keys, then the fitted values; numbers to 6 digits: what
    // a scene's author writes
    for (const auto& [key, value] : o.keys) {
      const std::optional<double> v = ParseNumber(value);
      keys.emplace_back(key, v ? fmt::format("{:.6g}", *v) : value);
    }
    for (size_t k = 0; k < parameters.size(); ++k) {
      if (parameters[k].tag_key) {
        keys.emplace_back(parameters[k].key, fmt::format("{:.6g}", f.fit.values[k]));
      }
    }
    const std::string_view data = m->text_data + m->text_adr[i];
    lines += fmt::format("<text name=\"{}\" data=\"{}\"/>\n", name, WithKeys(data, keys));
    break;
  }
  for (size_t i = 0; i < parameters.size(); ++i) {
    if (parameters[i].tag_key) continue;
    lines += fmt::format("<!-- {} = {:.6g} -->\n", parameters[i].key, f.fit.values[i]);
  }
  return lines;
}

}  // namespace

FitJob::FitJob(const Scene& scene, const MeasuredData& train, const MeasuredData* validate,
               FitRequest request)
    : scene_(scene),
      train_data_(train),
      validate_data_(validate),
      request_(std::move(request)),
      train_(scene, train) {
  if (validate) validate_.emplace(scene, *validate);
  const std::vector<FitParameter>& parameters = request_.parameters;
  std::vector<bool> read_by_any(parameters.size(), false);
  for (const auto& law : request_.laws) {
    for (const auto& friction : request_.frictions) {
      Combo c;
      ReplayOptions& o = c.options;
      o = request_.base;
      if (law) o.simulation.overrides.law = law;
      if (friction) o.simulation.overrides.friction = friction;
      Fitted& f = c.fitted;
      const std::vector<bool> read = ParametersRead(scene, o, parameters);
      for (size_t i = 0; i < parameters.size(); ++i) {
        if (!read[i]) continue;
        f.parameters.push_back(parameters[i]);
        f.place.push_back(i);
        read_by_any[i] = true;
      }
      CheckFit(scene, o, f.parameters);
      if (const auto stop = request_.stop.Callback()) o.should_stop = stop;
      f.law = law;
      f.friction = friction;
      f.label = CombinationName(scene, o.simulation.overrides);
      f.combination = FirstCombination(scene, o.simulation.overrides);
      combos_.push_back(std::move(c));
    }
  }
  for (size_t i = 0; i < parameters.size(); ++i) {
    if (!read_by_any[i]) CheckFit(scene, combos_.front().options, {parameters[i]});  // refuses it
  }
  // with folds: each fold's training part and held-out part, as data
  if (request_.folds) {
    const int count = static_cast<int>(train.trajectories.size());
    fold_of_ = AssignFolds(count, *request_.folds, request_.seed);
    for (int k = 0; k < *request_.folds; ++k) {
      MeasuredData in = train, out = train;
      in.trajectories.clear();
      out.trajectories.clear();
      for (int i = 0; i < count; ++i) {
        (fold_of_[i] == k ? out : in).trajectories.push_back(train.trajectories[i]);
      }
      in.source = fmt::format("{} (fold {} left out)", train.source, k);
      out.source = fmt::format("{} (fold {})", train.source, k);
      fold_train_.push_back(std::move(in));
      fold_held_.push_back(std::move(out));
    }
  }
}

FitJob::~FitJob() = default;

FitOutcome FitJob::Run() const {
  const FitRequest& r = request_;
  const int count = static_cast<int>(train_data_.trajectories.size());
  FitOutcome outcome;
  std::vector<Fitted> fitted;
  for (const Combo& c : combos_) fitted.push_back(c.fitted);
  bool interrupted = false;
  for (size_t c = 0; c < combos_.size() && !interrupted; ++c) {
    Fitted& f = fitted[c];
    FitOptions options;
    options.replay = combos_[c].options;
    options.metric = r.metric;
    options.trim = r.trim;
    options.parameters = f.parameters;
    // the start of the parameters this combination fits
    for (size_t k = 0; k < f.place.size() && !r.initial.empty(); ++k) {
      options.initial.push_back(r.initial[f.place[k]]);
    }
    options.budget = r.budget;
    options.seed = r.seed;
    if (r.progress) {
      // the first evaluation (the start: the initial values, or the middle of each range),
      // then every 10th, and the last
      options.on_evaluation = [&](int n, double score, double best) {
        if (n == 1 || n % 10 == 0 || n == options.budget) {
          r.progress(fmt::format("fit {}: evaluation {}/{}: {:.4g} (best {:.4g})", f.label, n,
                                 options.budget, score, best));
        }
      };
    }
    // each fold left out in turn: fitted on the others, scored on it
    f.cv.assign(r.folds ? count : 0, {});
    for (int k = 0; r.folds && k < *r.folds && !interrupted; ++k) {
      const Replay part(scene_, fold_train_[k]);
      const FitResult fit = Fit(part, options);
      interrupted = fit.interrupted;
      if (interrupted) break;
      const Replay held(scene_, fold_held_[k]);
      std::vector<ReplayedTrajectory> scored =
          held.Run(WithParameters(combos_[c].options, f.parameters, fit.values));
      for (int i = 0, j = 0; i < count; ++i) {
        if (fold_of_[i] == k) f.cv[i] = std::move(scored[j++]);
      }
    }
    if (interrupted) break;  // a combination without its folds is not ranked
    f.fit = Fit(train_, options);
    interrupted = f.fit.interrupted;
    if (f.fit.values.empty()) break;  // stopped before its first evaluation
    // the best point's scores, without a stop: what is written is whole
    ReplayOptions best = WithParameters(combos_[c].options, f.parameters, f.fit.values);
    best.should_stop = nullptr;
    f.train = train_.Run(best);
    if (validate_) f.validate = validate_->Run(best);
  }
  fitted.erase(std::remove_if(fitted.begin(), fitted.end(),
                              [](const Fitted& f) { return f.fit.values.empty(); }),
               fitted.end());
  if (fitted.empty()) {
    outcome.nothing = outcome.interrupted = true;
    return outcome;
  }
  const ScoredData scored{&train_data_, validate_data_, r.folds.has_value(), r.trim};
  Rank(&fitted, r.metric, scored, r.seed);
  outcome.ranking = RankingTable(fitted, r.parameters, r.metric, scored, r.seed);
  outcome.errors = ErrorsTable(fitted, scored);
  if (r.folds) {
    outcome.folds = Table({{"trajectory", Column::Kind::kText}, {"fold", Column::Kind::kCount}});
    for (int i = 0; i < count; ++i) {
      outcome.folds.AddRow({Text(train_data_.trajectories[i].name), Count(fold_of_[i])});
    }
  }
  // the best combination's simulated trajectories, beside the data they score
  const Fitted& winner = fitted.front();
  outcome.best_tag = TagLine(scene_, winner, r.base, winner.parameters);
  {
    ReplayOptions best = r.base;
    if (winner.law) best.simulation.overrides.law = winner.law;
    if (winner.friction) best.simulation.overrides.friction = winner.friction;
    best = WithParameters(best, winner.parameters, winner.fit.values);
    best.keep_trajectories = true;
    const Replay& on = validate_ ? *validate_ : train_;
    outcome.best_trajectories = SimulatedOf(on.data(), on.Run(best));
  }
  // the winner's profile on the training data, on every rank of a job (its
  // replays are spread over them); none after a fit that was stopped
  WinnerProfile profile;
  if (r.profile && !interrupted) {
    FitOptions options;
    options.replay = r.base;
    if (winner.law) options.replay.simulation.overrides.law = winner.law;
    if (winner.friction) options.replay.simulation.overrides.friction = winner.friction;
    if (const auto stop = r.stop.Callback()) options.replay.should_stop = stop;
    options.metric = r.metric;
    options.trim = r.trim;
    options.parameters = winner.parameters;
    options.seed = r.seed;
    profile = ProfileWinner(winner, train_, options, *r.profile, r.progress);
    interrupted = profile.interrupted;
    if (!interrupted) outcome.profile = ProfileTable(winner, profile, r.trim);
  }
  outcome.profiled = r.profile && !interrupted;
  outcome.interrupted = interrupted;

  std::string& report = outcome.report;
  report = RankingText(fitted, r.parameters, r.metric, scored, r.seed);
  report += fmt::format("best ({}):\n{}", winner.label, outcome.best_tag);
  // the winner read in units, and where its bodies rest against the data
  report += fmt::format("{} on {} (95% bootstrap intervals):\n", winner.label, train_data_.source);
  report += ReadableText("  ", train_data_, winner.train, r.metric, r.seed);
  report += RestingGapsText("  ", train_data_, winner.train, r.seed);
  if (validate_data_) {
    report += fmt::format("{} on {}:\n", winner.label, validate_data_->source);
    report += ReadableText("  ", *validate_data_, winner.validate, r.metric, r.seed);
    report += RestingGapsText("  ", *validate_data_, winner.validate, r.seed);
  }
  if (outcome.profiled) {
    report += ProfileText(winner, profile, r.parameters, *r.profile, train_data_);
  }
  outcome.fitted = std::move(fitted);
  return outcome;
}

}  // namespace contactlaws::app
