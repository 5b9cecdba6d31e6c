// Copyright contactlaws authors.
//
// ContactStepper: the contacts of one step integrated inside it
// (docs/timestep.md, "Contact steps"). At the step's start, for the points
// in contact or within reach of the step (PointEvaluator collects both), it
// takes the normal Jacobians J (one row per point), the contact-space
// inverse inertia A = J M^-1 J^T (mj_solveM) and the free contact-space
// acceleration b = J M^-1 (the forces other than the laws' normal ones),
// then integrates each point's depth and depth rate over the step with the
// laws' own forces, in sub-steps of its own (classical RK4, a touch
// ending a sub-step), the configuration frozen, the configuration frozen. The step's normal
// impulse P acts on the bodies as the constant generalized force -J^T P / h
// (ApplyForce); after the step the positions are moved onto the inner
// trajectory (CorrectPositions). The sub-samples are kept as evaluations
// (samples()) for the step committer: episodes, impacts and the ledger see
// the contact at the inner resolution.

#ifndef CONTACTLAWS_MUJOCO_CONTACT_STEPPER_H_
#define CONTACTLAWS_MUJOCO_CONTACT_STEPPER_H_

#include <vector>

#include <mujoco/mujoco.h>

#include "contactlaws/contact_data.h"
#include "contactlaws/contact_model.h"
#include "contactlaws/point_evaluation.h"

namespace contactlaws::internal {

// One sub-sample of the inner integration: the points in contact at time.
struct InnerSample {
  double time = 0;  // s
  std::vector<PointEvaluation> points;
  std::vector<int> ids;  // per point: its inner point (ContactStepper), 0..
};

class ContactStepper {
 public:
  // model must outlive this object.
  explicit ContactStepper(const ContactModel& model);

  void set_options(const ContactStepsOptions& options) { options_ = options; }
  const ContactStepsOptions& options() const { return options_; }
  bool enabled() const { return options_.enabled(); }

  // How far (m) pair's surfaces can close within a step of h s at d's state
  // (cvel current): the narrowphase margin of the points kept as near.
  double Reach(const mjData* d, const GeomPair& pair, double h) const;

  // Forgets the points of the previous evaluation.
  void Clear() { near_.clear(); }
  // A point of pair within reach but not in contact (con.dist >= 0).
  void AddNear(const mjData* d, int pair, const mjContact& con);

  // At the step's start (m: the model as stepped, its timestep h): integrates
  // touching (the evaluator's points in contact, their episodes matched) and
  // the near points over the step, keeps the samples, and adds the step's
  // mean normal force to d->qfrc_passive.
  void Integrate(const mjModel* m, mjData* d, const std::vector<PointEvaluation>& touching);
  // Adds the force Integrate found again (an RK4 stage of the same step).
  void ApplyForce(const mjModel* m, mjData* d) const;
  // After the step: moves d->qpos onto the inner trajectory (no-op when the
  // step had no points).
  void CorrectPositions(const mjModel* m, mjData* d) const;
  // Drops the step's samples (committed, or a step refused).
  void Spend() { samples_used_ = 0; active_ = false; }

  // The step's sub-samples, the first the step's start state (touching).
  const std::vector<InnerSample>& samples() const { return samples_; }
  // The committer sets each sample's episodes (mutable for it).
  std::vector<InnerSample>& samples() { return samples_; }
  int point_count() const { return static_cast<int>(points_.size()); }
  int sample_count() const { return samples_used_; }
  // The rate of inner point id at sample k (m/s): a separation's speed.
  double Rate(int k, int id) const { return rates_[k * points_.size() + id]; }
  // The inner point of pair at pos, or -1.
  int FindPoint(int pair, const double pos[3]) const;
  // The episode of inner point id when the step started (-1: none).
  int StartEpisode(int id) const { return points_[id].episode; }
  // The largest angle (rad) a body with points turned within one step, at
  // its start's spin, and the time of that step's start: how far the frozen
  // configuration was from the step's end.
  double worst_turn() const { return worst_turn_; }
  double worst_turn_time() const { return worst_turn_time_; }
  // The sub-steps the last Integrate took (its touches split some).
  int substeps() const { return substeps_; }

 private:
  // Sub-steps for the step of h s: options_.substeps, or each point's elastic
  // duration and its damper's lag over the per-contact counts.
  int SubSteps(double h) const;
  // One RK4 sub-step of the points' depths and rates (b - A f(d, d')), from
  // the forces at its start; adds to impulse_ and impulse_sum_.
  void Rk4SubStep(double step, const std::vector<double>& start_force,
                  const std::vector<double>& v0, std::vector<double>* depth,
                  std::vector<double>* rate);
  // J rows, M^-1 J^T, A, b at d's state.
  void BuildContactSpace(const mjModel* m, mjData* d);

  const ContactModel& model_;
  ContactStepsOptions options_;
  std::vector<PointEvaluation> near_;   // AddNear's points, as evaluations
  std::vector<PointEvaluation> points_; // this step's points: touching, then near
  std::vector<double> mass_;       // per point: 1 / A_ii, kg
  std::vector<double> j_;          // points x nv: J_i, d' = J_i qvel (+ drives)
  std::vector<double> minv_jt_;    // points x nv: M^-1 J_i^T
  std::vector<double> a_;          // points x points
  std::vector<double> b_;          // per point, m/s^2
  std::vector<double> a_free_;     // nv: M^-1 (forces but the normal laws')
  std::vector<double> impulse_;    // per point: P at the step's end, N s
  std::vector<double> impulse_sum_;  // per point: delta * sum_k P_k, N s^2
  std::vector<double> force_;      // nv: the generalized force added
  std::vector<double> rates_;      // samples x points
  std::vector<double> stage_;      // Rk4SubStep's stages
  std::vector<InnerSample> samples_;
  int samples_used_ = 0;
  int substeps_ = 0;
  double h_ = 0;
  double worst_turn_ = 0;
  double worst_turn_time_ = 0;
  bool active_ = false;  // Integrate found points this step
};

}  // namespace contactlaws::internal

#endif  // CONTACTLAWS_MUJOCO_CONTACT_STEPPER_H_
