// Copyright contactlaws authors.
//
// compare, restitution, replay, fit, laws and check as functions: the
// keywords read by the application's option grammar (app/options.h), the
// application's jobs run (src/app), their result columns handed over as
// arrays. No file written, nothing read back. The work runs on a thread of
// its own while the caller watches for Ctrl-C.

#include <atomic>
#include <chrono>
#include <cstdio>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "app/check_job.h"
#include "app/compare_job.h"
#include "app/identify_options.h"
#include "app/law_tables.h"
#include "app/replay_job.h"
#include "app/restitution_job.h"
#include "app/run_warnings.h"
#include "bindings.h"
#include "ident/work_spread.h"

namespace contactlaws::python {
namespace {

namespace py = pybind11;

// What a sweep says, on stderr as the command line prints it, the
// library's advice (sim/) spelled with the keywords (KeywordSpelling).
class StderrMonitor : public app::SweepMonitor {
 public:
  void Warn(const std::string& scene, const std::string& what) override {
    std::fprintf(stderr, "contactlaws: warning: %s: %s\n", scene.c_str(),
                 KeywordSpelling(what).c_str());
  }
  void TagWarning(const std::string& what) override {
    std::fprintf(stderr, "contactlaws: warning: %s\n", what.c_str());
  }
  void Note(const std::string& scene, const std::string& what) override {
    std::fprintf(stderr, "contactlaws: %s: %s\n", scene.c_str(), what.c_str());
  }
  void RunFailed(const std::string& scene, const std::string& run,
                 const std::string& reason) override {
    std::fprintf(stderr, "contactlaws: %s: %s: run failed: %s\n", scene.c_str(), run.c_str(),
                 KeywordSpelling(reason).c_str());
  }
};

// compare's and restitution's keywords.
app::SweepInput SweepInputOf(const py::dict& kwargs) {
  app::SweepInput input;
  static_cast<app::CommonInput&>(input) = CommonInputOf(kwargs);
  if (auto v = OptionalText(kwargs, "laws")) input.laws = *v;
  input.restitution = ValueOf(kwargs, "restitution");
  input.frictions = OptionalText(kwargs, "frictions");
  input.jobs = ValueOf(kwargs, "jobs");
  return input;
}

// A table's columns as the Python side hands them over: {"source": str,
// "trajectory": [str], "time": float64 array, "columns": [str], "values":
// [float64 array]} (contactlaws._data), checked as a file is.
MeasuredData MeasuredOf(const py::dict& table) {
  const auto doubles = [](const py::handle& h) {
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(h);
    if (!a || a.ndim() != 1) throw py::type_error("data: a column is not a 1-D array of numbers");
    return std::vector<double>(a.data(), a.data() + a.size());
  };
  std::vector<std::vector<double>> values;
  for (const py::handle column : table["values"]) values.push_back(doubles(column));
  return MeasuredFromColumns(table["trajectory"].cast<std::vector<std::string>>(),
                             doubles(table["time"]),
                             table["columns"].cast<std::vector<std::string>>(), values,
                             table["source"].cast<std::string>());
}

// data: a path (read as a file is), or a table (MeasuredOf).
MeasuredData DataOf(const py::dict& kwargs, const char* key) {
  if (kwargs.contains(key) && py::isinstance<py::dict>(kwargs[key])) {
    return MeasuredOf(kwargs[key].cast<py::dict>());
  }
  return app::ReadData(Keywords(), key, OptionalText(kwargs, key).value_or(""));
}

// replay's keywords (fit's too) into input.
void TakeReplay(const py::dict& kwargs, app::ReplayInput* input) {
  static_cast<app::CommonInput&>(*input) = CommonInputOf(kwargs);
  if (auto v = OptionalText(kwargs, "start")) input->start = *v;
  input->refit_height = ValueOf(kwargs, "refit_height");
  if (auto v = ValueOf(kwargs, "refit_lead")) input->refit_lead = *v;
  if (auto v = ValueOf(kwargs, "refit_min_samples")) input->refit_min_samples = *v;
  if (auto v = OptionalText(kwargs, "metric")) input->metric = *v;
  input->weights = OptionalText(kwargs, "weights");
  input->length = ValueOf(kwargs, "length");
  input->law = OptionalText(kwargs, "law");
  input->restitution = ValueOf(kwargs, "restitution");
  input->jobs = ValueOf(kwargs, "jobs");
  if (kwargs.contains("set") && !kwargs["set"].is_none()) {
    for (const py::handle item : kwargs["set"]) input->set.push_back(py::str(item));
  }
  if (auto v = ValueOf(kwargs, "seed")) input->seed = *v;
}

// Runs work on a thread of its own with the GIL released. The calling
// thread checks for Ctrl-C meanwhile: on it, *stop is set, which makes the
// runs stop after their current step (what the command line does on
// SIGINT), and KeyboardInterrupt is raised once work has returned. Work's
// exceptions propagate.
template <typename Work>
auto Interruptible(const Work& work, std::atomic<bool>* stop) -> decltype(work()) {
  std::packaged_task<decltype(work())()> task(work);
  auto done = task.get_future();
  bool interrupted = false;
  {
    py::gil_scoped_release release;
    std::thread worker(std::move(task));
    constexpr auto kSignalCheck = std::chrono::milliseconds(20);  // Ctrl-C felt at once
    while (done.wait_for(kSignalCheck) != std::future_status::ready) {
      if (interrupted) continue;
      py::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) {
        interrupted = true;
        *stop = true;
      }
    }
    worker.join();
  }
  if (interrupted) throw py::error_already_set();  // the KeyboardInterrupt raised
  return done.get();
}

// Simulated samples of data's trajectories: {"names": every trajectory's
// name, "trajectory": each row's index into names, "time": s, "columns":
// the data's, "values": a rows x columns array}.
py::dict SimulatedColumns(const MeasuredData& data, const app::SimulatedSamples& samples) {
  std::vector<std::string> names;
  for (const MeasuredTrajectory& t : data.trajectories) names.push_back(t.name);
  const auto width = static_cast<py::ssize_t>(samples.columns.size());
  const auto rows = static_cast<py::ssize_t>(samples.time.size());
  py::dict out;
  out["names"] = names;
  out["trajectory"] =
      Array(std::vector<int64_t>(samples.trajectory.begin(), samples.trajectory.end()));
  out["time"] = Array(samples.time);
  out["columns"] = samples.columns;
  out["values"] = py::array_t<double>({rows, width}, samples.values.data());
  return out;
}

// compare's results as columns: {"trajectories", "impacts", "summary":
// tables (the columns of its three files), "report": the printed table,
// "failed": whether a run failed}. No file written.
py::dict Compare(const std::string& scene, const py::dict& kwargs) {
  StderrMonitor monitor;
  app::ComparePlan plan = app::PlanCompare(Keywords(), scene, SweepInputOf(kwargs),
                                           Switch(kwargs, "impacts_per_point"), &monitor);
  std::atomic<bool> stop{false};
  plan.sweep.keep_numbers = true;
  plan.sweep.advance.stop = &stop;
  app::CompareTables tables(plan);
  const app::SweepStatus status = Interruptible(
      [&] {
        return app::Sweep(*plan.in.scene, plan.in.common.simulation, plan.specs, plan.advices,
                          plan.sweep, Keywords(), &monitor,
                          [&](int k, app::RunOutput& out) { tables.Add(plan.specs[k], out); });
      },
      &stop);
  py::dict out;
  out["trajectories"] = TableDict(tables.trajectories());
  out["impacts"] = TableDict(tables.impacts());
  out["summary"] = TableDict(tables.summary());
  out["report"] = app::CompareTableText(tables.rows(), plan.frictions);
  out["failed"] = status == app::SweepStatus::kFailed;
  return out;
}

// restitution's results: {"table": its columns, "incomplete": whether a run
// failed or a first contact did not end}. No file written.
py::dict Restitution(const std::string& scene, const py::dict& kwargs) {
  StderrMonitor monitor;
  app::RestitutionPlan plan =
      app::PlanRestitution(Keywords(), scene, SweepInputOf(kwargs), &monitor);
  std::atomic<bool> stop{false};
  plan.sweep.advance.stop = &stop;
  const app::RestitutionResult result =
      Interruptible([&] { return app::RunRestitution(plan, Keywords(), &monitor); }, &stop);
  py::dict out;
  out["table"] = TableDict(result.table);
  out["incomplete"] = result.status == app::SweepStatus::kFailed || result.incomplete > 0;
  return out;
}

// replay's results as columns: {"scores": TableColumns, "simulated":
// SimulatedColumns, "report", "diverged", "settled": text}. No file
// written, nothing printed.
py::dict Replay(const std::string& scene_path, const py::dict& kwargs) {
  app::ReplayInput input;
  TakeReplay(kwargs, &input);
  const Scene scene = app::LoadReplayScene(scene_path);
  const MeasuredData data = DataOf(kwargs, "data");
  app::ReplayRequest request;
  request.options = app::ReadReplayOptions(Keywords(), input, scene, &request.metric);
  request.seed = app::ReadSeed(Keywords(), input.seed);
  request.keep_trajectories = true;
  std::atomic<bool> stop{false};
  request.stop = app::StopToken(&stop);
  const app::ReplayJob job(scene, data, std::move(request));
  const app::ReplayResult result = Interruptible([&] { return job.Run(); }, &stop);

  py::dict out;
  out["scores"] = TableDict(app::ScoresTable(result.scores));
  out["simulated"] = SimulatedColumns(data, result.simulated);
  out["report"] = result.report;
  out["diverged"] = KeywordSpelling(result.diverged);  // the library's advice names flags
  out["settled"] = result.settled;
  return out;
}

// fit's results as columns: {"ranking", "errors", "folds", "profile":
// tables (TableColumns; folds and profile None when not asked),
// "best_trajectories": SimulatedColumns, "best_tag", "report": text}. No
// file written, nothing printed; Ctrl-C raises KeyboardInterrupt.
py::dict Fit(const std::string& scene_path, const py::dict& kwargs) {
  app::FitInput input;
  TakeReplay(kwargs, &input);
  if (auto v = OptionalText(kwargs, "params")) input.params = *v;
  input.initial = OptionalText(kwargs, "initial");
  input.laws = OptionalText(kwargs, "laws");
  input.frictions = OptionalText(kwargs, "frictions");
  if (auto v = ValueOf(kwargs, "budget")) input.budget = *v;
  input.folds = ValueOf(kwargs, "folds");
  input.trim = ValueOf(kwargs, "trim");
  input.profile = OptionalText(kwargs, "profile");
  input.profile_points = ValueOf(kwargs, "profile_points");
  input.profile_budget = ValueOf(kwargs, "profile_budget");
  const Scene scene = app::LoadReplayScene(scene_path);
  const MeasuredData train = DataOf(kwargs, "data");
  std::optional<MeasuredData> validate;
  if (kwargs.contains("validate") && !kwargs["validate"].is_none()) {
    validate = DataOf(kwargs, "validate");
  }
  std::vector<std::string> offset_lines;
  app::FitRequest request =
      app::ReadFitRequest(Keywords(), input, scene, train, &offset_lines);
  std::atomic<bool> stop{false};
  request.stop = app::StopToken(&stop);
  const app::FitJob job = app::CheckedFitJob(Keywords(), scene, train,
                                             validate ? &*validate : nullptr, std::move(request));
  const app::FitOutcome outcome = Interruptible([&] { return job.Run(); }, &stop);
  // stopped before a first evaluation: only by Ctrl-C, raised above
  if (outcome.nothing) throw Error("fit: stopped before a first evaluation");
  std::string report;
  for (const std::string& line : offset_lines) report += line + "\n";
  py::dict out;
  out["ranking"] = TableDict(outcome.ranking);
  out["errors"] = TableDict(outcome.errors);
  out["folds"] = input.folds ? py::object(TableDict(outcome.folds)) : py::none();
  out["profile"] = outcome.profiled ? py::object(TableDict(outcome.profile)) : py::none();
  out["best_trajectories"] =
      SimulatedColumns(validate ? *validate : train, outcome.best_trajectories);
  out["best_tag"] = outcome.best_tag;
  out["report"] = report + outcome.report;
  return out;
}

// check's report (its options named as the keywords); the tags' warnings
// on stderr, as the command line prints them.
std::string Check(const std::string& scene_path, const py::dict& kwargs) {
  app::CheckInput input;
  input.law = OptionalText(kwargs, "law");
  input.restitution = ValueOf(kwargs, "restitution");
  input.dissipation = ValueOf(kwargs, "dissipation");
  input.friction = OptionalText(kwargs, "friction");
  input.mu = ValueOf(kwargs, "mu");
  input.timestep = ValueOf(kwargs, "timestep");
  input.accuracy = ValueOf(kwargs, "accuracy");
  input.impact_velocity = ValueOf(kwargs, "impact_velocity");
  const app::CheckRequest request = app::ReadCheck(Keywords(), input);
  const Scene scene(scene_path);
  std::unique_ptr<Simulation> sim = scene.Make(request.options);
  for (const std::string& w : app::TagWarnings(sim->contact_model())) {
    std::fprintf(stderr, "contactlaws: warning: %s\n", w.c_str());
  }
  return app::Check(sim.get(), request, Keywords()).text;
}

// The law and friction tables, and each law's a(e) and rebound per
// restitution (`laws --format csv`): {"laws", "frictions", "effective"},
// each a table's columns.
py::dict LawTables(const py::dict& kwargs) {
  const std::vector<double> restitutions = Keywords().RestitutionList(
      "restitution", ValueOf(kwargs, "restitution").value_or(app::kDefaultRestitutions));
  py::dict out;
  out["laws"] = TableDict(app::LawTable());
  out["frictions"] = TableDict(app::FrictionTable());
  out["effective"] = TableDict(app::EffectiveRestitutionTable(restitutions));
  return out;
}

}  // namespace

void BindJobs(py::module_& m) {
  m.def("_compare", &Compare);
  m.def("_restitution", &Restitution);
  m.def("_replay", &Replay);
  m.def("_fit", &Fit);
  m.def("_check", &Check);
  m.def("_laws", &LawTables);
  // the cluster's plan of items over processes, for bench/mpi_projection.py
  m.def("_longest_first", &internal::LongestFirst, py::arg("seconds"), py::arg("processes"));
}

}  // namespace contactlaws::python
