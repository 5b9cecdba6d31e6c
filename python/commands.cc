// Copyright contactlaws authors.
//
// run as a function: the application's option grammar (app/options.h, its
// messages naming the keywords) and the library's Advance, with the results
// kept in memory.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"
#include "app/arena.h"
#include "app/impact_table.h"
#include "app/run_warnings.h"
#include "sim/start_contact.h"
#include "sim/summary.h"
#include "sim/timestep_advice.h"

namespace contactlaws::python {
namespace {

namespace py = pybind11;

// Thrown out of Advance's row callback when Ctrl-C arrived (Python's error
// indicator is set: KeyboardInterrupt follows).
struct Interrupted {};

// The table run prints: one row per tag.
py::list SummaryRows(const Simulation& sim, double end_time) {
  const ContactModel& cm = sim.contact_model();
  py::list rows;
  for (int t = 0; t < static_cast<int>(cm.tags().size()); ++t) {
    const PairTag& tag = cm.tags()[t];
    const RunSummary s = SummarizeTag(sim, t, end_time);
    py::object restitution = py::none();
    if (ReadsRestitution(tag.law)) restitution = py::float_(tag.restitution);
    rows.append(py::make_tuple(tag.label, std::string(LawName(tag.law)), restitution, s.impacts,
                               s.restitution_post ? py::object(py::float_(*s.restitution_post))
                                                  : py::object(py::none()),
                               s.max_force));
  }
  return rows;
}

// contactlaws run: (columns, rows as an n x columns array, impact columns,
// impact rows as text fields, summary rows, warnings, divergence message).
py::tuple Run(const std::string& scene_path, const py::dict& kwargs) {
  const app::CommonOptions common = Keywords().Common(CommonInputOf(kwargs));
  SimulationOptions options = common.simulation;
  Keywords().LawOverrides(OptionalText(kwargs, "law"), ValueOf(kwargs, "restitution"),
                          &options.overrides);
  // the arena sized as the command line sizes it (the same work per step)
  const Scene scene(scene_path, app::LoadSizedModel(scene_path, options.overrides));
  std::unique_ptr<Simulation> sim = scene.Make(options);
  // a start deep in contact, whatever the step; a fixed step's own
  const std::vector<StartContact> starts = StartContacts(sim.get());
  std::vector<std::string> warnings = DeepStartWarnings(*sim, starts, kKeywordSpelling);
  const std::vector<TimestepAdvice> advice = AdviseTimestep(sim.get(), starts);
  if (!common.auto_timestep) {
    for (std::string& w : TimestepWarnings(*sim, advice, kKeywordSpelling)) warnings.push_back(std::move(w));
  }

  const std::vector<std::string> columns = sim->Columns();
  auto values = std::make_unique<std::vector<double>>();
  AdvanceOptions advance;
  advance.duration = common.duration;
  advance.sample_rate = common.sample_rate;
  advance.auto_timestep = common.auto_timestep;
  AdvanceResult result;
  {
    // stepping without the GIL; every kRowsPerSignalCheck rows, Ctrl-C?
    constexpr long kRowsPerSignalCheck = 256;
    long rows = 0;
    py::gil_scoped_release release;
    try {
      result = Advance(sim.get(), advance, [&](const std::vector<double>& row) {
        values->insert(values->end(), row.begin(), row.end());
        if (++rows % kRowsPerSignalCheck != 0) return;
        py::gil_scoped_acquire acquire;
        if (PyErr_CheckSignals() != 0) throw Interrupted{};
      });
    } catch (const Interrupted&) {
      py::gil_scoped_acquire acquire;
      throw py::error_already_set();
    }
  }
  for (std::string& w : app::RunWarnings(*sim, result, Keywords())) {
    warnings.push_back(std::move(w));
  }
  // a settled body with no resting pose rolls or tips from the start: the
  // command line's settled line says so on its own, Python hears it
  if (sim->settled() && !sim->settled()->unheld.empty()) warnings.push_back(sim->settled()->Line());
  const double end_time = result.divergence ? result.divergence->time : sim->time();
  std::string divergence;
  if (result.divergence) divergence = DivergenceMessage(*sim, *result.divergence, advice, kKeywordSpelling);
  // the library's advice (sim/) names the command line's flags
  for (std::string& w : warnings) w = KeywordSpelling(w);
  divergence = KeywordSpelling(divergence);

  // the rows as an array that owns the vector
  const py::ssize_t width = static_cast<py::ssize_t>(columns.size());
  const py::ssize_t n = static_cast<py::ssize_t>(values->size()) / width;
  std::vector<double>* owned = values.release();
  py::capsule free_rows(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  py::array_t<double> trajectory({n, width}, owned->data(), free_rows);

  const py::dict impacts = TableDict(app::ImpactTable(*sim, sim->contacts().impacts()));
  return py::make_tuple(columns, trajectory, impacts,
                        SummaryRows(*sim, end_time), warnings, divergence);
}

}  // namespace

void BindCommands(py::module_& m) {
  m.def("_run", &Run, py::arg("scene"), py::arg("options"));
}

}  // namespace contactlaws::python
