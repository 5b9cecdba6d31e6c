// Copyright contactlaws authors.

#include "contactlaws/replay.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <numeric>
#include <string_view>

#include <fmt/format.h>

#include "contactlaws/contact_model.h"
#include "ident/binding.h"
#include "ident/wire.h"
#include "ident/work_spread.h"
#include "sim/parallel.h"
#include "sim/settle.h"

namespace contactlaws {

Replay::Replay(const Scene& scene, const MeasuredData& data)
    : scene_(scene), data_(data), binding_(std::make_unique<internal::Binding>(scene, data)) {}

Replay::~Replay() = default;

int Replay::StartSample(int i, const ReplayOptions& options) const {
  return binding_->StartSample(i, options);
}

namespace {

// Every process's trajectories to every process, exchanged through spread
// with the seconds each took.
void Share(WorkSpread& spread, const std::vector<double>& seconds,
           std::vector<ReplayedTrajectory>* results) {
  std::vector<std::string> items(results->size());
  const int count = static_cast<int>(results->size());
  for (int i = 0; i < count; ++i) {
    if (spread.Mine(i, count)) items[i] = internal::Written((*results)[i]);
  }
  spread.Share(&items, seconds);
  for (int i = 0; i < count; ++i) (*results)[i] = internal::Read<ReplayedTrajectory>(items[i]);
}

}  // namespace

void ApplyEdits(mjModel* m, const std::vector<ModelEdit>& edits) {
  bool inertia = false;
  for (const ModelEdit& e : edits) {
    inertia = inertia || e.kind == ModelEdit::Kind::kMassScale ||
              e.kind == ModelEdit::Kind::kInertiaScale;
    switch (e.kind) {
      case ModelEdit::Kind::kMassScale:
        m->body_mass[e.id] *= e.value;
        break;
      case ModelEdit::Kind::kInertiaScale:
        for (int i = 0; i < 3; ++i) m->body_inertia[3 * e.id + i] *= e.value;
        break;
      case ModelEdit::Kind::kOffset: {
        // the geom's z axis in its body's frame
        const double z[3] = {0, 0, 1};
        double axis[3];
        mju_rotVecQuat(axis, z, m->geom_quat + 4 * e.id);
        for (int i = 0; i < 3; ++i) m->geom_pos[3 * e.id + i] += e.value * axis[i];
        // a geom compiled in its body's frame is placed with the body's pose,
        // its own pos unread (mj_kinematics): it has a frame of its own now
        m->geom_sameframe[e.id] = 0;
        break;
      }
      case ModelEdit::Kind::kMujocoTimeconst:
      case ModelEdit::Kind::kMujocoDampratio:
        for (int g = 0; g < m->ngeom; ++g) {
          m->geom_solref[mjNREF * g + (e.kind == ModelEdit::Kind::kMujocoDampratio)] = e.value;
        }
        break;
      case ModelEdit::Kind::kMujocoDmin:
      case ModelEdit::Kind::kMujocoDmax:
      case ModelEdit::Kind::kMujocoWidth: {
        const int i = e.kind == ModelEdit::Kind::kMujocoDmin   ? 0
                      : e.kind == ModelEdit::Kind::kMujocoDmax ? 1
                                                               : 2;
        for (int g = 0; g < m->ngeom; ++g) m->geom_solimp[mjNIMP * g + i] = e.value;
        break;
      }
      case ModelEdit::Kind::kMujocoFriction:
        for (int g = 0; g < m->ngeom; ++g) m->geom_friction[3 * g] = e.value;
        break;
    }
  }
  if (inertia) {
    // what MuJoCo derives from the masses at compile time (subtree masses,
    // the armature-free dof_M0 ...), derived again
    UniqueData d(mj_makeData(m));
    mj_setConst(m, d.get());
  }
}

// One thread's simulation of the scene, reused across trajectories.
class Replay::Rollout {
 public:
  Rollout(const Replay& replay, const ReplayOptions& options)
      : replay_(replay), options_(options), width_(static_cast<int>(replay.data_.columns.size())) {
    SimulationOptions simulation = options.simulation;
    simulation.columns = ColumnGroups{true, true, false, false, false};
    simulation.settle = false;  // each trajectory's start is settled, not the scene's
    simulation.motion_only = true;  // the rows read the motion alone
    if (options.edits.empty()) {
      sim_ = replay.scene_.Make(simulation);  // the scene's model, shared
    } else {
      UniqueModel model(mj_copyModel(nullptr, replay.scene_.model()));
      ApplyEdits(model.get(), options.edits);
      sim_ = replay.scene_.Make(simulation, std::move(model));
    }
    // each measured column's place in the run's rows (Simulation::Columns)
    const std::vector<std::string> columns = sim_->Columns();
    for (const std::string& name : replay.data_.columns) {
      const auto it = std::find(columns.begin(), columns.end(), name);
      if (it == columns.end()) {
        throw OptionError(fmt::format("{}: column '{}' is not one the scene's trajectory has "
                                      "(run {})",
                                      replay.data_.source, name, OptionError::kMark),
                          {{OptionError::Form::kGiven, "columns", "bodies,joints"}});
      }
      place_.push_back(static_cast<int>(it - columns.begin()));
    }
  }

  // Trajectory i from its start sample (StartSample).
  ReplayedTrajectory Run(int i, int start) {
    const MeasuredTrajectory& t = replay_.data_.trajectories[i];
    ReplayedTrajectory result;
    result.start = start;
    Start(t, result.start);
    if (options_.simulation.settle) {
      // the measured positions into their static equilibrium; Settle leaves
      // the velocities zeroed and its relaxation's memory: started again
      const SettleReport settled = Settle(sim_.get());
      result.settled_bodies = settled.bodies;
      result.settled_distance = settled.distance;
      const std::vector<mjtNum> qpos(sim_->data()->qpos, sim_->data()->qpos + sim_->model()->nq);
      Start(t, result.start);
      mju_copy(sim_->data()->qpos, qpos.data(), sim_->model()->nq);
      mj_forward(sim_->model(), sim_->data());
    }
    std::optional<AutoTimestep> stepper;
    if (options_.auto_timestep) stepper.emplace(sim_->contacts(), *options_.auto_timestep);
    const double tolerance = stepper ? 1e-9 : 0.5 * sim_->model()->opt.timestep;

    ScoreAccumulator score(options_.weights);
    row_.assign(width_, 0.0);
    const bool fixed_step = !stepper;
    Record(fixed_step);
    bool diverged = false;
    for (int k = result.start; k < t.samples(); ++k) {
      const double target = t.time[k] - t.time[result.start];
      while (!diverged && sim_->time() < target - tolerance) {
        if (stepper) {
          sim_->Step(stepper->Next(sim_->data(), target - sim_->time()));
        } else {
          sim_->Step();
        }
        if (sim_->contacts().divergence()) {
          diverged = true;
          result.status = ReplayedTrajectory::Status::kDiverged;
          result.diverged_at = sim_->contacts().divergence()->time;
        }
      }
      if (!diverged) Record(fixed_step);  // a diverged state is not read: the last finite one stands
      Add(t, k, &score);
      if (options_.keep_trajectories) {
        result.simulated.insert(result.simulated.end(), row_.begin(), row_.end());
      }
      if (options_.should_stop && options_.should_stop()) {
        result.status = ReplayedTrajectory::Status::kInterrupted;
        break;
      }
    }
    result.score = score.Finish();
    result.last = row_;
    return result;
  }

 private:
  const double* Sample(const MeasuredTrajectory& t, int k) const {
    return t.values.data() + static_cast<size_t>(k) * width_;
  }

  // The run reset to sample s of t (positions, velocities, time 0).
  void Start(const MeasuredTrajectory& t, int s) {
    sim_->Reset();
    replay_.binding_->SetStart(t, s, options_, sim_->model(), sim_->data());
    mj_forward(sim_->model(), sim_->data());
  }


  // The simulated state in the data's columns (row_), as the run's rows
  // give it.
  void Record(bool fixed_step) {
    if (fixed_step) {
      sim_->SampleMotion(&sample_);
    } else {
      sim_->Sample(&sample_);
    }
    for (int c = 0; c < width_; ++c) row_[c] = sample_[place_[c]];
  }

  // Sample k's errors.
  void Add(const MeasuredTrajectory& t, int k, ScoreAccumulator* score) const {
    const double* x = Sample(t, k);
    using internal::kQw;
    using internal::kX;
    for (const internal::MeasuredBody& b : replay_.binding_->bodies()) {
      const double p[3] = {x[b.col[kX]], x[b.col[kX + 1]], x[b.col[kX + 2]]};
      const double ps[3] = {row_[b.col[kX]], row_[b.col[kX + 1]], row_[b.col[kX + 2]]};
      double q[4] = {1, 0, 0, 0}, qs[4] = {1, 0, 0, 0};
      for (int i = 0; b.has(kQw) && i < 4; ++i) q[i] = x[b.col[kQw + i]], qs[i] = row_[b.col[kQw + i]];
      const bool oriented = b.has(kQw);
      score->AddBody(ps, p, oriented ? qs : nullptr, oriented ? q : nullptr,
                     options_.length.value_or(b.length));
    }
    for (const internal::MeasuredJoint& j : replay_.binding_->joints()) score->AddJoint(row_[j.col_q], x[j.col_q]);
    score->EndSample();
  }

  const Replay& replay_;
  const ReplayOptions& options_;
  const int width_;
  std::unique_ptr<Simulation> sim_;
  std::vector<int> place_;      // per data column, its index in the run's rows
  std::vector<double> sample_;  // the run's row
  std::vector<double> row_;     // the data's columns
};

std::vector<ReplayedTrajectory> Replay::Run(const ReplayOptions& options) const {
  if (options.start == StartRule::kRefit) {
    if (options.refit.lead < 0 || options.refit.min_samples < 2) {
      throw Error(fmt::format("refit: lead {} must be >= 0 and min_samples {} >= 2",
                              options.refit.lead, options.refit.min_samples));
    }
    StartSample(0, options);  // refuses data without a free body
  }
  const int count = static_cast<int>(data_.trajectories.size());
  std::vector<ReplayedTrajectory> results(count);
  std::vector<double> seconds(count);  // each rollout's, for the spread's balance
  // a rollout's cost before it is measured: its simulated duration. The
  // threads take the longest first, so that none is left with a long one
  // at the end (each result goes to its own index: the same bits)
  std::vector<int> first_sample(count);  // each trajectory's start (StartSample)
  std::vector<double> duration(count);
  for (int i = 0; i < count; ++i) {
    const std::vector<double>& time = data_.trajectories[i].time;
    first_sample[i] = StartSample(i, options);
    duration[i] = time.back() - time[first_sample[i]];
  }
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return duration[a] > duration[b]; });
  if (options.spread) options.spread->Expect(duration);
  // the first rollout on this thread: the tags are checked (and refused) here
  Rollout first(*this, options);
  // a rollout per thread, made on it (the first thread's is made above)
  std::vector<std::unique_ptr<Rollout>> rollouts(std::max(1, std::min(options.jobs, count)));
  internal::ParallelFor(count, options.jobs, [&](int worker, int k) {
    const int i = order[k];
    if (options.spread && !options.spread->Mine(i, count)) return;
    if (options.should_stop && options.should_stop()) {
      results[i].status = ReplayedTrajectory::Status::kInterrupted;
      return;
    }
    Rollout* rollout = worker == 0 ? &first : rollouts[worker].get();
    if (!rollout) rollout = (rollouts[worker] = std::make_unique<Rollout>(*this, options)).get();
    const double start = ThreadSeconds();
    results[i] = rollout->Run(i, first_sample[i]);
    seconds[i] = ThreadSeconds() - start;
  });
  if (options.spread) Share(*options.spread, seconds, &results);
  return results;
}

}  // namespace contactlaws
