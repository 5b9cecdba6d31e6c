// Copyright contactlaws authors.
//
// ContactStepper: the contacts of one step integrated inside it
// (docs/timestep.md, "Contact steps"). At the step's start, for the points
// in contact or within reach of the step (PointEvaluator collects both), it
// takes the contact-space rows J (one normal row per point, and two
// tangential ones for a point whose pair has friction), the contact-space
// inverse inertia A = J M^-1 J^T (mj_solveM) and the free contact-space
// acceleration b = J M^-1 (the forces other than the laws' and the
// tangential friction), then integrates each point's depth and depth rate,
// and its tangential displacement and slip, over the step with the laws' own
// forces and the pair's friction model at the same sub-step's normal force,
// in sub-steps of its own (classical RK4, a touch ending a sub-step; the
// stick springs of coulomb and stribeck, and the normal force of a point at
// rest, by backward Euler: ImplicitRows), the configuration frozen. The friction's memory (stick spring or bristles) is
// committed at every sub-sample, as a step's start commits it. The step's
// impulse P acts on the bodies as the constant generalized force -J^T P / h
// (ApplyForce); after the step the positions are moved onto the inner
// trajectory (CorrectPositions). The sub-samples are kept as evaluations
// (samples()) for the step committer: episodes, impacts, the friction state
// and the ledger see the contact at the inner resolution.

#ifndef CONTACTLAWS_MUJOCO_CONTACT_STEPPER_H_
#define CONTACTLAWS_MUJOCO_CONTACT_STEPPER_H_

#include <vector>

#include <mujoco/mujoco.h>

#include "contactlaws/friction.h"

#include "contactlaws/contact_data.h"
#include "contactlaws/contact_model.h"
#include "contactlaws/impact.h"
#include "mujoco/step_pairs.h"

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
  // (cvel current): kStepReachFactor times its start's closing speed (and
  // spins) and gravity over the step; the narrowphase margin of the points
  // kept as near.
  double Reach(const mjData* d, const GeomPair& pair, double h) const;

  // The tagged pairs the evaluations of a step of h s cover (StepPairs): at
  // its start (start) those that can touch within it, found at d's state;
  // the same list for its later evaluations (RK4's stages).
  const std::vector<int>& Pairs(const mjData* d, double h, bool start) {
    return start ? step_pairs_.Find(d, h) : step_pairs_.pairs();
  }

  // Forgets the points of the previous evaluation.
  void Clear() { near_.clear(); }
  // Forgets the previous steps (a reset): which episodes were calm.
  void Forget() {
    calm_.clear();
    end_.clear();
    previous_end_.clear();
  }
  // A point of pair within reach but not in contact (con.dist >= 0), of
  // weight (PointEvaluation::weight).
  void AddNear(const mjData* d, int pair, const mjContact& con, double weight,
               const mjtNum gradient[3]);

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
  // After every step: its points' end rates (none when Integrate did not run
  // in it) become EndRate's.
  void Committed() {
    previous_end_.swap(end_);
    end_.clear();
  }
  // Drops the step's samples (committed, or a step refused).
  void Spend() { samples_used_ = 0; active_ = false; }

  // The step's sub-samples, the first the step's start state (touching).
  const std::vector<InnerSample>& samples() const { return samples_; }
  // The committer sets each sample's episodes (mutable for it).
  std::vector<InnerSample>& samples() { return samples_; }
  int point_count() const { return static_cast<int>(points_.size()); }
  int sample_count() const { return samples_used_; }
  // The rate of inner point id at sample k (m/s): a separation's speed.
  double Rate(int k, int id) const { return rates_[static_cast<size_t>(k) * rows_ + id]; }
  // The inner point of pair at pos, or -1.
  int FindPoint(int pair, const double pos[3]) const;
  // The depth rate (m/s) at the end of the step before this one of its inner
  // point of pair at pos, in *rate: the speed a point that separated in that
  // step's last sub-step left with, which the bodies' velocity at a material
  // point no longer under the contact misreads (a ball spinning at w, its
  // contact point moved v_t h on: by w v_t h). False when that step had no
  // such point.
  bool EndRate(int pair, const double pos[3], double* rate) const;
  // The episode of inner point id when the step started (-1: none).
  int StartEpisode(int id) const { return points_[id].episode; }
  // The largest angle (rad) a body with points turned within one step, at
  // its start's spin, and the time of that step's start: how far the frozen
  // configuration was from the step's end.
  double worst_turn() const { return worst_turn_; }
  double worst_turn_time() const { return worst_turn_time_; }
  // the first step's time (s) that turned beyond kFrozenTurnWarning, or -1
  double first_far_turn_time() const { return first_far_turn_time_; }
  // The sub-steps the last Integrate took (its touches split some).
  int substeps() const { return substeps_; }
  // J: what the laws' damping dissipated over the last Integrate's sub-steps
  // but its last by RK4's own weights on its stages, less the trapezoid of
  // the sub-samples' power that the ledger books over them
  // (DissipationLedger), for the normal rows RK4 takes (not a resting
  // point's): the trapezoid is
  // second order in the sub-step, RK4's quadrature fourth. At 20 sub-steps
  // per contact the trapezoid left 2.6e-3 J of box_stack.xml's top cube's
  // landing unbooked (0.75% of what it dissipated).
  double dissipation_correction() const { return dissipation_correction_; }
  // The step's last sub-step of inner point id, whose trapezoid the ledger
  // ends at the next step's start, at the evaluator's point there (a face
  // patch's, clipped again, is another point of another weight than the
  // rows' own end: taken from the rows, the correction raised a tilted
  // lid's total at 1e-5 s by 2e-5 J): RK4's quadrature of its power less
  // the trapezoid's half at the sub-step's start (J), and half the
  // sub-step (s). False when RK4 did not take it (out of contact at the
  // sub-step's start, or resting).
  bool LastSubStep(int id, double* energy, double* half_step) const;

 private:
  // The friction's memory of a point within the step: its state at the last
  // sub-sample (the stick spring or LuGre's z, world frame; k_t; sliding)
  // and its tangential displacement then (row coordinates, m).
  struct FrictionMemory {
    double spring[3] = {0, 0, 0};
    double stiffness = 0;
    bool sliding = false;
    double at[2] = {0, 0};
  };

  // Sub-steps for the step of h s: options_.substeps, or each point's elastic
  // duration (an impact's, or the vibration's of a point that stays in
  // contact) and its dampers' lag (normal and tangential), and each friction
  // point's tangential period, over the per-contact counts; the couplings
  // weighed by the points' weights.
  // Sets row_sum_. A point out of contact sets none (TouchSubStep).
  int SubSteps(double h);
  // The sub-step of point i touching at speed within the step (out of
  // contact at its start: SubSteps left it out): its impact's duration over
  // the per-contact count, and its damper's lag at the impact's deepest;
  // infinity with a fixed count of sub-steps (options_.substeps).
  double TouchSubStep(int i, double speed) const;
  // RK4's first stage at t0 s into the step, from x, rate and the forces
  // start_force (stage_, stage_spread_): its acceleration foresees the
  // sub-step's touches before Rk4SubStep takes it.
  void Rk4Start(double t0, const std::vector<double>& start_force, const std::vector<double>& x,
                const std::vector<double>& rate);
  // One RK4 sub-step (Rk4Start's first stage), starting t0 s into the step, of the rows' positions
  // and rates (b - A f(x, x'), and the terms of the moving J:
  // Acceleration), from the forces at its start; adds to impulse_ and
  // impulse_sum_.
  void Rk4SubStep(double t0, double step, const std::vector<double>& start_force,
                  const std::vector<double>& v0, std::vector<double>* x,
                  std::vector<double>* rate);
  // The friction of point i (its pair's model, against memory_[i]) at normal
  // force fn and v0, at x and rate (all rows: its depth and depth rate, its
  // displacement and slip): the tangential force on body[1] (world) and the
  // state to commit; slip gets the slip (world), stiffness k_t.
  FrictionOutput Friction(int i, double fn, double v0, const double* x, const double* rate,
                          double slip[3], double* stiffness, double* damping = nullptr) const;
  // After Rk4SubStep of step s (the held rows' forces at start_force):
  // backward Euler on the normal rows of the resting points and the
  // tangential rows of coulomb and stribeck points, those acting (in contact
  // at the sub-step's start), each force linear in its spring and damper
  // (about the end state; a resting point's about the sub-step's start);
  // moves x, rate, impulse_ and impulse_sum_ by the change of force.
  void ImplicitRows(double step, const std::vector<char>& acting,
                    const std::vector<double>& start_force, const std::vector<double>& v0,
                    std::vector<double>* x, std::vector<double>* rate);
  // Before ImplicitRows, in a sub-step whose points in contact all rest:
  // moves x (and rest_shift_) by the displacement that makes the sub-step
  // backward Euler's, x1 = x0 + step x1', along their rows (the normal ones,
  // and a stick spring's tangential ones), in the dofs of their trees.
  void RestingShift(const mjModel* m, double step, const std::vector<char>& acting,
                    std::vector<double>* x);
  // RestingShift's shift (nv) of the trees of dofs dofs, replaced by the
  // nearest (in M's norm) that moves the resting rows of acting points as
  // much and nothing else.
  void ProjectOntoRestingRows(const std::vector<char>& acting, int dofs,
                              std::vector<double>* shift);
  // The solve of ImplicitRows' pass for its rows solve_ (gains gain_):
  // (K^-1 + A_SS) f_S = K^-1 g_S + A_SS f0_S - A_SL delta_L in the rows
  // (SolveInRows), or, with z = M^-1 J_H^T delta_H the held rows' velocity
  // change per second, (M + J_S^T K J_S) z = J_S^T (g_S - f0_S) + J_L^T
  // delta_L in the dofs of the rows' trees and f_S = g_S - K J_S z
  // (SolveInDofs; M is block diagonal over the trees, so M restricted to
  // them is exact); f gets f_S. False when the system is not positive
  // definite.
  bool SolveInRows(const std::vector<int>& held, const std::vector<double>& start_force,
                   double* f);
  bool SolveInDofs(const std::vector<int>& held, const std::vector<double>& start_force,
                   double* f);
  // The dofs of the trees of the rows of solve_ (marked in root_marked_),
  // their count.
  int MarkTrees();
  // J rows, M^-1 J^T, A's diagonal, b at d's state.
  void BuildContactSpace(const mjModel* m, mjData* d);
  // A_ij = J_i M^-1 J_j^T, over J_i's nonzero entries.
  double Coupling(int i, int j) const;
  // out = M^-1 J^T c (nv) for the rows' coefficients c (zeros skipped).
  void Spread(const double* c, double* out) const;
  // J' of every row (AddPointJacobianRate; two spheres' turning normal), J'
  // v0 added to b, b1. Over the step J moves to J + J' t (a spinning body's
  // contact points, two spheres sliding past each other): x' = J(t) v(t),
  // so to first order in J'
  //   x'' = b + t b1 - (A + t C) f - D P(t),  b1 = 2 J' a_free,
  //   C = D + D^T,  D = J' M^-1 J^T,  P(t) the impulse so far,
  // and the bodies take f along J(t): -(J^T P + J'^T Q) / h. The frozen J
  // alone left the force's work and the depth's change apart by f J' v h^2
  // / 2 a step, an error of order h (a box landing on a corner lost 4.5e-3
  // of its energy at 1e-4 s, 3.6% at 1 ms, unbooked); J' in the applied
  // force alone, without its terms here, made the bodies' kinetic energy
  // and the law's work part by P^2 (A(t_c) - A) / 2 (a spinning die at 2
  // ms gained 2.5e-4 J in a step).
  void BuildJacobianRates(const mjModel* m, mjData* d);
  // The rate (rad/s) at which point e's rows turn at d's state: its bodies'
  // largest spin; two spheres' |v_t| / s.
  double RowTurn(const mjModel* m, const mjData* d, const PointEvaluation& e) const;
  // The rows' forces f in the dofs: u = M^-1 J^T f and, with J', w =
  // M^-1 J'^T f (nv each); with base (forces whose u and w are base_u and
  // base_w), through f - base: only the rows whose force differs.
  void SpreadForces(const double* f, const double* base, const double* base_u,
                    const double* base_w, double* u, double* w);
  // acc = b + t b1 - (A + t C) f - D P (BuildJacobianRates; without J',
  // b - A f) for the rows' forces f and impulse P at t s into the step,
  // through the dofs: A f = J u, t C f = t (J' u + J w), D P = J' p with u
  // and w f's (SpreadForces) and p = M^-1 J^T P (u, w, p: nv; w and p read
  // with J' only): a row's nonzero entries, where A, C and D are rows x
  // rows.
  void Acceleration(double t, const double* u, const double* w, const double* p, double* acc);

  // The nonzero entries of a rows x nv matrix, row by row.
  struct SparseRows {
    std::vector<int> start;  // per row, and its end: its first entry
    std::vector<int> column;
    std::vector<double> value;
    // from the rows x nv matrix dense, whose rows have bound nonzero
    // entries at most in all
    void Assign(const double* dense, int rows, int nv, size_t bound);
    bool empty(int row) const { return start[row] == start[row + 1]; }
    // row . v
    double Dot(int row, const double* v) const {
      double dot = 0;
      for (int e = start[row]; e < start[row + 1]; ++e) dot += value[e] * v[column[e]];
      return dot;
    }
    // out += scale row
    void AddTo(int row, double scale, double* out) const {
      for (int e = start[row]; e < start[row + 1]; ++e) out[column[e]] += scale * value[e];
    }
  };

  const ContactModel& model_;
  ContactStepsOptions options_;
  StepPairs step_pairs_;
  std::vector<PointEvaluation> near_;   // AddNear's points, as evaluations
  std::vector<PointEvaluation> points_; // this step's points: touching, then near
  // rows: points' normal rows 0..n-1 (x = depth, x' = d'), then two per
  // friction point (x = body[1]'s displacement relative to body[0] along
  // the tangents since the step's start, x' = the slip along them)
  int rows_ = 0;
  std::vector<int> tangent_row_;   // per point: its first tangential row, or -1
  std::vector<double> tangents_;   // per point: t1, t2 (world, 6)
  std::vector<double> anchor_turn_;  // per point: body[0]'s xmat at the start (9)
  std::vector<FrictionMemory> memory_;  // per point
  std::vector<double> mass_;       // per point: 1 / A_ii of its normal row, kg
  int nv_ = 0;                     // the model's dofs
  std::vector<double> j_;          // rows x nv: x' = J_r qvel (+ drives)
  std::vector<double> minv_jt_;    // rows x nv: M^-1 J_r^T
  // the nonzero entries of J, M^-1 J^T, J' and M^-1 J'^T: a row moves the
  // dofs of its two bodies' trees only, and few of those (a free body's
  // translations across a normal: none)
  SparseRows j_rows_, minv_jt_rows_, jdot_rows_, minv_jdt_rows_;
  std::vector<double> a_diag_;     // per row: A_rr
  std::vector<double> b_;          // per row, m/s^2
  std::vector<double> a_free_;     // nv: M^-1 (forces but the contacts')
  std::vector<double> jdot_;       // rows x nv: J' of each row
  std::vector<double> minv_jdt_;   // rows x nv: M^-1 J'^T
  std::vector<double> b1_;         // per row: 2 J' a_free, m/s^3
  bool moving_ = false;            // some J' is not zero
  std::vector<char> velocity_only_;  // per point: its J' in b only (J' v0)
  std::vector<double> mass_matrix_;  // M at the step's start (MuJoCo's qM)
  std::vector<int> root_dofs_;     // per body: the dofs of the tree it roots
  size_t entries_bound_ = 0;       // the most nonzero entries of J (and alike)
  std::vector<int> row_point_;     // per row: its point
  // nv: Spread's out (ImplicitRows, the resting points), Acceleration's
  // u + t w and p + t u
  std::vector<double> spread_, spread_rate_, spread_impulse_;
  std::vector<char> root_marked_;  // per body: a tree of SolveInDofs' system
  std::vector<int> local_;         // per dof: its index in SolveInDofs' system, or -1
  std::vector<int> dofs_;          // SolveInDofs' dofs
  std::vector<int> columns_;       // SolveInDofs' local dofs of a row's entries
  std::vector<double> coefficients_;  // per row: Spread's coefficients
  std::vector<double> difference_;    // per row: SpreadForces' f - base
  // nv each: Rk4SubStep's M^-1 J^T f at its four stages, M^-1 J^T P at its
  // start and at a stage
  std::vector<double> stage_spread_;
  std::vector<double> start_force_;  // per row: the step's start forces (the resting test)
  // per row: f, the row's force with x'' = b - A f (normal: F_n; tangential:
  // minus the friction force on body[1] along the tangent)
  std::vector<double> impulse_;    // per row: P at the step's end, N s
  std::vector<double> impulse_sum_;  // per row: delta * sum_k P_k, N s^2
  std::vector<double> force_;      // nv: the generalized force added
  std::vector<double> rest_shift_; // nv: RestingShift's displacement over the step
  // ProjectOntoRestingRows' rows kept, their Cholesky factor (dofs x dofs),
  // envelope (none) and right-hand side
  std::vector<int> rest_rows_, rest_first_;
  std::vector<double> rest_factor_, rest_rhs_;
  std::vector<double> rates_;      // samples x rows
  std::vector<double> stage_;      // Rk4SubStep's stages
  std::vector<int> implicit_rows_; // ImplicitRows' rows
  std::vector<double> delta_;      // ImplicitRows' change of force, per row
  std::vector<double> g_;          // ImplicitRows' explicit change, g - f0
  std::vector<double> system_;     // ImplicitRows' matrix
  // ImplicitRows' rows solved for, their gains and caps, the system's
  // right-hand side and solution, the rows solved again
  std::vector<int> solve_, still_;
  std::vector<double> gain_, cap_, still_gain_, still_cap_, rhs_, solution_;
  std::vector<char> solved_;
  std::vector<int> envelope_;      // per row of ImplicitRows' matrix: its first nonzero
  std::vector<char> acting_;       // per point: in contact at the sub-step's start
  std::vector<char> resting_;      // per point: at rest (kRestingFraction)
  // per point: in contact through the step, vibrating (kSustainedFraction)
  std::vector<char> sustained_;
  // the episodes of the points at rest or sustained in the last step, and
  // this step's: a point rests only after a calm step
  std::vector<int> calm_, calm_next_;
  // per point: out of contact beyond what the step can close (left out of
  // its neighbours' Gershgorin sums)
  std::vector<char> out_of_reach_;
  std::vector<double> row_sum_;    // per point: SubSteps' Gershgorin sum, 1/kg
  std::vector<double> x_start_;    // per row: x at the sub-step's start
  std::vector<double> rate_start_; // per row: x' at the sub-step's start
  // A point of a step and its depth rate at the step's end: this step's
  // (end_) and the one's before (previous_end_, EndRate).
  struct PointEnd {
    int pair = -1;
    double pos[3] = {0, 0, 0};
    double rate = 0;
  };
  std::vector<PointEnd> end_, previous_end_;
  std::vector<InnerSample> samples_;
  int samples_used_ = 0;
  int substeps_ = 0;
  double dissipation_correction_ = 0;  // J (dissipation_correction)
  struct LastStaged {
    double energy = 0;     // J
    double half_step = 0;  // s, 0: not taken by RK4
  };
  std::vector<LastStaged> last_staged_;  // per point (LastSubStep)
  // Rk4SubStep's laws' dissipated power (W) of each point in contact at the
  // sub-step's start and not resting, at its stages 1-3 (3 per point)
  std::vector<double> stage_power_;
  double h_ = 0;
  double worst_turn_ = 0;
  double worst_turn_time_ = 0;
  double first_far_turn_time_ = -1;
  bool active_ = false;  // Integrate found points this step
};

}  // namespace contactlaws::internal

#endif  // CONTACTLAWS_MUJOCO_CONTACT_STEPPER_H_
