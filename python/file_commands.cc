// Copyright contactlaws authors.
//
// compare, restitution, replay, fit, laws and check as functions. replay:
// the keywords parsed as the command line's options, the library's replay
// job (app/replay_job.h), its result columns handed over as arrays. The
// others: the command line's own commands (src/cli), given the keywords as
// their options, their CSV files written into a folder the package reads
// back as DataFrames, and their printed report kept as text. The work runs
// on a thread of its own while the caller watches for Ctrl-C.

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <future>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include "app/check_job.h"
#include "app/identify_options.h"
#include "app/law_tables.h"
#include "app/replay_job.h"
#include "bindings.h"
#include "cli/commands.h"
#include "cli/identify.h"
#include "cli/sweep.h"

namespace contactlaws::python {
namespace {

namespace py = pybind11;

// The keyword key's text into field (absent or None: the command's default).
void Take(const py::dict& kwargs, const char* key, std::optional<std::string>* field) {
  if (auto v = OptionalText(kwargs, key)) *field = *v;
}
void Take(const py::dict& kwargs, const char* key, std::string* field) {
  if (auto v = OptionalText(kwargs, key)) *field = *v;
}

// A flag keyword: True or False (absent or None: false).
bool Flag(const py::dict& kwargs, const char* key) {
  if (!kwargs.contains(key) || kwargs[key].is_none()) return false;
  if (!py::isinstance<py::bool_>(kwargs[key])) {
    throw py::type_error(std::string(key) + " must be True or False");
  }
  return kwargs[key].cast<bool>();
}

}  // namespace

void TakeCommon(const py::dict& kwargs, cli::CommonArgs* args) {
  Take(kwargs, "duration", &args->duration);
  Take(kwargs, "sample_rate", &args->sample_rate);
  Take(kwargs, "timestep", &args->timestep);
  Take(kwargs, "max_timestep", &args->max_timestep);
  Take(kwargs, "accuracy", &args->accuracy);
  Take(kwargs, "integrator", &args->integrator);
  Take(kwargs, "columns", &args->columns);
  Take(kwargs, "dissipation", &args->dissipation);
  Take(kwargs, "friction", &args->friction);
  Take(kwargs, "mu", &args->mu);
  args->settle = Flag(kwargs, "settle");
}

namespace {

cli::SweepArgs SweepArgsOf(const std::string& scene, const py::dict& kwargs) {
  cli::SweepArgs args;
  args.scene = scene;
  TakeCommon(kwargs, &args);
  Take(kwargs, "laws", &args.laws);
  Take(kwargs, "restitution", &args.restitution);
  Take(kwargs, "frictions", &args.frictions);
  Take(kwargs, "jobs", &args.jobs);
  args.impacts_per_point = Flag(kwargs, "impacts_per_point");
  args.quiet = true;  // no progress line on the caller's stderr
  return args;
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

// What a command prints, kept in memory (a POSIX memory stream).
class Report {
 public:
  Report() : file_(open_memstream(&buffer_, &size_)) {
    if (!file_) throw std::runtime_error("contactlaws: cannot open a memory stream");
  }
  ~Report() {
    std::fclose(file_);
    std::free(buffer_);
  }
  Report(const Report&) = delete;
  Report& operator=(const Report&) = delete;

  std::FILE* file() { return file_; }
  std::string Text() {
    std::fflush(file_);
    return std::string(buffer_, size_);
  }

 private:
  char* buffer_ = nullptr;
  size_t size_ = 0;
  std::FILE* file_;
};

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

// A command of the command line, stopped through its program-wide flag.
int InterruptibleCommand(const std::function<int()>& command) {
  struct Clear {
    ~Clear() { cli::stop_signal = false; }
  } clear;
  return Interruptible(command, &cli::stop_signal);
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

// (exit status, printed report) of command given args with report.
template <typename Args>
py::tuple Call(int (*command)(const Args&), Args args) {
  Report report;
  args.report = report.file();
  const int status = InterruptibleCommand([&] { return command(args); });
  return py::make_tuple(status, report.Text());
}

// compare's results as columns: {"trajectories", "impacts", "summary":
// tables (the columns of its three files), "report": the printed table,
// "status": the command line's exit status}. No file written.
py::dict Compare(const std::string& scene, const py::dict& kwargs) {
  using Kind = app::Column::Kind;
  const cli::SweepArgs args = SweepArgsOf(scene, kwargs);
  cli::ComparePlan plan = cli::PlanCompare(args);
  std::atomic<bool> stop{false};
  plan.sweep.keep_numbers = true;
  plan.sweep.advance.stop = &stop;
  // each file's first columns: law, restitution, and friction when the runs
  // compare friction models
  std::vector<std::pair<std::string, Kind>> run = {{"law", Kind::kText},
                                                   {"restitution", Kind::kNumber}};
  if (plan.frictions) run.emplace_back("friction", Kind::kText);
  const std::vector<std::string> columns = plan.first->Columns();
  std::vector<std::pair<std::string, Kind>> header = run;
  for (const std::string& c : columns) header.emplace_back(c, Kind::kNumber);
  app::Table trajectories(header);
  header = run;
  for (const std::string& c : cli::SummaryColumns()) {
    header.emplace_back(c, c == "status" || c == "reason" ? Kind::kText
                           : c == "impacts"               ? Kind::kCount
                                                          : Kind::kNumber);
  }
  app::Table summary(header);
  header.clear();
  const app::Table no_impacts = app::ImpactTable(*plan.first, {});
  for (const app::Column& c : no_impacts.columns()) {
    header.emplace_back(c.name, c.kind);
  }
  if (plan.frictions) header.emplace(header.begin() + 2, "friction", Kind::kText);
  app::Table impacts(header);

  std::vector<cli::CompareRow> rows;
  auto deliver = [&](int k, cli::RunOutput& out) {
    const cli::RunSpec& spec = plan.specs[k];
      std::vector<app::Cell> prefix = {
        app::Text(std::string(LawName(spec.law))),
        out.restitution ? app::Number(*out.restitution) : app::Unknown()};
    if (plan.frictions) prefix.push_back(app::Text(std::string(FrictionName(*spec.friction))));
    const bool rows_valid = out.status == cli::RunOutput::Status::kOk ||
                            out.status == cli::RunOutput::Status::kFailed;
    if (rows_valid) {
      // a failed run's rows up to its divergence are valid; an interrupted
      // run's are not kept
      for (size_t at = 0; at + columns.size() <= out.rows.size(); at += columns.size()) {
        std::vector<app::Cell> cells = prefix;
        for (size_t c = 0; c < columns.size(); ++c) cells.push_back(app::Number(out.rows[at + c]));
        trajectories.AddRow(cells);
      }
      const app::Table& log = out.impact_table;
      for (size_t i = 0; i < log.rows(); ++i) {
        std::vector<app::Cell> cells;
        for (const app::Column& c : log.columns()) {
          cells.push_back(c.kind == Kind::kText ? app::Text(c.text[i])
                                                : app::Cell{c.kind, c.numbers[i], {}});
        }
        if (plan.frictions) cells.emplace(cells.begin() + 2, prefix[2]);
        impacts.AddRow(cells);
      }
    }
    std::vector<app::Cell> cells = prefix;
    const RunSummary& r = out.summary;
    auto known = [](const std::optional<double>& v) {
      return v ? app::Number(*v) : app::Unknown();
    };
    if (out.status == cli::RunOutput::Status::kOk) {
      for (app::Cell c : {app::Count(r.impacts), known(r.restitution_post),
                          app::Number(r.max_depth), app::Number(r.max_force),
                          known(r.contact_duration), known(r.time_to_rest),
                          app::Number(out.dissipated), app::Text("ok"), app::Text("")}) {
        cells.push_back(std::move(c));
      }
    } else {
      // a failed run's numbers are not to be trusted: only its status
      for (int i = 0; i < 7; ++i) cells.push_back(app::Unknown());
      cells.push_back(app::Text(cli::StatusName(out.status)));
      cells.push_back(app::Text(out.reason));
    }
    summary.AddRow(cells);
    rows.push_back({spec, out.status, out.restitution, out.summary, out.dissipated});
    out.rows.clear();  // a delivered run's numbers are in the tables
  };
  const int status = Interruptible(
      [&] {
        return cli::Sweep(*plan.in.scene, plan.in.common.simulation, plan.specs, plan.advices,
                          plan.sweep, deliver);
      },
      &stop);
  py::dict out;
  out["trajectories"] = TableDict(trajectories);
  out["impacts"] = TableDict(impacts);
  out["summary"] = TableDict(summary);
  out["report"] = cli::CompareTableText(rows, plan.frictions);
  out["status"] = status;
  return out;
}

py::tuple Restitution(const std::string& scene, const py::dict& kwargs, const std::string& path) {
  cli::SweepArgs args = SweepArgsOf(scene, kwargs);
  args.output = path;
  return Call(&cli::RestitutionCommand, std::move(args));
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

void BindFileCommands(py::module_& m) {
  m.def("_compare", &Compare);
  m.def("_restitution", &Restitution);
  m.def("_replay", &Replay);
  m.def("_fit", &Fit);
  m.def("_check", &Check);
  m.def("_laws", &LawTables);
}

}  // namespace contactlaws::python
