// Copyright contactlaws authors.

#include <algorithm>
#include <cstdio>

#include <fmt/format.h>

#include "cli/cluster.h"
#include "cli/arena.h"
#include "cli/commands.h"
#include "cli/identify.h"
#include "cli/impact_csv.h"
#include "cli/sweep.h"
#include "scene/number.h"
#include "scene/tags.h"

namespace contactlaws::cli {
namespace {

// One law x friction model fitted, and its scores.
struct Fitted {
  std::optional<LawId> law;
  std::optional<FrictionKind> friction;
  // the parameters its tags read, and each one's place in --params
  std::vector<FitParameter> parameters;
  std::vector<size_t> place;
  FitResult fit;
  std::vector<ReplayedTrajectory> train, validate;
  std::string label;  // "flores/coulomb"
  std::optional<Combination> combination;  // the label's law and friction; none: "mujoco"
};

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
    // --set's words, then the fitted values; numbers to 6 digits: what a
    // scene's author writes
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

// f's value of --params' parameter i, nullopt when its tags do not read it.
std::optional<double> ValueOf(const Fitted& f, size_t i) {
  for (size_t k = 0; k < f.place.size(); ++k) {
    if (f.place[k] == i) return f.fit.values[k];
  }
  return std::nullopt;
}

void PrintRanking(const std::vector<Fitted>& fitted, const std::vector<FitParameter>& parameters,
                  Metric metric, bool validated, std::FILE* out) {
  fmt::print(out, "{:<32}", "law/friction");
  for (const FitParameter& p : parameters) fmt::print(out, " {:>13}", p.key.substr(0, 13));
  fmt::print(out, " {:>11} {:>11}", "train mean", "median");
  if (validated) fmt::print(out, " {:>11} {:>11} {:>11}", "valid. mean", "median", "p90");
  fmt::print(out, " {:>6} {:>8}\n", "evals", "wall s");
  for (const Fitted& f : fitted) {
    fmt::print(out, "{:<32}", f.label + (f.fit.interrupted ? " (interrupted)" : ""));
    for (size_t i = 0; i < parameters.size(); ++i) {
      const std::optional<double> v = ValueOf(f, i);
      fmt::print(out, " {:>13}", v ? fmt::format("{:.6g}", *v) : "-");
    }
    std::vector<double> train, validate;
    for (const ReplayedTrajectory& r : f.train) train.push_back(r.score.Of(metric));
    for (const ReplayedTrajectory& r : f.validate) validate.push_back(r.score.Of(metric));
    const Distribution t = Distribute(train), v = Distribute(validate);
    fmt::print(out, " {:>11.4g} {:>11.4g}", t.mean, t.median);
    if (validated) fmt::print(out, " {:>11.4g} {:>11.4g} {:>11.4g}", v.mean, v.median, v.p90);
    fmt::print(out, " {:>6} {:>8.1f}\n", f.fit.evaluations, f.fit.wall_seconds);
  }
}

}  // namespace

int FitCommand(const FitArgs& args) {
  // the arena sized to the scene: each trajectory's mj_resetData zeroes all of it
  const Scene scene(args.scene, LoadSizedModel(args.scene, Overrides{}));
  const MeasuredData train_data = ReadData("--data", args.data);
  const Replay train(scene, train_data);
  std::optional<MeasuredData> validate_data;
  if (args.validate) validate_data = ReadData("--validate", *args.validate);
  std::optional<Replay> validate;
  if (validate_data) validate.emplace(scene, *validate_data);
  Metric metric = Metric::kEq;
  const ReplayOptions base = ParseReplayOptions(args, scene, &metric);
  const std::vector<FitParameter> parameters =
      UnderOption("--params", [&] { return ParseFitParameters(args.params, scene.model()); });
  const std::vector<std::optional<double>> initial =
      args.initial ? UnderOption("--initial",
                                 [&] {
                                   return ParseFitInitial(*args.initial, parameters, scene.model());
                                 })
                   : std::vector<std::optional<double>>();
  const std::optional<long> budget = ParseWholeNumber(args.budget, 1, 1000000);
  if (!budget) Refuse("--budget", args.budget, "must be a whole number in [1, 1000000]");
  const std::optional<long> seed = ParseWholeNumber(args.seed, 0, 4294967295L);
  if (!seed) Refuse("--seed", args.seed, "must be a whole number in [0, 4294967295]");

  // every combination, checked before any is fitted
  std::vector<std::optional<LawId>> laws = {std::nullopt};
  std::vector<std::optional<FrictionKind>> frictions = {std::nullopt};
  if (args.laws) {
    laws.clear();
    for (LawId law : ParseLawList("--laws", *args.laws)) laws.emplace_back(law);
  }
  if (args.frictions) {
    if (args.friction) Refuse("--frictions", *args.frictions, "goes without --friction");
    frictions.clear();
    for (FrictionKind f : ParseFrictionList("--frictions", *args.frictions)) frictions.emplace_back(f);
  }
  std::vector<Fitted> fitted;
  std::vector<ReplayOptions> combos;
  std::vector<bool> read_by_any(parameters.size(), false);
  for (const auto& law : laws) {
    for (const auto& friction : frictions) {
      ReplayOptions o = base;
      if (law) o.simulation.overrides.law = law;
      if (friction) o.simulation.overrides.friction = friction;
      Fitted f;
      const std::vector<bool> read = ParametersRead(scene, o, parameters);
      for (size_t i = 0; i < parameters.size(); ++i) {
        if (!read[i]) continue;
        f.parameters.push_back(parameters[i]);
        f.place.push_back(i);
        read_by_any[i] = true;
      }
      UnderOption("--params", [&] { CheckFit(scene, o, f.parameters); });
      o.should_stop = [] { return stop_signal.load(); };
      f.law = law;
      f.friction = friction;
      f.label = CombinationName(scene, o.simulation.overrides);
      f.combination = FirstCombination(scene, o.simulation.overrides);
      fitted.push_back(std::move(f));
      combos.push_back(std::move(o));
    }
  }
  for (size_t i = 0; i < parameters.size(); ++i) {
    if (read_by_any[i]) continue;
    // refuses it
    UnderOption("--params", [&] { CheckFit(scene, combos.front(), {parameters[i]}); });
  }
  const std::string dir = CreateDirectory(args.output.value_or("fit"));
  CsvFile ranking(dir + "/ranking.csv"), errors(dir + "/errors.csv");
  CsvFile best_trajectories(dir + "/best_trajectories.csv");

  bool interrupted = false;
  for (size_t c = 0; c < combos.size() && !interrupted; ++c) {
    Fitted& f = fitted[c];
    FitOptions options;
    options.replay = combos[c];
    options.metric = metric;
    options.parameters = f.parameters;
    // the start of the parameters this combination fits
    for (size_t k = 0; k < f.place.size() && !initial.empty(); ++k) {
      options.initial.push_back(initial[f.place[k]]);
    }
    options.budget = static_cast<int>(*budget);
    options.seed = static_cast<uint64_t>(*seed);
    if (!args.quiet && WritesOutputs()) {  // rank 0 of a job reports alone
      // the first evaluation (the start: --initial's values, or the middle of each range),
      // then every 10th, and the last
      options.on_evaluation = [&](int n, double score, double best) {
        if (n == 1 || n % 10 == 0 || n == options.budget) {
          fmt::print(stderr, "fit {}: evaluation {}/{}: {:.4g} (best {:.4g})\n", f.label, n,
                     options.budget, score, best);
        }
      };
    }
    f.fit = Fit(train, options);
    interrupted = f.fit.interrupted;
    if (f.fit.values.empty()) break;  // stopped before its first evaluation
    // the best point's scores, without a stop: what is written is whole
    ReplayOptions best = WithParameters(combos[c], f.parameters, f.fit.values);
    best.should_stop = nullptr;
    f.train = train.Run(best);
    if (validate) f.validate = validate->Run(best);
  }
  fitted.erase(std::remove_if(fitted.begin(), fitted.end(),
                              [](const Fitted& f) { return f.fit.values.empty(); }),
               fitted.end());
  if (fitted.empty()) {
    fmt::print(stderr, "contactlaws: interrupted before a first evaluation: no file written\n");
    return kExitInterrupted;
  }
  // ranked by the training mean: choosing by the held-out scores would fit
  // the choice to them
  auto key = [&](const Fitted& f) { return MeanScore(f.train, metric); };
  std::stable_sort(fitted.begin(), fitted.end(),
                   [&](const Fitted& a, const Fitted& b) { return key(a) < key(b); });

  std::vector<std::string> header = {"law", "friction"};
  for (const FitParameter& p : parameters) header.push_back(p.key);
  for (const char* set : {"train", "validate"}) {
    for (const char* stat : {"mean", "median", "p90"}) header.push_back(fmt::format("{}_{}", set, stat));
  }
  for (const char* column : {"evaluations", "wall_seconds", "status"}) header.emplace_back(column);
  ranking.Header(header);
  std::vector<std::string> error_header = {"law", "friction", "set"};
  for (const std::string& column : ReplayColumns()) error_header.push_back(column);
  errors.Header(error_header);
  for (const Fitted& f : fitted) {
    const std::string law(f.combination ? LawName(f.combination->law) : "mujoco");
    const std::string friction(f.combination ? FrictionName(f.combination->friction) : "");
    std::vector<std::string> row = {law, friction};
    for (size_t i = 0; i < parameters.size(); ++i) {
      const std::optional<double> v = ValueOf(f, i);
      row.push_back(v ? Field(*v) : "");
    }
    for (const auto* set : {&f.train, &f.validate}) {
      std::vector<double> values;
      for (const ReplayedTrajectory& r : *set) values.push_back(r.score.Of(metric));
      const Distribution d = Distribute(values);
      for (double v : {d.mean, d.median, d.p90}) row.push_back(set->empty() ? "" : Field(v));
    }
    row.push_back(fmt::format("{}", f.fit.evaluations));
    row.push_back(fmt::format("{:.3f}", f.fit.wall_seconds));
    row.push_back(f.fit.interrupted ? "interrupted" : "complete");
    ranking.Fields(row);
    auto write_errors = [&](const std::vector<ReplayedTrajectory>& set, const char* name,
                            const MeasuredData& data) {
      for (size_t i = 0; i < set.size(); ++i) {
        std::vector<std::string> fields = {law, friction, name};
        for (std::string& field : ReplayFields(data.trajectories[i], set[i])) {
          fields.push_back(std::move(field));
        }
        errors.Fields(fields);
      }
    };
    write_errors(f.train, "train", train_data);
    if (validate_data) write_errors(f.validate, "validate", *validate_data);
  }
  // the best combination's simulated trajectories, beside the data they score
  const Fitted& winner = fitted.front();
  const std::string tag = TagLine(scene, winner, base, winner.parameters);
  {
    ReplayOptions best = base;
    if (winner.law) best.simulation.overrides.law = winner.law;
    if (winner.friction) best.simulation.overrides.friction = winner.friction;
    best = WithParameters(best, winner.parameters, winner.fit.values);
    best.keep_trajectories = true;
    const Replay& scored = validate ? *validate : train;
    WriteSimulated(scored.data(), scored.Run(best), &best_trajectories);
    if (!WritesOutputs()) return 0;  // rank 0 of the job writes and prints
    std::FILE* file = std::fopen((dir + "/best_tag.txt").c_str(), "w");
    if (!file) throw Error(fmt::format("{}/best_tag.txt: cannot write", dir));
    std::fputs(tag.c_str(), file);
    std::fclose(file);
  }
  ranking.Commit();
  errors.Commit();
  best_trajectories.Commit();
  PrintRanking(fitted, parameters, metric, validate.has_value(), args.report);
  fmt::print(args.report, "best ({}):\n{}", winner.label, tag);
  fmt::print(args.report,
             "wrote {0}/ranking.csv, {0}/errors.csv, {0}/best_trajectories.csv, {0}/best_tag.txt\n",
             dir);
  if (interrupted) {
    fmt::print(stderr, "contactlaws: interrupted: the best result so far is written\n");
    return kExitInterrupted;
  }
  return 0;
}

}  // namespace contactlaws::cli
