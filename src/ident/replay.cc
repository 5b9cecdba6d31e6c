// Copyright contactlaws authors.

#include "contactlaws/replay.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <exception>
#include <string_view>
#include <thread>

#include <fmt/format.h>

#include "contactlaws/error.h"

namespace contactlaws {

// A measured body: its free joint's slots and the data's columns.
struct Replay::Body {
  int body = -1;
  bool free = false;        // it has a free joint of its own: its state is set
  int qpos = 0, qvel = 0;   // its free joint's addresses
  int col[13];              // kBodyQuantities' columns, -1 when absent
  double length = 0;        // e_q's default L_b: its smallest GeomSize, m
  double rbound = 0;        // the refit's default height, m
  bool has(int q) const { return col[q] >= 0; }
};

// A measured hinge or slide.
struct Replay::Joint {
  int joint = -1;
  int qpos = 0, qvel = 0;
  int col_q = -1, col_v = -1;
};

namespace {

enum BodyQuantity { kX = 0, kQw = 3, kVx = 7, kWx = 10 };

// The quantity's index in list, -1 when absent.
template <size_t N>
int IndexOf(const char* const (&list)[N], std::string_view quantity) {
  for (size_t i = 0; i < N; ++i) {
    if (quantity == list[i]) return static_cast<int>(i);
  }
  return -1;
}

std::string QuantityList(const char* const* list, size_t n) {
  std::string text;
  for (size_t i = 0; i < n; ++i) text += (i ? " " : "") + std::string(list[i]);
  return text;
}

// v_body = R(q)^T v_world.
void RotateBack(const double q[4], const double v[3], double out[3]) {
  double conj[4];
  mju_negQuat(conj, q);
  mju_rotVecQuat(out, v, conj);
}

// The constant body-frame angular velocity that turns q0 into q1 in dt.
void AngularVelocity(const double q0[4], const double q1[4], double dt, double w[3]) {
  double conj[4], dq[4];
  mju_negQuat(conj, q0);
  mju_mulQuat(dq, conj, q1);
  mju_quat2Vel(w, dq, dt);
}

// Every process's trajectories to every process: each result as bytes (its
// fields, then the simulated samples), exchanged through spread.
void Share(const WorkSpread& spread, std::vector<ReplayedTrajectory>* results) {
  struct Fixed {
    ReplayedTrajectory::Status status;
    int start;
    Score score;
    double diverged_at;
  };
  std::vector<std::string> items(results->size());
  const int count = static_cast<int>(results->size());
  for (int i = 0; i < count; ++i) {
    if (!spread.Mine(i, count)) continue;
    const ReplayedTrajectory& r = (*results)[i];
    const Fixed fixed{r.status, r.start, r.score, r.diverged_at};
    items[i].assign(reinterpret_cast<const char*>(&fixed), sizeof fixed);
    items[i].append(reinterpret_cast<const char*>(r.simulated.data()),
                    r.simulated.size() * sizeof(double));
  }
  spread.Share(&items);
  for (int i = 0; i < count; ++i) {
    ReplayedTrajectory& r = (*results)[i];
    Fixed fixed;
    std::memcpy(&fixed, items[i].data(), sizeof fixed);
    r.status = fixed.status;
    r.start = fixed.start;
    r.score = fixed.score;
    r.diverged_at = fixed.diverged_at;
    r.simulated.resize((items[i].size() - sizeof fixed) / sizeof(double));
    std::memcpy(r.simulated.data(), items[i].data() + sizeof fixed,
                r.simulated.size() * sizeof(double));
  }
}

}  // namespace

void ApplyEdits(mjModel* m, const std::vector<ModelEdit>& edits) {
  for (const ModelEdit& e : edits) {
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
}

Replay::Replay(const Scene& scene, const MeasuredData& data) : scene_(scene), data_(data) {
  const mjModel* m = scene.model();
  auto fail = [&](const std::string& what) {
    throw Error(fmt::format("{}: {}", data.source, what));
  };
  for (size_t c = 0; c < data.columns.size(); ++c) {
    const std::string& column = data.columns[c];
    const size_t dot = column.rfind('.');
    const std::string name = column.substr(0, dot);
    const std::string_view quantity = std::string_view(column).substr(dot + 1);
    if (const int b = mj_name2id(m, mjOBJ_BODY, name.c_str()); b > 0) {
      const int q = IndexOf(kBodyQuantities, quantity);
      if (q < 0) {
        fail(fmt::format("column '{}': a body's quantities are {}", column,
                         QuantityList(kBodyQuantities, std::size(kBodyQuantities))));
      }
      auto it = std::find_if(bodies_.begin(), bodies_.end(),
                             [&](const Body& x) { return x.body == b; });
      if (it == bodies_.end()) {
        Body body;
        body.body = b;
        std::fill(std::begin(body.col), std::end(body.col), -1);
        bodies_.push_back(body);
        it = bodies_.end() - 1;
      }
      it->col[q] = static_cast<int>(c);
    } else if (const int j = mj_name2id(m, mjOBJ_JOINT, name.c_str()); j >= 0) {
      const int type = m->jnt_type[j];
      if (type != mjJNT_HINGE && type != mjJNT_SLIDE) {
        fail(fmt::format("column '{}': joint '{}' is a {} joint: measure its body's columns "
                         "(<body>.x ... .qw ...) instead",
                         column, name, type == mjJNT_FREE ? "free" : "ball"));
      }
      const int q = IndexOf(kJointQuantities, quantity);
      if (q < 0) fail(fmt::format("column '{}': a joint's quantities are q v", column));
      auto it = std::find_if(joints_.begin(), joints_.end(),
                             [&](const Joint& x) { return x.joint == j; });
      if (it == joints_.end()) {
        Joint joint;
        joint.joint = j;
        joint.qpos = m->jnt_qposadr[j];
        joint.qvel = m->jnt_dofadr[j];
        joints_.push_back(joint);
        it = joints_.end() - 1;
      }
      (q == 0 ? it->col_q : it->col_v) = static_cast<int>(c);
    } else {
      fail(fmt::format("column '{}': the scene {} has no body or joint '{}'", column,
                       scene.path(), name));
    }
  }
  // whole groups, and a free joint to set
  for (Body& body : bodies_) {
    const std::string name = ObjectName(m, mjOBJ_BODY, body.body);
    const int groups[4][2] = {{kX, 3}, {kQw, 4}, {kVx, 3}, {kWx, 3}};
    for (const auto& g : groups) {
      int given = 0;
      for (int i = 0; i < g[1]; ++i) given += body.has(g[0] + i);
      for (int i = 0; given > 0 && i < g[1]; ++i) {
        if (!body.has(g[0] + i)) {
          fail(fmt::format("missing column {}.{} (beside {}.{})", name, kBodyQuantities[g[0] + i],
                           name, kBodyQuantities[g[0] + (i == 0 ? 1 : 0)]));
        }
      }
    }
    const int j = m->body_jntadr[body.body];
    body.free = m->body_jntnum[body.body] == 1 && m->jnt_type[j] == mjJNT_FREE;
    if (!body.has(kX) || (body.free && !body.has(kQw))) {
      fail(fmt::format("missing column {}.{}: {}", name, body.has(kX) ? "qw" : "x",
                       body.free ? "a free body's state needs its position (x y z) and "
                                   "orientation (qw qx qy qz)"
                                 : "a body is scored by its position (x y z)"));
    }
    if (body.free) {
      body.qpos = m->jnt_qposadr[j];
      body.qvel = m->jnt_dofadr[j];
    }
    body.length = std::numeric_limits<double>::infinity();
    for (int g = m->body_geomadr[body.body];
         g < m->body_geomadr[body.body] + m->body_geomnum[body.body]; ++g) {
      body.length = std::min(body.length, GeomSize(m, g));
      body.rbound = std::max(body.rbound, m->geom_rbound[g] + mju_norm3(m->geom_pos + 3 * g));
    }
    if (!std::isfinite(body.length)) body.length = 1.0;
  }
  for (const Joint& joint : joints_) {
    if (joint.col_q < 0) {
      fail(fmt::format("missing column {}.q (beside {}.v)", ObjectName(m, mjOBJ_JOINT, joint.joint),
                       ObjectName(m, mjOBJ_JOINT, joint.joint)));
    }
  }
}

Replay::~Replay() = default;

int Replay::StartSample(int i, const ReplayOptions& options) const {
  if (options.start == StartRule::kFirst) return 0;
  const auto free = std::find_if(bodies_.begin(), bodies_.end(), [](const Body& b) { return b.free; });
  if (free == bodies_.end()) {
    throw Error(fmt::format("{}: --start refit needs a measured body with a free joint",
                            data_.source));
  }
  const Body& body = *free;
  const MeasuredTrajectory& t = data_.trajectories[i];
  const int width = static_cast<int>(data_.columns.size());
  const double height = options.refit.height.value_or(body.rbound);
  int first = t.samples() - 1;
  for (int k = 0; k < t.samples(); ++k) {
    if (t.values[k * width + body.col[kX + 2]] <= height) {
      first = k;
      break;
    }
  }
  return std::max(0, first - options.refit.lead);
}

// One thread's simulation of the scene, reused across trajectories.
class Replay::Rollout {
 public:
  Rollout(const Replay& replay, const ReplayOptions& options)
      : replay_(replay), options_(options), width_(static_cast<int>(replay.data_.columns.size())) {
    UniqueModel model(mj_copyModel(nullptr, replay.scene_.model()));
    ApplyEdits(model.get(), options.edits);
    SimulationOptions simulation = options.simulation;
    simulation.columns = ColumnGroups{true, true, false, false, false};
    sim_ = std::make_unique<Simulation>(std::move(model), replay.scene_.path(), simulation);
    // each measured column's place in the run's rows (Simulation::Columns)
    const std::vector<std::string> columns = sim_->Columns();
    for (const std::string& name : replay.data_.columns) {
      const auto it = std::find(columns.begin(), columns.end(), name);
      if (it == columns.end()) {
        throw Error(fmt::format("{}: column '{}' is not one the scene's trajectory has (run "
                                "--columns bodies,joints)",
                                replay.data_.source, name));
      }
      place_.push_back(static_cast<int>(it - columns.begin()));
    }
  }

  ReplayedTrajectory Run(int i) {
    const MeasuredTrajectory& t = replay_.data_.trajectories[i];
    ReplayedTrajectory result;
    result.start = replay_.StartSample(i, options_);
    sim_->Reset();
    SetStart(t, result.start);
    mj_forward(sim_->model(), sim_->data());
    std::optional<AutoTimestep> stepper;
    if (options_.auto_timestep) stepper.emplace(sim_->contacts(), *options_.auto_timestep);
    const double tolerance = stepper ? 1e-9 : 0.5 * sim_->model()->opt.timestep;

    ScoreAccumulator score(options_.weights);
    row_.assign(width_, 0.0);
    Record();
    bool diverged = false;
    for (int k = result.start; k < t.samples(); ++k) {
      const double target = t.time[k] - t.time[result.start];
      while (!diverged && sim_->time() < target - tolerance) {
        if (stepper) {
          sim_->Step(stepper->Next(target - sim_->time()));
        } else {
          sim_->Step();
        }
        if (sim_->contacts().divergence()) {
          diverged = true;
          result.status = ReplayedTrajectory::Status::kDiverged;
          result.diverged_at = sim_->contacts().divergence()->time;
        }
      }
      if (!diverged) Record();  // a diverged state is not read: the last finite one stands
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
    return result;
  }

 private:
  const double* Sample(const MeasuredTrajectory& t, int k) const {
    return t.values.data() + static_cast<size_t>(k) * width_;
  }

  // The measured state of sample s into the data (RefitRule for kRefit).
  void SetStart(const MeasuredTrajectory& t, int s) {
    const mjModel* m = sim_->model();
    mjData* d = sim_->data();
    const bool refit = options_.start == StartRule::kRefit && s >= options_.refit.min_samples;
    const int next = s + 1 < t.samples() ? s + 1 : s;  // finite differences forward,
    const int prev = next == s ? s - 1 : s;            // or backward at the end
    const double dt = t.time[next] - t.time[prev];
    for (const Body& b : replay_.bodies_) {
      if (!b.free) continue;  // set by its joints
      double* qpos = d->qpos + b.qpos;
      double* qvel = d->qvel + b.qvel;
      const double* x = Sample(t, s);
      for (int i = 0; i < 3; ++i) qpos[i] = x[b.col[kX + i]];
      for (int i = 0; i < 4; ++i) qpos[3 + i] = x[b.col[kQw + i]];
      mju_normalize4(qpos + 3);
      if (refit) {
        RefitVelocity(t, s, b, qvel);
        continue;
      }
      const double* a = Sample(t, prev);
      const double* c = Sample(t, next);
      for (int i = 0; i < 3; ++i) {
        qvel[i] = b.has(kVx) ? x[b.col[kVx + i]] : (c[b.col[kX + i]] - a[b.col[kX + i]]) / dt;
      }
      if (b.has(kWx)) {
        const double w[3] = {x[b.col[kWx]], x[b.col[kWx + 1]], x[b.col[kWx + 2]]};
        RotateBack(qpos + 3, w, qvel + 3);
      } else {
        double qa[4], qc[4];
        for (int i = 0; i < 4; ++i) qa[i] = a[b.col[kQw + i]], qc[i] = c[b.col[kQw + i]];
        mju_normalize4(qa);
        mju_normalize4(qc);
        AngularVelocity(qa, qc, dt, qvel + 3);
      }
    }
    for (const Joint& j : replay_.joints_) {
      d->qpos[j.qpos] = Sample(t, s)[j.col_q];
      d->qvel[j.qvel] = j.col_v >= 0 ? Sample(t, s)[j.col_v]
                                     : (Sample(t, next)[j.col_q] - Sample(t, prev)[j.col_q]) / dt;
    }
    (void)m;
  }

  // RefitRule's velocities of body b at start sample s (>= 2 samples before).
  void RefitVelocity(const MeasuredTrajectory& t, int s, const Body& b, double* qvel) const {
    const double* gravity = sim_->model()->opt.gravity;
    double q0[4], qs[4];
    for (int i = 0; i < 4; ++i) q0[i] = Sample(t, 0)[b.col[kQw + i]], qs[i] = Sample(t, s)[b.col[kQw + i]];
    mju_normalize4(q0);
    mju_normalize4(qs);
    AngularVelocity(q0, qs, t.time[s] - t.time[0], qvel + 3);
    for (int i = 0; i < 3; ++i) {
      if (gravity[i] == 0 && b.has(kVx)) {
        double sum = 0;
        for (int k = 0; k < s; ++k) sum += Sample(t, k)[b.col[kVx + i]];
        qvel[i] = sum / s;
        continue;
      }
      // least squares y = a + v t over samples 0..s-1, y = p - g t^2 / 2
      double tm = 0, ym = 0;
      for (int k = 0; k < s; ++k) {
        const double tk = t.time[k] - t.time[0];
        tm += tk;
        ym += Sample(t, k)[b.col[kX + i]] - 0.5 * gravity[i] * tk * tk;
      }
      tm /= s;
      ym /= s;
      double stt = 0, sty = 0;
      for (int k = 0; k < s; ++k) {
        const double tk = t.time[k] - t.time[0];
        const double yk = Sample(t, k)[b.col[kX + i]] - 0.5 * gravity[i] * tk * tk;
        stt += (tk - tm) * (tk - tm);
        sty += (tk - tm) * (yk - ym);
      }
      qvel[i] = sty / stt + gravity[i] * (t.time[s - 1] - t.time[0]);
    }
  }

  // The simulated state in the data's columns (row_), as the run's rows
  // give it.
  void Record() {
    sim_->Sample(&sample_);
    for (int c = 0; c < width_; ++c) row_[c] = sample_[place_[c]];
  }

  // Sample k's errors.
  void Add(const MeasuredTrajectory& t, int k, ScoreAccumulator* score) const {
    const double* x = Sample(t, k);
    for (const Body& b : replay_.bodies_) {
      const double p[3] = {x[b.col[kX]], x[b.col[kX + 1]], x[b.col[kX + 2]]};
      const double ps[3] = {row_[b.col[kX]], row_[b.col[kX + 1]], row_[b.col[kX + 2]]};
      double q[4] = {1, 0, 0, 0}, qs[4] = {1, 0, 0, 0};
      for (int i = 0; b.has(kQw) && i < 4; ++i) q[i] = x[b.col[kQw + i]], qs[i] = row_[b.col[kQw + i]];
      const bool oriented = b.has(kQw);
      score->AddBody(ps, p, oriented ? qs : nullptr, oriented ? q : nullptr,
                     options_.length.value_or(b.length));
    }
    for (const Joint& j : replay_.joints_) score->AddJoint(row_[j.col_q], x[j.col_q]);
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
  // the first rollout on this thread: the tags are checked (and refused) here
  Rollout first(*this, options);
  const int threads = std::max(1, std::min(options.jobs, count));
  std::atomic<int> next{0};
  std::vector<std::exception_ptr> errors(threads);
  auto work = [&](int thread, Rollout* rollout) {
    try {
      std::unique_ptr<Rollout> own;
      if (!rollout) rollout = (own = std::make_unique<Rollout>(*this, options)).get();
      for (int i = next++; i < count; i = next++) {
        if (options.spread && !options.spread->Mine(i, count)) continue;
        if (options.should_stop && options.should_stop()) {
          results[i].status = ReplayedTrajectory::Status::kInterrupted;
          continue;
        }
        results[i] = rollout->Run(i);
      }
    } catch (...) {
      errors[thread] = std::current_exception();
      next = count;
    }
  };
  std::vector<std::thread> pool;
  for (int thread = 1; thread < threads; ++thread) pool.emplace_back(work, thread, nullptr);
  work(0, &first);
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e);
  }
  if (options.spread) Share(*options.spread, &results);
  return results;
}

Distribution Distribute(std::vector<double> values) {
  Distribution d;
  if (values.empty()) return d;
  double sum = 0;
  for (double v : values) sum += v;  // in order: the same bits whatever the threads
  d.mean = sum / values.size();
  std::sort(values.begin(), values.end());
  auto quantile = [&](double p) {
    const double at = p * (values.size() - 1);
    const size_t lo = static_cast<size_t>(std::floor(at));
    const size_t hi = std::min(lo + 1, values.size() - 1);
    return values[lo] + (at - lo) * (values[hi] - values[lo]);
  };
  d.median = quantile(0.5);
  d.p90 = quantile(0.9);
  return d;
}

}  // namespace contactlaws
