// Copyright contactlaws authors.
//
// Simulation: one tagged scene stepped with its laws, and what the CLI
// records of it (trajectory rows, the impact log, the energy ledger). A user's
// own program can use it as is, or take ContactModel and ContactData alone.

#ifndef CONTACTLAWS_SIMULATION_H_
#define CONTACTLAWS_SIMULATION_H_

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "contactlaws/auto_timestep.h"
#include "contactlaws/contact_data.h"
#include "contactlaws/contact_model.h"
#include "contactlaws/impact.h"

namespace contactlaws {

class Scene;
namespace internal {
class ParsedTags;  // src/scene/parsed_tags.h
const ParsedTags& TagsOf(const Scene& scene);
}  // namespace internal

// The energy ledger, J. total = kinetic + potential + elastic + dissipated is
// constant for a scene without drives, up to the integrator's error.
struct EnergyLedger {
  double kinetic = 0;     // 1/2 qvel^T M qvel
  double potential = 0;   // gravity of the moving bodies, slide and hinge springs
  double elastic = 0;     // stored by the contact laws
  double dissipated = 0;  // dissipated by the contact laws since the start
  double total() const { return kinetic + potential + elastic + dissipated; }
};

// One kind of MuJoCo warning raised on a run's data (d->warning), once, with
// the number of times it was raised.
struct MujocoWarning {
  std::string text;  // mju_warningText of its last occurrence
  int count = 0;
};

// A run whose total energy grows by more than this fraction of its energy
// scale (the largest of |total| at the start and the kinetic energy seen) is
// suspect when nothing drives it: the laws only dissipate, so the growth is
// the integrator's. RK4 at 1e-5 s keeps the paper's drop within 1e-5 of it.
inline constexpr double kEnergyGrowthTolerance = 1e-2;

// The groups of trajectory columns (Simulation::Columns), each on or off.
// friction came last: an initializer of the first four keeps its meaning.
struct ColumnGroups {
  bool bodies = true;    // every moving body: position, velocity; orientation, spin
  bool joints = true;    // every hinge and slide joint: coordinate and rate
  bool pairs = true;     // every tag: depth, depth rate, force
  bool energy = true;    // the energy ledger
  bool friction = true;  // every tag: its friction force (columns before energy's)
};

// What SimulationOptions::settle did (src/sim/settle.h: the relaxation).
struct SettleReport {
  int bodies = 0;          // moved: the bodies in contact at the start
  std::string body;        // the one moved farthest ("" when none)
  double distance = 0;     // m, how far it moved
  double angle = 0;        // rad, the largest turn of any of them
  double relaxation = 0;   // s of relaxation taken
  // a body its contacts carry that friction does not hold at rest (it rolls
  // or tips from its contacts' depth in the run), "" when none
  std::string unheld;
  // "settled 3 bodies: the farthest, box2, by 2.1e-05 m (turns <= 1e-9 rad)"
  std::string Line() const;
};

struct SimulationOptions {
  Overrides overrides;
  std::optional<double> timestep;   // s, > 0; default: the scene's
  std::optional<int> integrator;    // mjtIntegrator; default: the scene's
  ColumnGroups columns;             // of the trajectory
  // Before t = 0, move the bodies that start in contact into the static
  // equilibrium of their contacts (SettleReport); Simulation::settled() says what
  // moved. Throws Error when there is none.
  bool settle = false;
  // Steps that keep the bodies' motion and the contacts' memory alone
  // (ContactData::KeepMotionOnly): for runs whose rows are the bodies' and
  // joints' motion and read nothing else of the data (replay's rollouts).
  bool motion_only = false;
  // Contacts integrated inside each step (ContactData::SetContactSteps); off
  // by default. Set after settle, which relaxes without them.
  ContactStepsOptions contact_steps;
};

// One run of a model: its data, its laws (the tags with the run's
// overrides) and its options. The model is only read: many Simulations (a
// Scene's) share one, on as many threads; the run's timestep and integrator
// (SimulationOptions, the auto timestep's steps) are the data's options
// (ContactData::options), never written into the model.
class Simulation {
 public:
  // Shares the model, reads its tags (throws Error naming source), makes the
  // data and resets it to keyframe 0 when the scene has one.
  Simulation(std::shared_ptr<const mjModel> model, std::string source,
             const SimulationOptions& options = {});
  // Takes the model, as above.
  Simulation(UniqueModel model, std::string source, const SimulationOptions& options = {});

  // One step with the laws active.
  void Step() { contacts_->Step(); }
  // One step of the given length, s (> 0): it becomes this run's timestep
  // until Reset, which gives the run its own back.
  void Step(double timestep) { contacts_->Step(timestep); }

  // Back to the initial state (keyframe 0 or the model's qpos0).
  void Reset();

  double time() const { return data_->time; }
  // The model as this run steps it: the shared model's arrays with this run's
  // options (ContactData::model_view). Give it to MuJoCo with data().
  const mjModel* model() const { return contacts_->model_view(); }
  // The model itself, shared with the other runs of its scene.
  const std::shared_ptr<const mjModel>& shared_model() const { return model_; }
  const mjData* data() const { return data_.get(); }
  mjData* data() { return data_.get(); }
  const ContactModel& contact_model() const { return *contact_model_; }
  const ContactData& contacts() const { return *contacts_; }
  const std::string& source() const { return source_; }

  // Trajectory columns, by group (SimulationOptions::columns):
  //   time;
  //   bodies: for every moving body (not welded to the world: jointed or the
  //     child of one) and every driven body, <body>.x .y .z .vx .vy .vz
  //     (frame origin, world frame, m and m/s); for a body with a free or ball
  //     joint also .qw .qx .qy .qz (orientation, world frame) and .wx .wy .wz
  //     (angular velocity, world frame, rad/s);
  //   joints: for every hinge and slide joint <joint>.q .v (rad and rad/s, or
  //     m and m/s);
  //   pairs: for every tag <label>.depth .depth_rate .force;
  //   friction: for every tag <label>.friction_x .friction_y .friction_z (N,
  //     world frame: the friction force of its points on its geom1; 0 without
  //     friction or out of contact);
  //   energy: energy.kinetic .potential .elastic .dissipated .total.
  std::vector<std::string> Columns() const;

  // The values of Columns() at the current state. Runs mj_forward so that
  // every quantity belongs to the accepted state.
  void Sample(std::vector<double>* row);
  // Sample, for a data stepped on at a fixed step: when the columns are
  // bodies' and joints' only and no step of the model makes a constraint
  // row, only the stages they read (positions, velocities), to the bit.
  // mj_forward's other stages (the hooks, the solver and its warm start)
  // then change nothing the next fixed step reads; the contact-aware step
  // reads the hooks' evaluation: give it Sample.
  void SampleMotion(std::vector<double>* row);

  // The ledger at the current state (after mj_forward).
  EnergyLedger Energy() const;

  // The tags' latest readings, by tag (ContactData::Reading).
  std::vector<TagReading> Readings() const;

  // The row of Columns() (what Sample writes) at a state d of this model at
  // d->time, with the tags' readings and the laws' elastic and dissipated
  // energy (J) given: a state inside a step. d has its kinematics computed
  // (mj_kinematics, mj_comPos, mj_comVel) and, unless the caller gives the
  // kinetic energy (J), its mass matrix (mj_crb).
  void Row(mjData* d, const std::vector<TagReading>& readings, double elastic,
           double dissipated, std::vector<double>* row,
           std::optional<double> kinetic = std::nullopt) const;

  // True when nothing feeds energy in: no contactdrive and no actuator. Only
  // then must the ledger's total not grow.
  bool Undriven() const;

  // MuJoCo's warnings on this data since the last reset, one per kind.
  std::vector<MujocoWarning> Warnings() const;

  // What SimulationOptions::settle moved (nullopt without it).
  const std::optional<SettleReport>& settled() const { return settled_; }

 private:
  friend class Scene;
  // With the tags already read (tags: a Scene's), else reads m's.
  Simulation(std::shared_ptr<const mjModel> model, std::string source,
             const SimulationOptions& options, const internal::ParsedTags* tags);
  // Reset(); fresh: the data is mj_makeData's, already at qpos0.
  void Reset(bool fresh);
  // The ledger's kinetic and potential energy at d (elastic, dissipated 0).
  EnergyLedger MechanicalEnergy(mjData* d) const;
  // Its potential part: the weight of the moving bodies, the joints' springs.
  double PotentialEnergy(const mjData* d) const;
  // The bodies and joints whose columns the trajectory has.
  void RecordBodiesAndJoints();

  std::shared_ptr<const mjModel> model_;
  std::string source_;
  std::unique_ptr<ContactModel> contact_model_;
  UniqueData data_;
  std::unique_ptr<ContactData> contacts_;
  ColumnGroups columns_;
  bool motion_only_ = false;  // SampleMotion: the kinematic stages suffice
  std::vector<mjtNum> kept_positions_;  // Sample's qpos, kept through its forward pass
  std::vector<int> recorded_bodies_;
  std::vector<uint8_t> oriented_;  // per recorded body: it has a free or ball joint
  std::vector<int> recorded_joints_;  // hinge and slide joints
  size_t row_size_ = 0;               // Columns().size()
  std::optional<SettleReport> settled_;
  std::vector<mjtNum> settled_qpos_;  // the initial positions after settle
  double timestep_ = 0;  // s: the run's own (Reset gives it back)
  // their contacts with the friction they carry at the start (settle_friction.h)
  std::vector<PointEvaluation> settled_contacts_;
};

// An MJCF scene, parsed once, its tags too; its simulations share its model,
// which nothing writes, and read its tags without reading text again.
class Scene {
 public:
  explicit Scene(std::string path);  // throws Error "PATH: ..."
  // A model already loaded; name stands for its file in messages.
  Scene(std::string name, UniqueModel model);

  const std::string& path() const { return path_; }
  const mjModel* model() const { return model_.get(); }

  // A fresh simulation of the shared model; throws Error when the tags (with
  // the overrides) are refused.
  std::unique_ptr<Simulation> Make(const SimulationOptions& options) const;
  // A fresh simulation of edited, a copy of the scene's model (mj_copyModel)
  // with numbers changed (masses, positions: ApplyEdits): the scene's tags,
  // with the overrides, on it. Throws Error when its <text> entries are not
  // the scene's, or as above.
  std::unique_ptr<Simulation> Make(const SimulationOptions& options, UniqueModel edited) const;

 private:
  friend const internal::ParsedTags& internal::TagsOf(const Scene& scene);

  std::string path_;
  std::shared_ptr<const mjModel> model_;
  std::shared_ptr<const internal::ParsedTags> tags_;  // of model_, read once
};

// ---------------------------------------------------------------------------
// The stepping loop of a Simulation with its monitors: divergence after every
// step, the energy ledger of an undriven scene, the run's stop flag (a
// program's Ctrl-C), and the trajectory sampled on a fixed grid. What the command line, the
// benchmarks and a user's program step with.

struct AdvanceOptions {
  double duration = 2.0;     // s of simulated time
  double sample_rate = 0.0;  // rows per simulated second; 0: no rows
  // Stop as soon as the first contact episode of the scene's first tag ends.
  bool until_first_episode = false;
  // Step with AutoTimestep instead of the model's fixed timestep; rows stay
  // on the sample grid: a row inside a step is interpolated between the
  // step's exact ends (src/sim/dense_rows.h), a row at a step's end is its.
  std::optional<AutoTimestepOptions> auto_timestep;
  // With auto_timestep: end a step at every sample time instead, so that
  // on_row is called with the simulation itself at the row's time (a
  // renderer draws the data, not the row).
  bool steps_end_at_rows = false;
  // This run's stop flag, or none: once *stop is true, Advance returns
  // (kInterrupted) before its next step. Set it from another thread or a
  // signal handler (std::atomic<bool> is lock-free there); it stops the runs
  // given it, and no other.
  const std::atomic<bool>* stop = nullptr;
};

// How a run ended: a call of Advance, a trajectory's replay
// (ReplayedTrajectory), a run of a sweep (the application's compare and
// restitution), a sweep as a whole.
enum class RunStatus {
  kComplete,     // reached its end (the duration, or the first episode's end)
  kDiverged,     // stopped at a divergence
  kFailed,       // refused or failed (a sweep's run: its reason says why)
  kInterrupted,  // stopped by a stop request (AdvanceOptions::stop, Ctrl-C)
  kNotRun,       // never started: its sweep was stopped first
};

// How a call of Advance ended.
struct AdvanceResult {
  using Status = RunStatus;  // kComplete, kDiverged or kInterrupted
  Status status = Status::kComplete;
  std::optional<Divergence> divergence;
  // Set when the total energy of an undriven scene grew beyond
  // kEnergyGrowthTolerance: how much, and when it was largest.
  std::optional<std::string> energy_growth;
  // With the auto timestep: the steps taken, and those at a contact's fine step.
  long steps = 0;
  long fine_steps = 0;
  // s: AutoTimestep::finest_step(), a fixed step as fine as the finest
  // step the rules asked for (infinite when no contact came near)
  double finest_step = 0;
};

// Steps sim from its current time until options.duration (or the first
// episode's end), calling on_row with Simulation::Sample() at every time
// k / sample_rate on the way, t = 0 included. Stops at divergence (the rows
// given so far are finite) and when options.stop is set. Checks the energy
// ledger of undriven scenes at every row and at the end.
AdvanceResult Advance(Simulation* sim, const AdvanceOptions& options,
                      const std::function<void(const std::vector<double>&)>& on_row);

}  // namespace contactlaws

#endif  // CONTACTLAWS_SIMULATION_H_
