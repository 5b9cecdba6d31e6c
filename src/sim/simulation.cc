// Copyright contactlaws authors.

#include "contactlaws/simulation.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <utility>

#include <fmt/format.h>

#include "contactlaws/contact_model.h"
#include "mujoco/kinematics.h"
#include "scene/parsed_tags.h"
#include "sim/settle.h"

namespace contactlaws {

namespace {

// No step of m makes a constraint row: MuJoCo's solver never runs, so the
// warm start it keeps between calls (qacc_warmstart) is never read.
bool WithoutConstraints(const mjModel* m) {
  if (m->opt.disableflags & mjDSBL_CONSTRAINT) return true;
  if (!(m->opt.disableflags & mjDSBL_CONTACT) || m->neq > 0) return false;
  for (int j = 0; j < m->njnt; ++j) {
    if (m->jnt_limited[j]) return false;
  }
  for (int v = 0; v < m->nv; ++v) {
    if (m->dof_frictionloss[v] > 0) return false;
  }
  for (int t = 0; t < m->ntendon; ++t) {
    if (m->tendon_limited[t] || m->tendon_frictionloss[t] > 0) return false;
  }
  return true;
}

}  // namespace

Simulation::Simulation(std::shared_ptr<const mjModel> model, std::string source,
                       const SimulationOptions& options)
    : Simulation(std::move(model), std::move(source), options, nullptr) {}

Simulation::Simulation(std::shared_ptr<const mjModel> model, std::string source,
                       const SimulationOptions& options, const internal::ParsedTags* tags)
    : model_(std::move(model)), source_(std::move(source)) {
  contact_model_ =
      tags ? std::unique_ptr<ContactModel>(
                 new ContactModel(model_.get(), source_, options.overrides, *tags))
           : std::make_unique<ContactModel>(model_.get(), source_, options.overrides);
  data_.reset(mj_makeData(model_.get()));
  if (!data_) throw Error(fmt::format("{}: MuJoCo could not allocate mjData", source_));
  contacts_ = std::make_unique<ContactData>(*contact_model_, data_.get());
  // the run's own options, on its data's side
  if (options.timestep) contacts_->options().timestep = *options.timestep;
  timestep_ = contacts_->options().timestep;
  if (options.integrator) contacts_->options().integrator = *options.integrator;
  if (options.motion_only) contacts_->KeepMotionOnly();

  columns_ = options.columns;
  motion_only_ = !columns_.pairs && !columns_.friction && !columns_.energy &&
                 WithoutConstraints(contacts_->model_view());
  RecordBodiesAndJoints();
  row_size_ = Columns().size();
  Reset(/*fresh=*/true);
  if (options.settle) {
    // relaxed under Euler, the run's integrator given back (settle.h says why)
    const int integrator = contacts_->options().integrator;
    contacts_->options().integrator = mjINT_EULER;
    settled_ = Settle(this, &settled_contacts_);
    contacts_->options().integrator = integrator;
    settled_qpos_.assign(data_->qpos, data_->qpos + model_->nq);
    Reset();
  }
  contacts_->SetContactSteps(options.contact_steps);
}

Simulation::Simulation(UniqueModel model, std::string source, const SimulationOptions& options)
    : Simulation(std::shared_ptr<const mjModel>(std::move(model)), std::move(source), options) {}

void Simulation::Reset() { Reset(/*fresh=*/false); }

void Simulation::Reset(bool fresh) {
  // mj_makeData has just reset a fresh data to qpos0: not zeroed twice
  if (model_->nkey > 0) {
    mj_resetDataKeyframe(model_.get(), data_.get(), 0);
  } else if (!fresh) {
    mj_resetData(model_.get(), data_.get());
  }
  // the scene's state, its bodies in contact settled when asked, at the
  // run's own timestep: a step of another length (Step(h): the auto
  // timestep's, the settling relaxation's) is the run's only until here
  if (!settled_qpos_.empty()) mju_copy(data_->qpos, settled_qpos_.data(), model_->nq);
  contacts_->options().timestep = timestep_;
  contacts_->Reset();
  for (const Drive& drive : contact_model_->drives()) {
    drive.Position(data_->time, data_->mocap_pos + 3 * drive.mocap);
  }
  // a settled start's contacts, with the friction their load asks
  if (!settled_contacts_.empty()) contacts_->StartWith(settled_contacts_);
}

void Simulation::RecordBodiesAndJoints() {
  const mjModel* m = model_.get();
  for (int b = 1; b < m->nbody; ++b) {
    if (m->body_weldid[b] == 0) continue;
    recorded_bodies_.push_back(b);
    bool oriented = false;
    for (int j = m->body_jntadr[b]; j < m->body_jntadr[b] + m->body_jntnum[b]; ++j) {
      oriented = oriented || m->jnt_type[j] == mjJNT_FREE || m->jnt_type[j] == mjJNT_BALL;
    }
    oriented_.push_back(oriented);
  }
  for (const Drive& drive : contact_model_->drives()) {
    recorded_bodies_.push_back(drive.body);
    oriented_.push_back(false);
  }
  for (int j = 0; j < m->njnt; ++j) {
    if (m->jnt_type[j] == mjJNT_HINGE || m->jnt_type[j] == mjJNT_SLIDE) {
      recorded_joints_.push_back(j);
    }
  }
}

std::vector<std::string> Simulation::Columns() const {
  const mjModel* m = model_.get();
  std::vector<std::string> columns = {"time"};
  auto add = [&](const std::string& name, std::initializer_list<const char*> quantities) {
    for (const char* q : quantities) columns.push_back(fmt::format("{}.{}", name, q));
  };
  for (size_t i = 0; columns_.bodies && i < recorded_bodies_.size(); ++i) {
    const std::string body = ObjectName(m, mjOBJ_BODY, recorded_bodies_[i]);
    add(body, {"x", "y", "z", "vx", "vy", "vz"});
    if (oriented_[i]) add(body, {"qw", "qx", "qy", "qz", "wx", "wy", "wz"});
  }
  for (size_t i = 0; columns_.joints && i < recorded_joints_.size(); ++i) {
    add(ObjectName(m, mjOBJ_JOINT, recorded_joints_[i]), {"q", "v"});
  }
  for (size_t t = 0; columns_.pairs && t < contact_model_->tags().size(); ++t) {
    add(contact_model_->tags()[t].label, {"depth", "depth_rate", "force"});
  }
  for (size_t t = 0; columns_.friction && t < contact_model_->tags().size(); ++t) {
    add(contact_model_->tags()[t].label, {"friction_x", "friction_y", "friction_z"});
  }
  if (columns_.energy) add("energy", {"kinetic", "potential", "elastic", "dissipated", "total"});
  return columns;
}

EnergyLedger Simulation::Energy() const {
  EnergyLedger e = MechanicalEnergy(data_.get());
  e.elastic = contacts_->ElasticEnergy();
  e.dissipated = contacts_->DissipatedEnergy();
  return e;
}

EnergyLedger Simulation::MechanicalEnergy(mjData* d) const {
  const mjModel* m = model_.get();
  EnergyLedger e;

  // kinetic: 1/2 qvel^T M qvel
  const int mark = d->pstack;
  mjtNum* mv = mj_stackAlloc(d, m->nv);
  mj_mulM(m, d, mv, d->qvel);
  e.kinetic = 0.5 * mju_dot(d->qvel, mv, m->nv);
  d->pstack = mark;
  e.potential = PotentialEnergy(d);
  return e;
}

double Simulation::PotentialEnergy(const mjData* d) const {
  const mjModel* m = model_.get();
  double potential = 0;
  // the weight of the bodies that move through dofs (static and driven
  // bodies are not part of the simulated system) ...
  if (!(m->opt.disableflags & mjDSBL_GRAVITY)) {
    for (int b = 1; b < m->nbody; ++b) {
      if (m->body_weldid[b] != 0) {
        potential -= m->body_mass[b] * mju_dot3(m->opt.gravity, d->xipos + 3 * b);
      }
    }
  }
  // ... and the springs of slide and hinge joints
  for (int j = 0; j < m->njnt; ++j) {
    const int type = m->jnt_type[j];
    if (m->jnt_stiffness[j] > 0 && (type == mjJNT_SLIDE || type == mjJNT_HINGE)) {
      const int adr = m->jnt_qposadr[j];
      const double stretch = d->qpos[adr] - m->qpos_spring[adr];
      potential += 0.5 * m->jnt_stiffness[j] * stretch * stretch;
    }
  }
  return potential;
}

std::vector<TagReading> Simulation::Readings() const {
  std::vector<TagReading> readings;
  for (int t = 0; t < static_cast<int>(contact_model_->tags().size()); ++t) {
    readings.push_back(contacts_->Reading(t));
  }
  return readings;
}

void Simulation::Sample(std::vector<double>* row) {
  const PositionsKept kept(model(), data_.get(), &kept_positions_);
  mj_forward(model(), data_.get());  // the run's options: mj_forward reads its timestep
  Row(data_.get(), Readings(), contacts_->ElasticEnergy(), contacts_->DissipatedEnergy(), row);
}

void Simulation::SampleMotion(std::vector<double>* row) {
  if (!motion_only_) return Sample(row);
  const PositionsKept kept(model(), data_.get(), &kept_positions_);
  mj_kinematics(model(), data_.get());
  mj_comPos(model(), data_.get());
  mj_comVel(model(), data_.get());
  Row(data_.get(), Readings(), contacts_->ElasticEnergy(), contacts_->DissipatedEnergy(), row);
}

void Simulation::Row(mjData* d, const std::vector<TagReading>& readings, double elastic,
                     double dissipated, std::vector<double>* row,
                     std::optional<double> kinetic) const {
  const mjModel* m = model();
  // written in place: a row of 49 balls is 640 values, 300 appends
  row->resize(row_size_);
  double* out = row->data();
  auto put = [&out](std::initializer_list<double> values) {
    out = std::copy(values.begin(), values.end(), out);
  };
  auto put_array = [&out](const double* values, int n) { out = std::copy(values, values + n, out); };
  // d->time accumulates timesteps: show it to the nanosecond
  put({std::round(d->time * 1e9) / 1e9});
  for (size_t i = 0; columns_.bodies && i < recorded_bodies_.size(); ++i) {
    const int b = recorded_bodies_[i];
    mjtNum vel[3];
    PointVelocity(*contact_model_, d, b, d->xpos + 3 * b, vel);
    put_array(d->xpos + 3 * b, 3);
    put_array(vel, 3);
    // cvel: (angular, linear) in the world frame
    if (oriented_[i]) {
      put_array(d->xquat + 4 * b, 4);
      put_array(d->cvel + 6 * b, 3);
    }
  }
  for (size_t i = 0; columns_.joints && i < recorded_joints_.size(); ++i) {
    const int j = recorded_joints_[i];
    put({d->qpos[m->jnt_qposadr[j]], d->qvel[m->jnt_dofadr[j]]});
  }
  for (size_t t = 0; columns_.pairs && t < readings.size(); ++t) {
    const TagReading& r = readings[t];
    put({r.depth, r.depth_rate, r.force});
  }
  for (size_t t = 0; columns_.friction && t < readings.size(); ++t) {
    put_array(readings[t].friction, 3);
  }
  if (columns_.energy) {
    EnergyLedger e;
    if (kinetic) {
      e.kinetic = *kinetic;
      e.potential = PotentialEnergy(d);
    } else {
      e = MechanicalEnergy(d);
    }
    e.elastic = elastic;
    e.dissipated = dissipated;
    put({e.kinetic, e.potential, e.elastic, e.dissipated, e.total()});
  }
  assert(out == row->data() + row->size());
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

Scene::Scene(std::string path)
    : path_(std::move(path)),
      model_(LoadModelFile(path_)),
      tags_(std::make_shared<const internal::ParsedTags>(model_.get(), path_)) {}

Scene::Scene(std::string name, UniqueModel model)
    : path_(std::move(name)),
      model_(std::move(model)),
      tags_(std::make_shared<const internal::ParsedTags>(model_.get(), path_)) {}

std::unique_ptr<Simulation> Scene::Make(const SimulationOptions& options) const {
  return std::unique_ptr<Simulation>(new Simulation(model_, path_, options, tags_.get()));
}

std::unique_ptr<Simulation> Scene::Make(const SimulationOptions& options,
                                        UniqueModel edited) const {
  // the tags read once are the copy's when its <text> entries are the scene's
  const mjModel* m = model_.get();
  const mjModel* e = edited.get();
  const bool same_text = e->ntext == m->ntext && e->ntextdata == m->ntextdata &&
                         std::memcmp(e->text_data, m->text_data, m->ntextdata) == 0 &&
                         std::memcmp(e->text_adr, m->text_adr, m->ntext * sizeof(int)) == 0;
  if (!same_text) {
    throw Error(fmt::format("{}: the model to simulate is not a copy of the scene's: its "
                            "<text> entries differ",
                            path_));
  }
  return std::unique_ptr<Simulation>(
      new Simulation(std::shared_ptr<const mjModel>(std::move(edited)), path_, options,
                     tags_.get()));
}

const internal::ParsedTags& internal::TagsOf(const Scene& scene) { return *scene.tags_; }

}  // namespace contactlaws
