// Copyright contactlaws authors.

#include "contactlaws/simulation.h"

#include <cmath>

#include <fmt/format.h>

#include "contactlaws/error.h"

namespace contactlaws {

Simulation::Simulation(UniqueModel model, std::string source,
                       const SimulationOptions& options)
    : model_(std::move(model)), source_(std::move(source)) {
  if (options.timestep) model_->opt.timestep = *options.timestep;
  if (options.integrator) model_->opt.integrator = *options.integrator;
  contact_model_ = std::make_unique<ContactModel>(model_.get(), source_, options.overrides);
  data_.reset(mj_makeData(model_.get()));
  if (!data_) throw Error(fmt::format("{}: MuJoCo could not allocate mjData", source_));
  contacts_ = std::make_unique<ContactData>(*contact_model_, data_.get());

  for (int b = 1; b < model_->nbody; ++b) {
    if (model_->body_jntnum[b] > 0) recorded_bodies_.push_back(b);
  }
  for (const Drive& drive : contact_model_->drives()) recorded_bodies_.push_back(drive.body);
  Reset();
}

void Simulation::Reset() {
  if (model_->nkey > 0) {
    mj_resetDataKeyframe(model_.get(), data_.get(), 0);
  } else {
    mj_resetData(model_.get(), data_.get());
  }
  contacts_->Reset();
  for (const Drive& drive : contact_model_->drives()) {
    drive.Position(data_->time, data_->mocap_pos + 3 * drive.mocap);
  }
}

std::vector<std::string> Simulation::Columns() const {
  std::vector<std::string> columns = {"time"};
  for (int b : recorded_bodies_) {
    for (const char* q : {"x", "y", "z", "vx", "vy", "vz"}) {
      columns.push_back(fmt::format("{}.{}", ObjectName(model_.get(), mjOBJ_BODY, b), q));
    }
  }
  for (const PairTag& tag : contact_model_->tags()) {
    for (const char* q : {"depth", "depth_rate", "force"}) {
      columns.push_back(fmt::format("{}.{}", tag.label, q));
    }
  }
  for (const char* q : {"kinetic", "potential", "elastic", "dissipated", "total"}) {
    columns.push_back(fmt::format("energy.{}", q));
  }
  return columns;
}

EnergyLedger Simulation::Energy() const {
  const mjModel* m = model_.get();
  mjData* d = data_.get();
  EnergyLedger e;

  // kinetic: 1/2 qvel^T M qvel
  const int mark = d->pstack;
  mjtNum* mv = mj_stackAlloc(d, m->nv);
  mj_mulM(m, d, mv, d->qvel);
  e.kinetic = 0.5 * mju_dot(d->qvel, mv, m->nv);
  d->pstack = mark;

  // potential: the weight of the bodies that move through dofs (static and
  // driven bodies are not part of the simulated system) ...
  if (!(m->opt.disableflags & mjDSBL_GRAVITY)) {
    for (int b = 1; b < m->nbody; ++b) {
      if (m->body_weldid[b] != 0) {
        e.potential -= m->body_mass[b] * mju_dot3(m->opt.gravity, d->xipos + 3 * b);
      }
    }
  }
  // ... and the springs of slide and hinge joints
  for (int j = 0; j < m->njnt; ++j) {
    const int type = m->jnt_type[j];
    if (m->jnt_stiffness[j] > 0 && (type == mjJNT_SLIDE || type == mjJNT_HINGE)) {
      const int adr = m->jnt_qposadr[j];
      const double stretch = d->qpos[adr] - m->qpos_spring[adr];
      e.potential += 0.5 * m->jnt_stiffness[j] * stretch * stretch;
    }
  }

  e.elastic = contacts_->ElasticEnergy();
  e.dissipated = contacts_->DissipatedEnergy();
  return e;
}

void Simulation::Sample(std::vector<double>* row) {
  const mjModel* m = model_.get();
  mjData* d = data_.get();
  mj_forward(m, d);
  row->clear();
  // d->time accumulates timesteps: show it to the nanosecond
  row->push_back(std::round(d->time * 1e9) / 1e9);
  for (int b : recorded_bodies_) {
    mjtNum vel[3];
    contacts_->PointVelocity(b, d->xpos + 3 * b, vel);
    for (int k = 0; k < 3; ++k) row->push_back(d->xpos[3 * b + k]);
    for (int k = 0; k < 3; ++k) row->push_back(vel[k]);
  }
  for (int t = 0; t < static_cast<int>(contact_model_->tags().size()); ++t) {
    const TagReading r = contacts_->Reading(t);
    row->push_back(r.depth);
    row->push_back(r.depth_rate);
    row->push_back(r.force);
  }
  const EnergyLedger e = Energy();
  for (double v : {e.kinetic, e.potential, e.elastic, e.dissipated, e.total()}) {
    row->push_back(v);
  }
}

bool Simulation::Undriven() const {
  return contact_model_->drives().empty() && model_->nu == 0;
}

std::vector<MujocoWarning> Simulation::Warnings() const {
  std::vector<MujocoWarning> warnings;
  for (int i = 0; i < mjNWARNING; ++i) {
    const mjWarningStat& w = data_->warning[i];
    if (w.number > 0) warnings.push_back({mju_warningText(i, w.lastinfo), w.number});
  }
  return warnings;
}

Scene::Scene(std::string path) : path_(std::move(path)), model_(LoadModelFile(path_)) {}

Scene::Scene(std::string name, UniqueModel model)
    : path_(std::move(name)), model_(std::move(model)) {}

std::unique_ptr<Simulation> Scene::Make(const SimulationOptions& options) const {
  UniqueModel copy(mj_copyModel(nullptr, model_.get()));
  if (!copy) throw Error(fmt::format("{}: MuJoCo could not copy the model", path_));
  return std::make_unique<Simulation>(std::move(copy), path_, options);
}

}  // namespace contactlaws
