// Copyright contactlaws authors.
//
// ContactData: the laws acting on one mjData.
//
// While a ContactData exists, MuJoCo's global hooks are ours (installed by the
// first ContactData, the callbacks found before restored when the last one is
// destroyed):
//   mjcb_contactfilter  discards the tagged geom pairs of this data's model
//                       (MuJoCo makes no constraint for them), records them
//                       as proposed by the broadphase, and applies MuJoCo's
//                       own rule, or the callback found before, to every
//                       other pair;
//   mjcb_passive        runs MuJoCo's narrowphase on each tagged pair the
//                       broadphase proposed (so the cost grows with the pairs
//                       near each other, not with all tagged pairs), evaluates
//                       the pair's law at each contact point and adds the force
//                       to qfrc_passive (after the callback found before).
// An mjData with no ContactData is left entirely to MuJoCo.
//
// The hooks are pure functions of the state they are given (RK4 calls the
// passive hook four times a step): the per-contact memory (impact velocity v0,
// episode, energy) is committed once per accepted step, from the evaluation
// at the step's start state, by AfterStep(). A user's loop is therefore
//
//   contactlaws::ContactData contacts(contact_model, d);
//   while (...) contacts.Step();      // BeforeStep(); mj_step(m, d); AfterStep();
//
// mj_resetData (the time going back) is noticed by the next BeforeStep, which
// then forgets the per-contact memory; after any other jump of the state, call
// Reset(). After each step, divergence() says whether the run can go on.

#ifndef CONTACTLAWS_CONTACT_DATA_H_
#define CONTACTLAWS_CONTACT_DATA_H_

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "contactlaws/contact_model.h"

namespace contactlaws {

// One contact episode of one contact point: first touch to separation.
struct Impact {
  int tag = -1;             // ContactModel::tags() index
  int pair = -1;            // ContactModel::pairs() index
  int index = 0;            // 1 for the tag's first episode, 2 for its second ...
  double time_contact = 0;  // s, extrapolated to d = 0
  // d' of the last state before first touch, m/s (> 0): the approach no
  // contact force has slowed yet (a fixed step finds a contact a fraction of
  // a step late, when a force that jumps at d = 0+ has acted for part of it)
  double impact_velocity = 0;
  bool open = true;               // still in contact
  double time_separation = 0;     // s, extrapolated to d = 0 (closed only)
  double separation_velocity = 0; // -d' of the first state after it, m/s (closed only)
  double max_depth = 0;           // m
  double max_force = 0;           // N
  // separation / impact depth rate (closed only)
  double restitution_post() const { return separation_velocity / impact_velocity; }
};

// qfrc += J^T force for a world-frame force at a world point fixed to body:
// what mj_applyFT(m, d, force, 0, point, body, qfrc) adds, walking only the
// dofs of the body's chain (O(depth of the tree), not O(nv)). Needs cdof and
// subtree_com (mj_comPos; current inside the hooks).
void AddPointForce(const mjModel* m, const mjData* d, int body, const mjtNum point[3],
                   const mjtNum force[3], mjtNum* qfrc);

// Why a run cannot go on: found by AfterStep, kept until Reset().
struct Divergence {
  enum class Kind {
    kNonFinite,     // NaN or infinity in qpos, qvel, qacc or a contact force
    kMujocoReset,   // MuJoCo found a bad qpos/qvel/qacc and reset the data
    kTooDeep,       // a contact deeper than its pair's depth_limit
  };
  Kind kind = Kind::kNonFinite;
  double time = 0;       // s: the start of the step that diverged
  // The deepest tagged contact at that state, relative to its limit (-1: none
  // in contact), its depth and depth rate.
  int pair = -1;
  double depth = 0;        // m
  double depth_rate = 0;   // m/s
  std::string what;        // one phrase: "depth 0.06 m beyond 0.05 m (half ...)"
};

// The latest evaluation of one tag: its deepest contact point, and the sum of
// the forces of all its points.
struct TagReading {
  double depth = 0;       // m, 0 when out of contact
  double depth_rate = 0;  // m/s, 0 when out of contact
  double force = 0;       // N
};

class ContactData {
 public:
  // model must describe d's mjModel and outlive this object.
  ContactData(const ContactModel& model, mjData* d);
  ~ContactData();

  ContactData(const ContactData&) = delete;
  ContactData& operator=(const ContactData&) = delete;

  // One accepted step: BeforeStep(); mj_step(m, d); AfterStep(). An mjData
  // stepped with plain mj_step gets one MuJoCo warning (mju_warning) after a
  // few steps: its contacts then have no memory.
  void Step();

  // Moves driven (mocap) bodies to their prescribed pose at d->time and arms
  // the capture of the step's first hook evaluation.
  void BeforeStep();

  // Commits the per-contact memory from the evaluation captured at the step's
  // start state.
  void AfterStep();

  // Forgets every episode, the energy ledger and any divergence. BeforeStep
  // calls it when the time has gone back (mj_resetData).
  void Reset();

  // Set by the AfterStep that found the state diverged; the state is then
  // not to be trusted (MuJoCo may even have reset it).
  const std::optional<Divergence>& divergence() const { return divergence_; }

  const ContactModel& model() const { return model_; }
  mjData* data() const { return d_; }

  // Every contact episode so far, in order of first touch.
  const std::vector<Impact>& impacts() const { return impacts_; }

  // One contact point as the hook last saw it.
  struct Evaluation {
    int pair = -1;
    int slot = -1;     // absolute slot index (pair.first_slot + point)
    double depth = 0;
    double depth_rate = 0;
    double impact_velocity = 0;  // the law's v0 (floored)
    double touch_velocity = 0;   // new points: d' at the step before first touch
    double touch_power = 0;      // new points: the law's dissipated power at touch, W
    double force = 0;
    double elastic_energy = 0;
    double dissipated_power = 0;
    mjtNum pos[3] = {0, 0, 0};     // contact point, world frame
    mjtNum normal[3] = {0, 0, 0};  // from geom[0] to geom[1]
  };

  // The contact points of the latest hook evaluation (depth > 0).
  const std::vector<Evaluation>& latest() const { return latest_; }

  // The tagged pairs the last collision pass proposed (what ApplyForces
  // evaluates), in pair order.
  const std::vector<int>& proposed_pairs() const { return proposed_; }

  // The latest hook evaluation (call mj_forward first for the current state).
  TagReading Reading(int tag) const;
  double ElasticEnergy() const;   // J, latest evaluation
  // J, integrated (trapezoid) over committed steps, up to the latest evaluation
  double DissipatedEnergy() const;

  // Called by the contact filter hook for each pair the broadphase proposes:
  // true, and recorded for ApplyForces, when the pair is tagged. O(1); no
  // allocation.
  bool ClaimPair(int g1, int g2);

  // Called by the passive hook: adds the laws' forces to d->qfrc_passive for
  // the tagged pairs the last collision pass proposed (the same pairs again
  // when the pass was skipped, e.g. mj_forwardSkip past positions).
  void ApplyForces();

  // World-frame velocity of a point fixed to body (driven bodies: their
  // prescribed motion). Needs cvel (mj_forward, or inside the hooks).
  void PointVelocity(int body, const mjtNum point[3], mjtNum vel[3]) const;

 private:

  // jn = (J1 - J0)^T n at point (nv entries): the normal relative velocity
  // of pair's bodies per dof.
  void NormalJacobian(const GeomPair& pair, const mjtNum point[3], const mjtNum normal[3],
                      mjtNum* jn);
  // 1 / (n^T J M^-1 J^T n) at a point, for the two bodies of pair.
  double EffectiveMass(const GeomPair& pair, const mjtNum point[3],
                       const mjtNum normal[3]);
  // d' at point along normal for the velocities qvel (at time, for driven
  // bodies), with the current configuration's Jacobians.
  double ApproachRate(const GeomPair& pair, const mjtNum point[3], const mjtNum normal[3],
                      const mjtNum* qvel, double time);
  void ApplyDrives();
  double Power(const std::vector<Evaluation>& evaluations) const;
  // AfterStep's checks: sets divergence_ when the step diverged.
  void CheckDivergence();

  const ContactModel& model_;
  const mjModel* m_;
  mjData* d_;

  // What AfterStep needs of an open episode beyond Impact.
  struct Track {
    int slot = -1;
    int64_t last_commit = -1;  // the commit that last saw it in contact
    double last_time = 0;
    double last_depth = 0;
    double last_rate = 0;
    mjtNum last_pos[3] = {0, 0, 0};
    mjtNum last_normal[3] = {0, 0, 0};
  };

  std::vector<mjContact> contacts_;   // narrowphase output, mjMAXCONPAIR
  // tagged pairs proposed by the broadphase (ClaimPair), for ApplyForces
  std::vector<int> proposed_;
  std::vector<uint8_t> is_proposed_;  // per pair
  bool proposals_sorted_ = true;
  bool proposals_consumed_ = true;  // ApplyForces used the list
  std::vector<Evaluation> latest_;    // the hook's last evaluation
  double latest_time_ = 0;
  std::vector<Evaluation> captured_;  // the evaluation at the step's start
  double captured_time_ = 0;
  bool capture_armed_ = false;
  bool has_capture_ = false;
  // plain mj_step detection: evaluations at a later time with no step armed
  static constexpr int kUnarmedAdvancesBeforeWarning = 8;
  int advances_unarmed_ = 0;
  bool unmanaged_ = false;

  std::vector<int> slot_impact_;  // slot -> index of its open impact, or -1
  std::vector<int> open_;         // indices of open impacts
  std::vector<int> tag_count_;    // episodes per tag
  std::vector<Impact> impacts_;
  std::vector<Track> tracks_;     // parallel to impacts_
  int64_t commits_ = 0;

  // qvel at the start of this step and of the one before (BeforeStep): the
  // rates just before a contact begins and just after it ends, which no
  // contact force has touched
  std::vector<mjtNum> current_qvel_;
  std::vector<mjtNum> previous_qvel_;
  double current_time_ = 0;
  double previous_time_ = 0;
  bool has_current_ = false;
  bool has_previous_ = false;

  // MuJoCo's bad-state warning counts at BeforeStep: a rise means mj_step
  // found NaN/huge values and reset the data
  std::array<int, 3> bad_state_warnings_ = {0, 0, 0};
  std::optional<Divergence> divergence_;

  // energy ledger
  bool has_committed_ = false;
  double committed_time_ = 0;
  double committed_power_ = 0;
  double dissipated_ = 0;
};

}  // namespace contactlaws

#endif  // CONTACTLAWS_CONTACT_DATA_H_
