// Copyright contactlaws authors.

#include <algorithm>
#include <cstdio>

#include <fmt/format.h>

#include "app/arena.h"
#include "app/score_text.h"
#include "cli/cluster.h"
#include "cli/commands.h"
#include "cli/identify.h"
#include "cli/fit_profile.h"
#include "cli/fit_ranking.h"
#include "cli/impact_csv.h"
#include "cli/rest_offsets.h"
#include "cli/sweep.h"
#include "scene/number.h"
#include "scene/tags.h"

namespace contactlaws::cli {
namespace {

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

}  // namespace

int FitCommand(const FitArgs& args) {
  // the arena sized to the scene: each trajectory's mj_resetData zeroes all of it
  const Scene scene = app::LoadReplayScene(args.scene);
  const MeasuredData train_data = DataOf(args);
  const Replay train(scene, train_data);
  std::optional<MeasuredData> validate_data;
  if (args.validate) validate_data = ReadData("--validate", *args.validate);
  std::optional<Replay> validate;
  if (validate_data) validate.emplace(scene, *validate_data);
  Metric metric = Metric::kEq;
  const ReplayOptions base = ParseReplayOptions(args, scene, &metric);
  const uint64_t seed = ParseSeed(args.seed);
  std::vector<std::string> offset_lines;  // GEOM.offset=rest: the data's estimate
  const RestOffsets rest = WithRestOffsets(args.params, scene, train_data, seed, &offset_lines);
  std::vector<FitParameter> parameters =
      UnderOption("--params", [&] { return ParseFitParameters(rest.text, scene.model()); });
  SetRestBounds(rest, &parameters);
  const std::vector<std::optional<double>> initial =
      args.initial ? UnderOption("--initial",
                                 [&] {
                                   return ParseFitInitial(*args.initial, parameters, scene.model());
                                 })
                   : std::vector<std::optional<double>>();
  const std::optional<ProfileRequest> profile_request = ParseProfile(args, parameters, seed);
  const std::optional<long> budget = ParseWholeNumber(args.budget, 1, 1000000);
  if (!budget) Refuse("--budget", args.budget, "must be a whole number in [1, 1000000]");
  const int count = static_cast<int>(train_data.trajectories.size());
  std::optional<long> folds;
  if (args.folds) {
    folds = ParseWholeNumber(*args.folds, 2, count);
    if (!folds) {
      Refuse("--folds", *args.folds,
             fmt::format("must be a whole number in [2, {}] (the trajectories of {})", count,
                         train_data.source));
    }
  }

  double trim = 0;
  if (args.trim) {
    const std::optional<double> t = ParseNumber(*args.trim);
    if (!t || !(*t >= 0 && *t < 0.5)) Refuse("--trim", *args.trim, "must be a number in [0, 0.5)");
    trim = *t;
  }

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
  std::optional<CsvFile> profile_file;
  if (profile_request) profile_file.emplace(dir + "/profile.csv");
  std::optional<CsvFile> fold_file;
  // with --folds: each fold's training part and held-out part, as data
  std::vector<int> fold_of;
  std::vector<MeasuredData> fold_train, fold_held;
  if (folds) {
    fold_of = AssignFolds(count, static_cast<int>(*folds), seed);
    fold_file.emplace(dir + "/folds.csv");
    fold_file->Header({"trajectory", "fold"});
    for (int i = 0; i < count; ++i) {
      fold_file->Fields({train_data.trajectories[i].name, fmt::format("{}", fold_of[i])});
    }
    for (int k = 0; k < *folds; ++k) {
      MeasuredData in = train_data, out = train_data;
      in.trajectories.clear();
      out.trajectories.clear();
      for (int i = 0; i < count; ++i) {
        (fold_of[i] == k ? out : in).trajectories.push_back(train_data.trajectories[i]);
      }
      in.source = fmt::format("{} (fold {} left out)", train_data.source, k);
      out.source = fmt::format("{} (fold {})", train_data.source, k);
      fold_train.push_back(std::move(in));
      fold_held.push_back(std::move(out));
    }
  }
  if (WritesOutputs()) {
    for (const std::string& line : offset_lines) fmt::print(args.report, "{}\n", line);
  }

  bool interrupted = false;
  for (size_t c = 0; c < combos.size() && !interrupted; ++c) {
    Fitted& f = fitted[c];
    FitOptions options;
    options.replay = combos[c];
    options.metric = metric;
    options.trim = trim;
    options.parameters = f.parameters;
    // the start of the parameters this combination fits
    for (size_t k = 0; k < f.place.size() && !initial.empty(); ++k) {
      options.initial.push_back(initial[f.place[k]]);
    }
    options.budget = static_cast<int>(*budget);
    options.seed = seed;
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
    // each fold left out in turn: fitted on the others, scored on it
    f.cv.assign(folds ? count : 0, {});
    for (int k = 0; folds && k < *folds && !interrupted; ++k) {
      const Replay part(scene, fold_train[k]);
      const FitResult fit = Fit(part, options);
      interrupted = fit.interrupted;
      if (interrupted) break;
      const Replay held(scene, fold_held[k]);
      std::vector<ReplayedTrajectory> scored =
          held.Run(WithParameters(combos[c], f.parameters, fit.values));
      for (int i = 0, j = 0; i < count; ++i) {
        if (fold_of[i] == k) f.cv[i] = std::move(scored[j++]);
      }
    }
    if (interrupted) break;  // a combination without its folds is not ranked
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
  const ScoredData scored{&train_data, validate_data ? &*validate_data : nullptr,
                          folds.has_value(), trim};
  Rank(&fitted, metric, scored, seed);
  WriteRanking(fitted, parameters, metric, scored, seed, &ranking, &errors);
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
    WriteSimulated(scored.data(), app::SimulatedOf(scored.data(), scored.Run(best)),
                   &best_trajectories);
  }
  // the winner's profile on the training data, on every rank of a job (its
  // replays are spread over them); none after a fit that was stopped
  WinnerProfile profile;
  if (profile_request && !interrupted) {
    FitOptions options;
    options.replay = base;
    if (winner.law) options.replay.simulation.overrides.law = winner.law;
    if (winner.friction) options.replay.simulation.overrides.friction = winner.friction;
    options.replay.should_stop = [] { return stop_signal.load(); };
    options.metric = metric;
    options.trim = trim;
    options.parameters = winner.parameters;
    options.seed = seed;
    profile = ProfileWinner(winner, train, options, *profile_request,
                            args.quiet || !WritesOutputs());
    interrupted = profile.interrupted;
    if (!interrupted) WriteProfile(winner, profile, trim, &*profile_file);
  }
  if (!WritesOutputs()) return 0;  // rank 0 of the job writes and prints
  std::FILE* file = std::fopen((dir + "/best_tag.txt").c_str(), "w");
  if (!file) throw Error(fmt::format("{}/best_tag.txt: cannot write", dir));
  std::fputs(tag.c_str(), file);
  std::fclose(file);
  ranking.Commit();
  errors.Commit();
  best_trajectories.Commit();
  if (fold_file) fold_file->Commit();
  const bool profiled = profile_request && !interrupted;
  if (profiled) profile_file->Commit();
  PrintRanking(fitted, parameters, metric, scored, seed, args.report);
  fmt::print(args.report, "best ({}):\n{}", winner.label, tag);
  // the winner read in units, and where its bodies rest against the data
  fmt::print(args.report, "{} on {} (95% bootstrap intervals):\n", winner.label, train_data.source);
  std::fputs(app::ReadableText("  ", train_data, winner.train, metric, seed).c_str(), args.report);
  std::fputs(app::RestingGapsText("  ", train_data, winner.train, seed).c_str(), args.report);
  if (validate_data) {
    fmt::print(args.report, "{} on {}:\n", winner.label, validate_data->source);
    std::fputs(app::ReadableText("  ", *validate_data, winner.validate, metric, seed).c_str(),
               args.report);
    std::fputs(app::RestingGapsText("  ", *validate_data, winner.validate, seed).c_str(),
               args.report);
  }
  if (profiled) {
    PrintProfile(winner, profile, parameters, *profile_request, train_data, args.report);
  }
  fmt::print(args.report, "wrote {0}/ranking.csv, {0}/errors.csv, {0}/best_trajectories.csv, "
             "{0}/best_tag.txt{1}{2}\n", dir, fold_file ? fmt::format(", {}/folds.csv", dir) : "",
             profiled ? fmt::format(", {}/profile.csv", dir) : "");
  if (interrupted) {
    fmt::print(stderr, "contactlaws: interrupted: the best result so far is written\n");
    return kExitInterrupted;
  }
  return 0;
}

}  // namespace contactlaws::cli
