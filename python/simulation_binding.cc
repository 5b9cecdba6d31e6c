// Copyright contactlaws authors.
//
// contactlaws.Simulation: a Simulation for a user's own loop. MuJoCo's state
// arrays are numpy views of its own memory (writable); the model's are
// read-only views. Stepping releases the GIL.

#include "bindings.h"

#include <memory>
#include <string>

#include "app/arena.h"
#include "app/impact_table.h"

namespace contactlaws::python {
namespace {

namespace py = pybind11;

// A view of n * width doubles at data owned by owner (kept alive by it).
py::array View(double* data, int n, int width, py::handle owner, bool writable) {
  std::vector<py::ssize_t> shape = {n};
  std::vector<py::ssize_t> strides = {static_cast<py::ssize_t>(width * sizeof(double))};
  if (width > 1) {
    shape.push_back(width);
    strides.push_back(sizeof(double));
  }
  py::array view(py::dtype::of<double>(), shape, strides, data, owner);
  if (!writable) py::detail::array_proxy(view.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return view;
}

std::vector<std::string> Names(const mjModel* m, int count, mjtObj type) {
  std::vector<std::string> names;
  for (int i = 0; i < count; ++i) {
    const char* name = mj_id2name(m, type, i);
    names.push_back(name ? name : "");
  }
  return names;
}

// Steps sim to time t (s) in steps of timestep (s), GIL released, in slices
// between which Ctrl-C is checked (it raises KeyboardInterrupt, the state
// stays at a step's end).
void AdvanceTo(Simulation* sim, double t, double timestep) {
  constexpr int kStepsPerSignalCheck = 1000;  // ~1 ms of stepping a ball
  while (sim->time() < t) {
    {
      py::gil_scoped_release release;
      for (int i = 0; i < kStepsPerSignalCheck && sim->time() < t; ++i) sim->Step(timestep);
    }
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  }
}

}  // namespace

std::unique_ptr<Simulation> MakeSimulation(const std::string& scene, const py::dict& kwargs) {
  SimulationOptions options;
  const app::OptionReader& keywords = Keywords();
  keywords.LawOverrides(OptionalText(kwargs, "law"), ValueOf(kwargs, "restitution"),
                        &options.overrides);
  keywords.FrictionOverrides(OptionalText(kwargs, "friction"), ValueOf(kwargs, "mu"),
                             &options.overrides);
  if (const auto timestep = ValueOf(kwargs, "timestep")) {
    options.timestep = keywords.Positive("timestep", *timestep, "s");
  }
  // the arena sized as the command line sizes it: reset() zeroes all of it
  return Scene(scene, app::LoadSizedModel(scene, options.overrides)).Make(options);
}

void BindSimulation(py::module_& m) {
  // a step length, read as the timestep keyword is (its message)
  m.def("_parse_timestep", [](const py::object& value) {
    py::dict kwargs;
    kwargs["timestep"] = value;
    // None too is refused by its text
    const std::optional<app::Value> timestep = ValueOf(kwargs, "timestep");
    return Keywords().Positive("timestep", timestep.value_or(app::Value("None")), "s");
  });
  py::class_<Simulation>(m, "_Simulation")
      .def(py::init([](const std::string& scene, const py::dict& overrides) {
             return MakeSimulation(scene, overrides);
           }),
           py::arg("scene"), py::arg("overrides"))
      // steps of the length the package keeps (Simulation.timestep)
      .def("_step", [](Simulation& sim, double timestep) {
             py::gil_scoped_release release;
             sim.Step(timestep);
           })
      .def("_advance", &AdvanceTo, py::arg("t"), py::arg("timestep"))
      .def("reset", [](Simulation& sim) { sim.Reset(); },
           "back to the initial state (keyframe 0 or qpos0), time 0, no impacts")
      .def_property_readonly("time", &Simulation::time, "the simulated time, s")
      // the scene's timestep, or the one given (SimulationOptions::timestep)
      .def_property_readonly("_initial_timestep",
                             [](const Simulation& sim) { return sim.model()->opt.timestep; })
      .def_property_readonly("qpos", [](py::object self) {
             Simulation& sim = self.cast<Simulation&>();
             return View(MutableData(&sim)->qpos, sim.model()->nq, 1, self, true);
           },
           "mjData.qpos, writable: the joints' positions (m, rad; a free joint: m and "
           "a unit quaternion)")
      .def_property_readonly("qvel", [](py::object self) {
             Simulation& sim = self.cast<Simulation&>();
             return View(MutableData(&sim)->qvel, sim.model()->nv, 1, self, true);
           },
           "mjData.qvel, writable: the joints' velocities (m/s, rad/s)")
      .def_property_readonly("ctrl", [](py::object self) {
             Simulation& sim = self.cast<Simulation&>();
             return View(MutableData(&sim)->ctrl, sim.model()->nu, 1, self, true);
           },
           "mjData.ctrl, writable: the actuators' controls (their units)")
      .def_property_readonly("xfrc_applied", [](py::object self) {
             Simulation& sim = self.cast<Simulation&>();
             return View(MutableData(&sim)->xfrc_applied, sim.model()->nbody, 6, self, true);
           },
           "mjData.xfrc_applied, writable (nbody x 6): force N and torque N m on each "
           "body, world frame")
      .def_property_readonly("xpos", [](py::object self) {
             Simulation& sim = self.cast<Simulation&>();
             return View(MutableData(&sim)->xpos, sim.model()->nbody, 3, self, false);
           },
           "mjData.xpos, read-only (nbody x 3): the bodies' positions, m, world frame")
      .def_property_readonly("body_mass", [](py::object self) {
             Simulation& sim = self.cast<Simulation&>();
             return View(sim.model()->body_mass, sim.model()->nbody, 1, self, false);
           },
           "mjModel.body_mass, read-only: kg")
      .def_property_readonly("geom_size", [](py::object self) {
             Simulation& sim = self.cast<Simulation&>();
             return View(sim.model()->geom_size, sim.model()->ngeom, 3, self, false);
           },
           "mjModel.geom_size, read-only (ngeom x 3): m")
      .def_property_readonly("body_names", [](const Simulation& sim) {
             return Names(sim.model(), sim.model()->nbody, mjOBJ_BODY);
           },
           "the bodies' names, in MuJoCo's order")
      .def_property_readonly("joint_names", [](const Simulation& sim) {
             return Names(sim.model(), sim.model()->njnt, mjOBJ_JOINT);
           },
           "the joints' names, in MuJoCo's order")
      .def_property_readonly("geom_names", [](const Simulation& sim) {
             return Names(sim.model(), sim.model()->ngeom, mjOBJ_GEOM);
           },
           "the geoms' names, in MuJoCo's order")
      .def("_contacts", [](const Simulation& sim) {
             // the points evaluated at the last step, as columns
             const auto& latest = sim.contacts().latest();
             const int n = static_cast<int>(latest.size());
             py::list pair;
             py::array_t<double> pos({n, 3}), normal({n, 3}), friction({n, 3});
             py::array_t<double> depth(n), depth_rate(n), force(n);
             for (int i = 0; i < n; ++i) {
               const PointEvaluation& e = latest[i];
               pair.append(sim.contact_model().tags()[e.tag].label);
               for (int k = 0; k < 3; ++k) {
                 pos.mutable_at(i, k) = e.pos[k];
                 normal.mutable_at(i, k) = e.normal[k];
                 friction.mutable_at(i, k) = e.friction[k];
               }
               depth.mutable_at(i) = e.depth;
               depth_rate.mutable_at(i) = e.depth_rate;
               force.mutable_at(i) = e.force;
             }
             py::dict columns;
             columns["pair"] = pair;
             columns["position"] = pos;
             columns["normal"] = normal;
             columns["depth"] = depth;
             columns["depth_rate"] = depth_rate;
             columns["force"] = force;
             columns["friction"] = friction;
             return columns;
           })
      .def("_impacts", [](const Simulation& sim) {
             return TableDict(app::ImpactTable(sim, sim.contacts().impacts()));
           })
      .def("energy", [](Simulation& sim) {
             mj_forward(sim.model(), MutableData(&sim));
             const EnergyLedger e = sim.Energy();
             py::dict ledger;
             ledger["kinetic"] = e.kinetic;
             ledger["potential"] = e.potential;
             ledger["elastic"] = e.elastic;
             ledger["dissipated"] = e.dissipated;
             ledger["total"] = e.total();
             return ledger;
           },
           "the energy ledger, J: kinetic, potential, elastic (stored in the contacts), "
           "dissipated (by the laws and friction), total");
}

}  // namespace contactlaws::python
