// Copyright contactlaws authors.

#include "mujoco/contact_stepper.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mujoco/kinematics.h"
#include "mujoco/vec3.h"

namespace contactlaws::internal {
namespace {

// A point's sub-step is at most this many lags of the dampers acting on it
// (its own and its coupled neighbours', Gershgorin's bound on the largest
// rate of A diag(c)): the auto timestep's rule 5 (docs/timestep.md).
constexpr double kSubStepLags = 1.0;

// A sub-step that meets a touch ends this fraction of it past the surface
// (inside the contact: d = 0+); none is shorter than kShortestSubStep of the
// touching point's own sub-step (TouchSubStep; a touch that close is taken
// at the sub-step's end), nor of the step's sub-step, which a point out of
// contact does not set (a touch 2 us into a 2 ms sub-step would be taken
// 5 um deep at 2.6 m/s).
constexpr double kPastTouch = 1e-6;
constexpr double kShortestSubStep = 1e-3;
// The inner integration ends within this fraction of the step.
constexpr double kEndTolerance = 1e-9;

// Friction models whose stick spring is integrated by backward Euler inside
// the sub-steps (ImplicitRows): the capped springs of coulomb and
// stribeck. LuGre's bristles and the regularized curve are taken by RK4 in
// sub-steps that resolve them.
bool Implicit(FrictionKind kind) { return ReadsTangentialSpring(kind); }

// A point in contact at the step's start rests when the amplitude of its
// vibration about its equilibrium, sqrt((d' / w)^2 + (d'' / w^2)^2) at its
// own rate w = sqrt(dF/dd A_ii), times w h where the step h is longer than
// 1 / w (how far that vibration carries the point within the step), is
// below this fraction of its depth: its normal force is then taken by
// backward Euler with the stick springs (ImplicitRows), linearized about
// the sub-step's start, and sets no sub-step. For F = K d^n that vibration
// holds at most n (n + 1) / 2 fraction^2 of the contact's elastic energy at
// rest (1.9% at n = 1.5), which backward Euler damps (unbooked), and the
// linearized force is off by n (n - 1) / 2 fraction^2 of itself at the
// vibration's extremes (0.4%). At an impact's peak (d' = 0 too) the
// amplitude is the depth. At 1e-2 and without the w h factor,
// box_stack.xml's stack (w h = 1.6), rocking at 1-10% of its depths from
// 0.3 s to 0.56 s, took 50 sub-steps a step there (13,500 in 5 s against
// 8,500); at 1e-1 without it, die_throw.xml's die (w h = 17) rocked on its
// four corners with friction, growing between one-sub-step steps from 2%
// to 50% of its depth (17,400 sub-steps against 8,400).
constexpr double kRestingFraction = 1e-1;

// A point in contact at the step's start that does not rest, but vibrates
// about its equilibrium (the resting test's amplitude, without the step's
// factor: the vibration's own reach) by less than kSustainedFraction of its
// depth, stays in contact through the step at depths below kSustainedDepth
// times its own: its sub-step is kSustainedTurn rad of its vibration's
// phase at the stiffness there, not a share of an impact's duration at its
// episode's speed v0 (per_contact_hertz of them, pi / 20 rad a sub-step).
// box_stack.xml's boxes, rocking in contact on each other's pushes, kept
// the pushes' sub-steps for as long as their contacts lasted. For
// F = K d^n the vibration's largest depth is below 1.5 times its own, where
// the stiffness n K d^(n-1) is below the one at kSustainedDepth; a
// vibration below half the depth is nearly linear, and RK4 at 0.25 rad a
// sub-step changes a linear vibration's energy by (w step)^6 / 72 = 3e-6
// of itself a sub-step. An impact's peak (d' = 0, d'' / w^2 = d / n) is
// above the fraction for n <= 2. Not a point whose rows turn by more than
// kMovingJacobianTurn within the step: the turn moves its equilibrium, and
// the amplitude at the start does not bound the step.
constexpr double kSustainedFraction = 0.5;
constexpr double kSustainedDepth = 2.0;
constexpr double kSustainedTurn = 0.25;

// A resting row is left out of ProjectOntoRestingRows' solve when all but
// this fraction of its A_ii lies in the span of the rows kept before it (a
// box's fourth corner on a plane: the three others span its dofs).
constexpr double kRestRowDependence = 1e-9;
// RestingShift takes the whole trees' shift, unprojected, where their
// acceleration is below this (m/s^2, rad/s^2): a body then moves less than
// h^2 a / 2 = 2e-8 m a 2 ms step off RK4's path (a stack at rest; the
// projection's solve cost box_stack.xml 11% of its instructions).
constexpr double kRestAcceleration = 1e-2;

// A point rests only if the step before found it calm (at rest, or
// vibrating within kSustainedFraction of its depth): the rule reads one
// point's vibration about its own equilibrium, and at the peak of a coupled
// strike every rate and the net force on each row are near zero at once (a
// 1 kg pendulum bob pressing a ball 2.8 mm into the floor). Rested there,
// backward Euler held the squeeze linear over the step while it released,
// and the ledger's total rose by 0.9 J (frictionless) or fell by 0.3 J.

// A point out of contact at the step's start sets no sub-step: the sub-step
// meets its touch (foreseen from the rows' acceleration at the sub-step's
// start: its neighbours' forces with b), and the rest of the step is
// divided again at the point's own (TouchSubStep). Taken from the step's
// start, the impact's sub-step was spent on the whole step: die_throw.xml's
// die, rocking on an edge with the other 0.25 mm above the floor, took 600
// sub-steps a step, of which the far edge touched in none. A point whose gap
// is wider than kStepReachFactor times what its start's approach rate and
// acceleration (b, and b - A f at the start's forces) close within the step
// is also left out of its neighbours' Gershgorin sums: it carries no force
// (the narrowphase keeps points within the bodies' reach, their spins and
// bounding radii: Reach, far wider than a point's own).

// The held rows of a sub-step (ImplicitRows) are taken by the trapezoid rule
// when they are all stick springs it resolves: each row's rate
// sqrt(k_t A_rr) and damper's c_t A_rr times the sub-step at most this.
// The trapezoid keeps a spring's energy (backward Euler takes
// (w step)^2 / 2 of it a sub-step, unbooked: 8e-5 of a tangential
// rebound's kinetic energy at t_c / 500), but does not damp a spring it
// does not resolve (it rings at the sub-step): resting points and stiff
// springs stay with backward Euler.
constexpr double kTrapezoidRate = 1.0;

// The largest turn (rad) of a point's rows within a step (its bodies' spin,
// two spheres' centres' line) for which the rows take J + J' t
// (BuildJacobianRates); beyond it the frozen J. At 3e-3 rad a step (a box
// landing on a corner at 1e-4 s) J' t took the ledger's error from 4.5e-3
// to 9e-5 of the energy; at 0.04 to 0.1 rad (a spinning die at 2 ms) the
// linear J(t) missed by (w h)^2 and the die gained 1.4e-4 J in a step,
// where the frozen J loses energy instead (unbooked; run warns beyond the
// same turn: kFrozenTurnWarning).
constexpr double kMovingJacobianTurn = kFrozenTurnWarning;

// An orthonormal tangent pair (t1, t2) of the unit normal n.
void TangentBasis(const double n[3], double t[6]) {
  // the world axis least along n, crossed with it
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(n[k]) < std::abs(n[axis])) axis = k;
  }
  double e[3] = {0, 0, 0};
  e[axis] = 1;
  mju_cross(t, n, e);
  mju_normalize3(t);
  mju_cross(t + 3, n, t);
}

// The energy the tangential spring (or LuGre's bristles) of state holds at
// stiffness k and normal force fn: FrictionOutput::stored_energy.
double TangentialEnergy(const FrictionParams& params, const FrictionState& state, double fn) {
  const double s2 = vec3::Dot(state.spring, state.spring);
  if (params.kind == FrictionKind::kLuGre) return 0.5 * fn * params.bristle_stiffness * s2;
  if (ReadsTangentialSpring(params.kind) && state.stiffness > 0) return s2 / (2 * state.stiffness);
  return 0;
}

// The time (s, in (0, limit]) at which a depth d <= 0 at rate r and
// acceleration b reaches 0: the first root of d + r t + b t^2 / 2, or limit.
// The roots as d / q and 2 q / b, q = -(r + sign(r) sqrt(r^2 - 2 b d)) / 2,
// which no b loses: the textbook (-r + sqrt(r^2 - 2 b d)) / b cancels to
// nothing for b near 0 (a ball 0.14 mm from another closing at 0.76 m/s at
// b = -7e-17 m/s^2 was found to touch at the end of the step, 1.4 mm deep).
double TimeToSurface(double d, double r, double b, double limit) {
  // at the surface and entering: now (a point placed touching, pushed in by
  // b from rest, was otherwise taken a whole sub-step later, 20 um deep)
  if (d == 0 && (r > 0 || (r == 0 && b > 0))) return 0;
  const double discriminant = r * r - 2 * b * d;
  if (discriminant < 0) return limit;
  const double q = -0.5 * (r + std::copysign(std::sqrt(discriminant), r));
  double first = limit;
  if (q != 0 && d / q > 0) first = std::min(first, d / q);
  if (b != 0 && 2 * q / b > 0) first = std::min(first, 2 * q / b);
  return first;
}

// The first time (s, in (0, limit]) at which a depth d <= 0 at rate r,
// acceleration a and jerk j (d'' = a + j t) is above 0, or infinity: the
// first crossing of the cubic d + r t + a t^2 / 2 + j t^3 / 6, looked for on
// each piece where it is monotone (between the roots of its rate).
double FirstCrossing(double d, double r, double a, double j, double limit) {
  const auto depth = [&](double t) { return d + t * (r + t * (a / 2 + t * j / 6)); };
  double ends[4] = {0, limit, limit, limit};
  int count = 1;
  // the rate's roots, r + a t + j t^2 / 2 = 0, inside (0, limit)
  double roots[2];
  int found = 0;
  if (j != 0) {
    const double discriminant = a * a - 2 * j * r;
    if (discriminant >= 0) {
      const double s = std::sqrt(discriminant);
      roots[0] = (-a - s) / j;
      roots[1] = (-a + s) / j;
      found = 2;
    }
  } else if (a != 0) {
    roots[0] = -r / a;
    found = 1;
  }
  std::sort(roots, roots + found);
  for (int k = 0; k < found; ++k) {
    if (roots[k] > 0 && roots[k] < limit) ends[count++] = roots[k];
  }
  ends[count++] = limit;
  for (int k = 1; k < count; ++k) {
    double lo = ends[k - 1], hi = ends[k];
    if (!(depth(hi) > 0)) continue;
    // bisection on a monotone piece whose start is not in contact
    for (int it = 0; it < 100 && hi - lo > kEndTolerance * limit * 1e-3; ++it) {
      const double mid = 0.5 * (lo + hi);
      (depth(mid) > 0 ? hi : lo) = mid;
    }
    return hi;
  }
  return std::numeric_limits<double>::infinity();
}

// The Cholesky factor L of the SPD n x n matrix s, in place (its lower
// triangle), each row from its first nonzero entry on (first; its envelope,
// which L keeps): the rows of points of bodies that share no chain are zero
// against each other. False when s is not positive definite.
bool EnvelopeCholesky(double* s, int n, std::vector<int>* first) {
  first->resize(n);
  for (int i = 0; i < n; ++i) {
    int f = 0;
    while (f < i && s[i * n + f] == 0) ++f;
    (*first)[i] = f;
  }
  for (int i = 0; i < n; ++i) {
    double* li = s + static_cast<size_t>(i) * n;
    for (int j = (*first)[i]; j <= i; ++j) {
      const double* lj = s + static_cast<size_t>(j) * n;
      double sum = li[j];
      for (int k = std::max((*first)[i], (*first)[j]); k < j; ++k) sum -= li[k] * lj[k];
      if (j < i) {
        li[j] = sum / lj[j];
      } else if (sum > 0) {
        li[i] = std::sqrt(sum);
      } else {
        return false;
      }
    }
  }
  return true;
}

// A step's point and a committed one are the same when their pair and
// position are: the configuration is frozen over the step, and a sample's
// points keep the step's positions.
bool SamePoint(int pair, const double pos[3], int other_pair, const double other_pos[3]) {
  return pair == other_pair && pos[0] == other_pos[0] && pos[1] == other_pos[1] &&
         pos[2] == other_pos[2];
}

// x with L L^T x = b (L from EnvelopeCholesky; its rows stride apart, n by
// default); x may be b.
void EnvelopeSolve(const double* l, int n, const std::vector<int>& first, const double* b,
                   double* x, int stride = 0) {
  if (stride == 0) stride = n;
  for (int i = 0; i < n; ++i) {
    const double* li = l + static_cast<size_t>(i) * stride;
    double sum = b[i];
    for (int k = first[i]; k < i; ++k) sum -= li[k] * x[k];
    x[i] = sum / li[i];
  }
  for (int i = n - 1; i >= 0; --i) {
    const double* li = l + static_cast<size_t>(i) * stride;
    x[i] /= li[i];
    for (int k = first[i]; k < i; ++k) x[k] -= li[k] * x[i];
  }
}

}  // namespace

void ContactStepper::SparseRows::Assign(const double* dense, int rows, int nv, size_t bound) {
  start.resize(rows + 1);
  if (column.size() < bound) {
    column.resize(bound);
    value.resize(bound);
  }
  int count = 0;
  for (int i = 0; i < rows; ++i) {
    start[i] = count;
    const double* row = dense + static_cast<size_t>(i) * nv;
    for (int k = 0; k < nv; ++k) {
      if (row[k] == 0) continue;
      column[count] = k;
      value[count++] = row[k];
    }
  }
  start[rows] = count;
}

ContactStepper::ContactStepper(const ContactModel& model) : model_(model), step_pairs_(model) {}

double ContactStepper::Reach(const mjData* d, const GeomPair& pair, double h) const {
  const mjModel* m = model_.model();
  mjtNum v[2][3];
  double spin = 0;
  for (int b = 0; b < 2; ++b) {
    PointVelocity(model_, d, pair.body[b], d->geom_xpos + 3 * pair.geom[b], v[b]);
    spin += mju_norm3(d->cvel + 6 * pair.body[b]) * m->geom_rbound[pair.geom[b]];
  }
  mjtNum relative[3];
  vec3::Sub(relative, v[1], v[0]);
  const double speed = mju_norm3(relative) + spin;
  return kStepReachFactor * (speed * h + mju_norm3(m->opt.gravity) * h * h);
}

void ContactStepper::AddNear(const mjData* d, int p, const mjContact& con, double weight,
                             const mjtNum gradient[3]) {
  PointEvaluation& e = near_.emplace_back();
  mjtNum v0[3], v1[3];
  ReadContactPoint(model_, d, p, con, &e, v0, v1);
  e.weight = weight;
  vec3::Copy(e.pos, con.pos);
  vec3::Copy(e.normal, con.frame);
  vec3::Copy(e.gradient, gradient);
  // the depth's rate along its gradient (PointEvaluator's), the slip in the
  // tangent plane
  vec3::Sub(e.slip, v1, v0);
  e.depth_rate = -vec3::Dot(e.slip, gradient);
  const double along = vec3::Dot(e.slip, con.frame);
  for (int k = 0; k < 3; ++k) e.slip[k] -= along * con.frame[k];
}

int ContactStepper::FindPoint(int pair, const double pos[3]) const {
  for (size_t i = 0; i < points_.size(); ++i) {
    if (SamePoint(points_[i].pair, points_[i].pos, pair, pos)) return static_cast<int>(i);
  }
  return -1;
}

bool ContactStepper::LastSubStep(int id, double* energy, double* half_step) const {
  if (id >= static_cast<int>(last_staged_.size()) || !(last_staged_[id].half_step > 0)) {
    return false;
  }
  *energy = last_staged_[id].energy;
  *half_step = last_staged_[id].half_step;
  return true;
}

bool ContactStepper::EndRate(int pair, const double pos[3], double* rate) const {
  for (const PointEnd& end : previous_end_) {
    if (SamePoint(end.pair, end.pos, pair, pos)) {
      *rate = end.rate;
      return true;
    }
  }
  return false;
}

void ContactStepper::BuildContactSpace(const mjModel* m, mjData* d) {
  const int nv = m->nv;
  const int n = static_cast<int>(points_.size());
  const int rows = rows_;
  nv_ = nv;
  j_.assign(static_cast<size_t>(rows) * nv, 0.0);
  minv_jt_.resize(j_.size());
  for (int i = 0; i < n; ++i) {
    const PointEvaluation& e = points_[i];
    const GeomPair& pair = model_.pairs()[e.pair];
    // NormalJacobian gives (J1 - J0)^T g, the separation rate along the
    // depth's gradient g (the hook's push: PointEvaluation::gradient): d' is
    // its opposite
    double* row = j_.data() + static_cast<size_t>(i) * nv;
    NormalJacobian(m, d, pair, e.pos, e.gradient, row);
    for (int k = 0; k < nv; ++k) row[k] = -row[k];
    // the tangential rows: body[1]'s velocity relative to body[0] along t1, t2
    const int r = tangent_row_[i];
    for (int j = 0; r >= 0 && j < 2; ++j) {
      NormalJacobian(m, d, pair, e.pos, tangents_.data() + 6 * i + 3 * j,
                     j_.data() + static_cast<size_t>(r + j) * nv);
    }
  }
  if (rows > 0) mj_solveM(m, d, minv_jt_.data(), j_.data(), rows);

  // the free acceleration: every force of the step's start but the laws'
  // normal ones and the tangential friction (the rolling and torsional
  // torques are in qfrc_passive); the actuators' at this state and ctrl
  // (mj_fwdActuation, which MuJoCo runs after this hook: its qfrc_actuator
  // is still the previous evaluation's, zero at a first step after a reset,
  // which lost a pushed box 150 N for a step); MuJoCo's constraints' as the
  // previous step left them
  mj_fwdActuation(m, d);
  std::vector<double> force(nv);
  mj_rne(m, d, 0, force.data());
  for (int k = 0; k < nv; ++k) {
    force[k] = d->qfrc_passive[k] + d->qfrc_applied[k] + d->qfrc_actuator[k] +
               d->qfrc_constraint[k] - force[k];
  }
  for (int b = 1; b < m->nbody; ++b) {
    const mjtNum* f = d->xfrc_applied + 6 * b;
    if (f[0] || f[1] || f[2] || f[3] || f[4] || f[5]) {
      mj_applyFT(m, d, f, f + 3, d->xipos + 3 * b, b, force.data());
    }
  }
  a_free_.resize(nv);
  mj_solveM(m, d, a_free_.data(), force.data(), 1);

  // each tree's dofs, and the most entries a row of J, M^-1 J^T, J' or
  // M^-1 J'^T can have: its two bodies' trees' dofs
  root_dofs_.assign(m->nbody, 0);
  for (int k = 0; k < nv; ++k) ++root_dofs_[m->body_rootid[m->dof_bodyid[k]]];
  entries_bound_ = 0;
  for (int i = 0; i < rows; ++i) {
    for (const int body : model_.pairs()[points_[row_point_[i]].pair].body) {
      entries_bound_ += root_dofs_[m->body_rootid[body]];
    }
  }
  // each row's nonzero entries in J and in M^-1 J^T
  j_rows_.Assign(j_.data(), rows, nv, entries_bound_);
  minv_jt_rows_.Assign(minv_jt_.data(), rows, nv, entries_bound_);
  a_diag_.resize(rows);
  b_.assign(rows, 0.0);
  mass_.assign(n, std::numeric_limits<double>::infinity());
  for (int i = 0; i < rows; ++i) {
    a_diag_[i] = Coupling(i, i);
    b_[i] = mju_dot(j_.data() + static_cast<size_t>(i) * nv, a_free_.data(), nv);
    if (i < n && a_diag_[i] > 0) mass_[i] = 1.0 / a_diag_[i];
  }
  // M (ImplicitRows' solve in the dofs)
  mass_matrix_.assign(d->qM, d->qM + m->nM);
}

double ContactStepper::Coupling(int i, int j) const {
  return j_rows_.Dot(i, minv_jt_.data() + static_cast<size_t>(j) * nv_);
}

void ContactStepper::Spread(const double* c, double* out) const {
  std::fill(out, out + nv_, 0.0);
  for (int j = 0; j < rows_; ++j) {
    if (c[j] != 0) minv_jt_rows_.AddTo(j, c[j], out);
  }
}

void ContactStepper::BuildJacobianRates(const mjModel* m, mjData* d) {
  const int nv = m->nv;
  const int n = static_cast<int>(points_.size());
  const int rows = rows_;
  jdot_.assign(static_cast<size_t>(rows) * nv, 0.0);
  velocity_only_.assign(n, 0);
  for (int i = 0; i < n; ++i) {
    const PointEvaluation& e = points_[i];
    const GeomPair& pair = model_.pairs()[e.pair];
    // a resting point keeps the frozen J: its rows are backward Euler's
    // (ImplicitRows), which take no J' (with it, the die of die_throw.xml at
    // rest began to rock after 1.5 s and took 470 sub-steps a step)
    if (resting_[i]) continue;
    // so does a point whose rows turn by more than kMovingJacobianTurn
    // within the step: the linear J + J' t is no better there. But one in
    // contact at the step's start that its rate moves by less than its
    // depth within the step (carried, not struck) keeps J' v0 in b, its contact point's
    // acceleration at the start's velocity (a body tipping about the point:
    // the centripetal r w^2): without it the die of die_throw.xml, tipping
    // over an edge at 5 rad/s, lifted the edge by r w^2 h^2 / 2 = 0.7 um a
    // step (twice its depth) and bounced on it at every step (10,800
    // sub-steps from 0.70 s to 0.85 s). Not for a point struck within the
    // step (out of contact, or its rate carrying it past its depth): the
    // impulse P then leaves the law's work and the bodies' energy apart by
    // P h J' v0 / 2 (a die thrown spinning gained 2e-5 J in a step, two
    // balls of InnerContactTest's box 8e-5 J)
    const bool far = RowTurn(m, d, e) * h_ > kMovingJacobianTurn;
    if (far && !(std::abs(e.depth_rate) * h_ < e.depth)) continue;
    velocity_only_[i] = far;
    // the normal row, d' = -(J1 - J0)^T n, at the points that carry the
    // depth (AddDepthJacobianRate): a sphere's centre, a capsule's segment
    // point, a cylinder's rim centre (the contact point rolls: no material
    // point), else the contact point (a vertex, an edge's or a face's point)
    double* row = jdot_.data() + static_cast<size_t>(i) * nv;
    bool spheres = true;
    for (int b = 0; b < 2; ++b) {
      const int g = pair.geom[b];
      spheres = spheres && m->geom_type[g] == mjGEOM_SPHERE;
      mjtNum direction[3];
      mju_scl3(direction, e.gradient, b == 0 ? 1.0 : -1.0);
      AddDepthJacobianRate(m, d, pair.body[b], g, e.pos, direction, row);
    }
    if (spheres) {
      // two spheres: the normal is their centres' line, which turns at
      // n' = v_t / s as they slide past each other (distance s, relative
      // tangential velocity v_t): -(J1 - J0)^T n' at the centres
      mjtNum between[3], turn[3], v[2][3];
      for (int b = 0; b < 2; ++b) {
        PointVelocity(model_, d, pair.body[b], d->geom_xpos + 3 * pair.geom[b], v[b]);
      }
      vec3::Sub(between, d->geom_xpos + 3 * pair.geom[1], d->geom_xpos + 3 * pair.geom[0]);
      vec3::Sub(turn, v[1], v[0]);
      const double along = vec3::Dot(turn, e.normal);
      const double distance = mju_norm3(between);
      for (int k = 0; k < 3 && distance > 0; ++k) {
        turn[k] = -(turn[k] - along * e.normal[k]) / distance;
      }
      if (distance > 0) {
        AddPointForce(m, d, pair.body[1], d->geom_xpos + 3 * pair.geom[1], turn, row);
        mju_scl3(turn, turn, -1);
        AddPointForce(m, d, pair.body[0], d->geom_xpos + 3 * pair.geom[0], turn, row);
      }
    }
    // the tangential rows: body[1]'s material point relative to body[0]'s
    const int r = tangent_row_[i];
    for (int j = 0; r >= 0 && j < 2; ++j) {
      double* tangential = jdot_.data() + static_cast<size_t>(r + j) * nv;
      for (int b = 0; b < 2; ++b) {
        mjtNum direction[3];
        mju_scl3(direction, tangents_.data() + 6 * i + 3 * j, b == 0 ? -1.0 : 1.0);
        AddPointJacobianRate(m, d, pair.body[b], e.pos, direction, tangential);
      }
    }
  }
  // x'' = J' v + J v' to first order in J' (contact_stepper.h, Rk4SubStep):
  // b gains J' v0, and b1 = 2 J' a_free per second
  for (int r = 0; r < rows; ++r) {
    if (!velocity_only_[row_point_[r]]) continue;
    double* row = jdot_.data() + static_cast<size_t>(r) * nv;
    b_[r] += mju_dot(row, d->qvel, nv);
    std::fill(row, row + nv, 0.0);
  }
  moving_ = false;
  b1_.assign(rows, 0.0);
  jdot_rows_.Assign(jdot_.data(), rows, nv, entries_bound_);
  for (int r = 0; r < rows; ++r) {
    if (jdot_rows_.empty(r)) continue;
    moving_ = true;
    b_[r] += jdot_rows_.Dot(r, d->qvel);
    b1_[r] = 2 * jdot_rows_.Dot(r, a_free_.data());
  }
  if (!moving_) return;
  // M^-1 J'^T, once a step, for D^T f = M^-1 J'^T f (Acceleration)
  minv_jdt_.resize(jdot_.size());
  mj_solveM(m, d, minv_jdt_.data(), jdot_.data(), rows);
  minv_jdt_rows_.Assign(minv_jdt_.data(), rows, nv, entries_bound_);
}

double ContactStepper::RowTurn(const mjModel* m, const mjData* d,
                               const PointEvaluation& e) const {
  const GeomPair& pair = model_.pairs()[e.pair];
  double rate = 0;
  for (const int body : pair.body) rate = std::max(rate, mju_norm3(d->cvel + 6 * body));
  if (m->geom_type[pair.geom[0]] == mjGEOM_SPHERE && m->geom_type[pair.geom[1]] == mjGEOM_SPHERE) {
    // the centres' line turns at |v_t| / s
    mjtNum v[2][3], slide[3], between[3];
    for (int b = 0; b < 2; ++b) {
      PointVelocity(model_, d, pair.body[b], d->geom_xpos + 3 * pair.geom[b], v[b]);
    }
    vec3::Sub(slide, v[1], v[0]);
    vec3::Sub(between, d->geom_xpos + 3 * pair.geom[1], d->geom_xpos + 3 * pair.geom[0]);
    const double along = vec3::Dot(slide, e.normal);
    const double distance = mju_norm3(between);
    const double tangential = std::sqrt(std::max(0.0, vec3::Dot(slide, slide) - along * along));
    if (distance > 0) rate = std::max(rate, tangential / distance);
  }
  return rate;
}

void ContactStepper::SpreadForces(const double* f, const double* base, const double* base_u,
                                  const double* base_w, double* u, double* w) {
  const int rows = rows_;
  const int nv = nv_;
  const double* c = f;
  if (base) {
    // the rows whose force changed (the held ones' did not)
    difference_.resize(rows);
    for (int j = 0; j < rows; ++j) difference_[j] = f[j] - base[j];
    c = difference_.data();
  }
  Spread(c, u);
  if (base) {
    for (int k = 0; k < nv; ++k) u[k] += base_u[k];
  }
  if (!moving_) return;
  if (base) {
    std::copy(base_w, base_w + nv, w);
  } else {
    std::fill(w, w + nv, 0.0);
  }
  for (int j = 0; j < rows; ++j) {
    if (c[j] != 0) minv_jdt_rows_.AddTo(j, c[j], w);
  }
}

void ContactStepper::Acceleration(double t, const double* u, const double* w, const double* p,
                                  double* acc) {
  // acc = b + t b1 - J (u + t w) - J' (t u + p): each row's part over its
  // nonzero entries
  const int rows = rows_;
  const int nv = nv_;
  if (!moving_) {
    for (int i = 0; i < rows; ++i) acc[i] = b_[i] - j_rows_.Dot(i, u);
    return;
  }
  spread_rate_.resize(nv);
  spread_impulse_.resize(nv);
  for (int k = 0; k < nv; ++k) {
    spread_rate_[k] = u[k] + t * w[k];
    spread_impulse_[k] = p[k] + t * u[k];
  }
  for (int i = 0; i < rows; ++i) {
    acc[i] = b_[i] + t * b1_[i] - j_rows_.Dot(i, spread_rate_.data()) -
             jdot_rows_.Dot(i, spread_impulse_.data());
  }
}

int ContactStepper::SubSteps(double h) {
  if (options_.substeps > 0) return options_.substeps;
  const int n = static_cast<int>(points_.size());
  double step = h;
  // each friction point's tangential spring and damper (TangentialDynamics)
  // in contact at the step's start
  std::vector<TangentialSpringDamper> tangential(n);
  for (int j = 0; j < n; ++j) {
    const PointEvaluation& f = points_[j];
    if (tangent_row_[j] < 0 || !(f.depth > 0)) continue;
    const GeomPair& pair = model_.pairs()[f.pair];
    const double k = f.friction_state.stiffness;
    const ContactState state{f.depth, f.depth_rate, f.impact_velocity, 0.0};
    const double c = ReadsTangentialSpring(pair.friction.kind)
                         ? TangentialDamping(pair.friction, pair.params, state, k,
                                             pair.friction_mass)
                         : 0.0;
    tangential[j] = TangentialDynamics(pair.friction, k, c, pair.friction_mass, f.force);
  }
  row_sum_.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    const PointEvaluation& e = points_[i];
    const GeomPair& pair = model_.pairs()[e.pair];
    const LawParams& law = pair.params;
    // a tangential row: its coupling to the other tangential rows (its
    // mass: 1 / the row sum of |A|), its spring's period and its dampers' lag
    const bool explicit_friction = !Implicit(pair.friction.kind);
    for (int r = tangent_row_[i];
         explicit_friction && r >= 0 && r < tangent_row_[i] + 2 && e.depth > 0; ++r) {
      double row = 0, damped = 0;
      for (int j = 0; j < n; ++j) {
        for (int c = tangent_row_[j]; c >= 0 && c < tangent_row_[j] + 2; ++c) {
          const double coupling = std::abs(Coupling(r, c));
          row += coupling;
          damped += coupling * tangential[j].damping;
        }
      }
      if (!(row > 0)) continue;
      // the spring's undamped half period pi / omega, as TangentialDuration
      // takes it without its damper: the damper is the lag's bound, and on
      // the row's small Gershgorin mass an overdamped rate would only
      // repeat it
      const double omega2 = tangential[i].stiffness * row;
      if (omega2 > 0) {
        step = std::min(step, 2 * M_PI / std::sqrt(omega2) / options_.per_contact_hertz);
      }
      if (damped > 0) step = std::min(step, kSubStepLags / damped);
    }
    // its coupling: the row of A against its own diagonal (a resting
    // point's force is implicit: neither its spring nor its damper bounds)
    if (resting_[i]) continue;
    // A is weighed by the points' shares of their contact's force (a
    // point's spring and damper are the law's times its weight w): the
    // Gershgorin sums of W^1/2 A W^1/2, whose eigenvalues those of A W are.
    // A face patch's point of vanishing weight on a long gradient (an edge
    // sliding off a face) has a large A_ii and couplings but moves nothing:
    // unweighed, it set 1,352 sub-steps in a step of box_stack.xml's landing.
    double row = 0, damped = 0;
    for (int j = 0; j < n; ++j) {
      if (out_of_reach_[j] && j != i) continue;
      const double coupling = std::abs(Coupling(i, j)) * std::sqrt(e.weight * points_[j].weight);
      row += coupling;
      const PointEvaluation& f = points_[j];
      if (f.depth > 0 && !resting_[j]) {
        const ContactState state{f.depth, f.depth_rate, f.impact_velocity, mass_[j]};
        damped +=
            coupling * DampingCoefficient(model_.pairs()[f.pair].params, state);
      }
    }
    row_sum_[i] = row;
    // a point out of contact sets its sub-step from its touch on
    // (TouchSubStep)
    if (!(row > 0) || !(e.depth > 0)) continue;
    // an impact's speed: its v0 once in contact, its rate and what b adds
    // within the step before
    const double speed = std::max({std::abs(e.depth_rate) + std::abs(b_[i]) * h,
                                   e.depth > 0 ? e.impact_velocity : 0.0,
                                   law.min_impact_velocity});
    const double per_contact = Law(law.law).family == LawFamily::kLinear
                                   ? options_.per_contact_linear
                                   : options_.per_contact_hertz;
    if (sustained_[i]) {
      // kSustainedTurn of its vibration's phase at kSustainedDepth times
      // its depth
      const double stiffness = NormalStiffness(law, kSustainedDepth * e.depth);
      if (stiffness > 0) step = std::min(step, kSustainedTurn / std::sqrt(stiffness * row));
    } else {
      step = std::min(step, ElasticContactDuration(law, 1.0 / row, speed) / per_contact);
    }
    if (damped > 0) step = std::min(step, kSubStepLags / damped);
  }
  return static_cast<int>(std::min<double>(std::ceil(h / step), options_.max_substeps));
}

double ContactStepper::TouchSubStep(int i, double speed) const {
  // a fixed count of sub-steps is the user's: no touch divides it (nor are
  // the rule's row sums formed)
  if (options_.substeps > 0) return std::numeric_limits<double>::infinity();
  const LawParams& law = model_.pairs()[points_[i].pair].params;
  const double row = row_sum_[i];
  if (!(row > 0)) return std::numeric_limits<double>::infinity();
  const double per_contact = Law(law.law).family == LawFamily::kLinear
                                 ? options_.per_contact_linear
                                 : options_.per_contact_hertz;
  speed = std::max(speed, law.min_impact_velocity);
  double step = ElasticContactDuration(law, 1.0 / row, speed) / per_contact;
  // its damper's lag at the impact's deepest (the damping grows with the
  // depth)
  const double mass = 1.0 / row;
  const double depth = Law(law.law).family == LawFamily::kLinear
                           ? speed * std::sqrt(mass / law.linear_stiffness)
                           : HertzMaxDepth(law.stiffness, law.exponent, mass, speed);
  const ContactState deepest{depth, speed, speed, mass_[i]};
  const double damping = DampingCoefficient(law, deepest) * points_[i].weight * row;
  if (damping > 0) step = std::min(step, kSubStepLags / damping);
  return step;
}

void ContactStepper::Integrate(const mjModel* m, mjData* d,
                               const std::vector<PointEvaluation>& touching) {
  active_ = false;
  samples_used_ = 0;
  substeps_ = 0;
  end_.clear();
  points_ = touching;
  points_.insert(points_.end(), near_.begin(), near_.end());
  force_.assign(m->nv, 0.0);
  if (points_.empty()) return;
  active_ = true;
  h_ = m->opt.timestep;

  // the rows: a normal one per point, then two tangential ones per point
  // whose pair has friction, in the plane of its normal
  const int n = static_cast<int>(points_.size());
  rows_ = n;
  tangent_row_.assign(n, -1);
  tangents_.resize(static_cast<size_t>(6) * n);
  anchor_turn_.resize(static_cast<size_t>(9) * n);
  memory_.assign(n, FrictionMemory());
  for (int i = 0; i < n; ++i) {
    const PointEvaluation& e = points_[i];
    const GeomPair& pair = model_.pairs()[e.pair];
    if (pair.friction.kind == FrictionKind::kNone) continue;
    tangent_row_[i] = rows_;
    rows_ += 2;
    TangentBasis(e.normal, tangents_.data() + 6 * i);
    mju_copy(anchor_turn_.data() + 9 * i, d->xmat + 9 * pair.body[0], 9);
    if (e.depth > 0) {
      // the evaluator's friction at the step's start is the first commit
      FrictionMemory& memory = memory_[i];
      vec3::Copy(memory.spring, e.friction_state.spring);
      memory.stiffness = e.friction_state.stiffness;
      memory.sliding = e.friction_state.sliding;
    }
  }
  row_point_.resize(rows_);
  for (int i = 0; i < n; ++i) {
    row_point_[i] = i;
    if (tangent_row_[i] >= 0) row_point_[tangent_row_[i]] = row_point_[tangent_row_[i] + 1] = i;
  }
  BuildContactSpace(m, d);
  // the points at rest: vibrating about their equilibrium by less than
  // kRestingFraction of their depth
  resting_.assign(n, 0);
  sustained_.assign(n, 0);
  if (options_.substeps <= 0) {
    // x'' = b - A f at the start's forces (u = M^-1 J^T f)
    std::vector<double>& start = start_force_;
    start.assign(rows_, 0.0);
    for (int j = 0; j < n; ++j) {
      if (!(points_[j].depth > 0)) continue;
      start[j] = points_[j].force;
      const int r = tangent_row_[j];
      for (int c = 0; r >= 0 && c < 2; ++c) {
        start[r + c] = -vec3::Dot(points_[j].friction, tangents_.data() + 6 * j + 3 * c);
      }
    }
    spread_.resize(m->nv);
    Spread(start.data(), spread_.data());
  }
  for (int i = 0; options_.substeps <= 0 && i < n; ++i) {
    const PointEvaluation& e = points_[i];
    if (!(e.depth > 0) || e.touch) continue;
    const double acc = b_[i] - j_rows_.Dot(i, spread_.data());
    const LawParams& law = model_.pairs()[e.pair].params;
    const double w2 = e.weight * NormalStiffness(law, e.depth) * a_diag_[i];
    if (!(w2 > 0)) continue;
    // the vibration's amplitude, and, where the step is longer than 1 / w,
    // how far its rate carries the point within the step (h d', h d'' / w)
    const double w = std::sqrt(w2);
    const double amplitude = std::hypot(e.depth_rate / w, acc / w2);
    // (a point comes to rest from a calm step only: calm_)
    const bool calm = std::find(calm_.begin(), calm_.end(), e.episode) != calm_.end();
    resting_[i] = calm && !e.friction_state.sliding &&
                  amplitude * std::max(1.0, w * h_) < kRestingFraction * e.depth;
    sustained_[i] = !resting_[i] && amplitude < kSustainedFraction * e.depth &&
                    RowTurn(m, d, e) * h_ <= kMovingJacobianTurn;
  }
  // the episodes calm in this step, which the next step's may rest
  calm_next_.clear();
  for (int i = 0; i < n; ++i) {
    if ((resting_[i] || sustained_[i]) && points_[i].episode >= 0) {
      calm_next_.push_back(points_[i].episode);
    }
  }
  calm_.swap(calm_next_);
  out_of_reach_.assign(n, 0);
  for (int i = 0; options_.substeps <= 0 && i < n; ++i) {
    const PointEvaluation& e = points_[i];
    if (e.depth > 0) continue;
    const double acc = std::max(std::abs(b_[i]), std::abs(b_[i] - j_rows_.Dot(i, spread_.data())));
    const double reach = kStepReachFactor * (std::max(e.depth_rate, 0.0) * h_ + acc * h_ * h_);
    out_of_reach_[i] = -e.depth > reach;
  }
  BuildJacobianRates(m, d);
  for (const PointEvaluation& e : points_) {
    for (const int body : model_.pairs()[e.pair].body) {
      const double turn = mju_norm3(d->cvel + 6 * body) * h_;
      if (turn > worst_turn_) {
        worst_turn_ = turn;
        worst_turn_time_ = d->time;
      }
      if (turn > kFrozenTurnWarning && first_far_turn_time_ < 0) first_far_turn_time_ = d->time;
    }
  }

  const int rows = rows_;
  double delta = h_ / SubSteps(h_);
  // each row's state: depth and rate (normal), displacement since the
  // step's start and slip (tangential); each point's: in contact; its
  // episode's v0 (touch speed or the episode's) and the largest rate
  // committed since
  std::vector<double> x(rows, 0.0), rate(rows, 0.0), force(rows, 0.0);
  std::vector<double> v0(n), committed(n);
  std::vector<double> contact_v0(n);  // the law's v0 of this sub-step
  std::vector<char> open(n);
  std::vector<char> divided(n, 0);  // per point: its touch divided the step again
  // per point: the rolling and torsional part of its friction's stored
  // energy and power at the step's start, which stay through the step
  std::vector<double> rolling_energy(n, 0.0), rolling_power(n, 0.0);
  for (int i = 0; i < n; ++i) {
    const PointEvaluation& e = points_[i];
    x[i] = e.depth;
    rate[i] = e.depth_rate;
    open[i] = e.depth > 0;
    v0[i] = e.impact_velocity;
    contact_v0[i] = e.impact_velocity;
    committed[i] = e.max_approach;
    const int r = tangent_row_[i];
    if (r < 0) continue;
    for (int j = 0; j < 2; ++j) rate[r + j] = vec3::Dot(e.slip, tangents_.data() + 6 * i + 3 * j);
    if (e.depth > 0) {
      const FrictionParams& params = model_.pairs()[e.pair].friction;
      rolling_energy[i] = e.friction_energy - TangentialEnergy(params, e.friction_state, e.force);
      rolling_power[i] = e.friction_power + vec3::Dot(e.friction, e.slip);
    }
  }
  impulse_.assign(rows, 0.0);
  impulse_sum_.assign(rows, 0.0);
  rest_shift_.assign(m->nv, 0.0);
  rates_.clear();

  // the laws' dissipated power of each point at the sample (W), the points
  // whose sub-step RK4 took (in contact at its start, not resting), and the
  // last sub-step's RK4 quadrature of their power, its start's power and
  // length (dissipation_correction; the step's last: LastSubStep).
  std::vector<double> power(n, 0.0), staged_energy(n, 0.0), staged_start(n, 0.0);
  std::vector<char> staged(n, 0);
  double staged_step = 0;
  dissipation_correction_ = 0;
  double t = 0;  // since the step's start, s
  for (int k = 0; t < h_ * (1 - kEndTolerance); ++k) {
    if (samples_.size() <= static_cast<size_t>(k)) samples_.resize(k + 1);
    InnerSample& sample = samples_[k];
    sample.time = d->time + t;
    sample.points.clear();
    sample.ids.clear();
    rates_.insert(rates_.end(), rate.begin(), rate.end());
    samples_used_ = k + 1;
    std::fill(force.begin(), force.end(), 0.0);
    std::fill(power.begin(), power.end(), 0.0);
    for (int i = 0; i < n; ++i) {
      const bool in_contact = x[i] > 0;
      const int r = tangent_row_[i];
      const double* tangent = tangents_.data() + 6 * i;
      if (k == 0) {
        // the step's start: the evaluator's points as they are
        if (in_contact) {
          force[i] = points_[i].force;
          power[i] = points_[i].dissipated_power;
          for (int j = 0; r >= 0 && j < 2; ++j) {
            force[r + j] = -vec3::Dot(points_[i].friction, tangent + 3 * j);
          }
          sample.points.push_back(points_[i]);
          sample.ids.push_back(i);
        }
        continue;
      }
      if (!in_contact) {
        open[i] = false;
        if (r >= 0) memory_[i] = FrictionMemory();
        continue;
      }
      const GeomPair& pair = model_.pairs()[points_[i].pair];
      const LawParams& law = pair.params;
      PointEvaluation& e = sample.points.emplace_back(points_[i]);
      sample.ids.push_back(i);
      e.depth = x[i];
      e.depth_rate = rate[i];
      e.at_start = false;
      e.touch = !open[i];
      if (e.touch) {
        // v0: the rate at the sub-sample before the touch
        e.episode = -1;
        e.touch_velocity = rates_[static_cast<size_t>(k - 1) * rows + i];
        v0[i] = std::max(e.touch_velocity, law.min_impact_velocity);
        committed[i] = e.touch_velocity;
        const ContactState touch{std::numeric_limits<double>::min(), e.touch_velocity, v0[i],
                                 mass_[i]};
        e.touch_power = e.weight * EvaluateLaw(law, touch).dissipated_power(e.touch_velocity);
        open[i] = true;
        if (!(points_[i].depth > 0) && !divided[i]) {
          // the first touch of a point out of contact at the step's start,
          // which SubSteps left out: the rest of the step in even sub-steps
          // no longer than the point's own
          divided[i] = 1;
          const double own = TouchSubStep(i, std::abs(e.touch_velocity));
          const double rest = h_ - t;
          if (own < delta && rest > 0) delta = rest / std::ceil(rest / own);
        }
      }
      e.impact_velocity = std::max({v0[i], committed[i], law.min_impact_velocity});
      contact_v0[i] = e.impact_velocity;
      e.max_approach = std::max(committed[i], rate[i]);
      committed[i] = e.max_approach;
      const ContactForce f =
          EvaluateLaw(law, ContactState{x[i], rate[i], e.impact_velocity, mass_[i]});
      e.force = force[i] = e.weight * f.total;
      e.dissipated_power = power[i] = e.weight * f.dissipated_power(rate[i]);
      if (r < 0) continue;

      // the friction at this sub-sample, against the memory of the one
      // before (none at a touch), committed as a step's start commits it
      FrictionMemory& memory = memory_[i];
      if (e.touch) {
        memory = FrictionMemory();
        memory.at[0] = x[r];
        memory.at[1] = x[r + 1];
      }
      double stiffness = 0;
      const FrictionOutput out = Friction(i, e.force, e.impact_velocity, x.data(), rate.data(),
                                          e.slip, &stiffness);
      for (int j = 0; j < 2; ++j) force[r + j] = -vec3::Dot(out.force, tangent + 3 * j);
      vec3::Copy(e.friction, out.force);
      e.friction_energy = rolling_energy[i] + out.stored_energy;
      e.friction_power = rolling_power[i] - vec3::Dot(out.force, e.slip);
      vec3::Copy(e.friction_state.spring, out.state);
      e.friction_state.stiffness = stiffness;
      e.friction_state.sliding = out.sliding;
      vec3::Copy(memory.spring, out.state);
      memory.stiffness = stiffness;
      memory.sliding = out.sliding;
      memory.at[0] = x[r];
      memory.at[1] = x[r + 1];
      // the stick anchors: body[1]'s material point of the step's start,
      // and body[0]'s that lies under it now (it moved by x along the
      // tangents relative to body[0]), in body[0]'s frame
      double moved[3], local[3];
      for (int c = 0; c < 3; ++c) moved[c] = x[r] * tangent[c] + x[r + 1] * tangent[3 + c];
      mju_mulMatTVec(local, anchor_turn_.data() + 9 * i, moved, 3, 3);
      for (int c = 0; c < 3; ++c) e.local[0][c] = points_[i].local[0][c] + local[c];
    }
    // the last sub-step's quadrature against the ledger's trapezoid, whose
    // end is this sample
    for (int i = 0; i < n && staged_step > 0; ++i) {
      if (!staged[i]) continue;
      dissipation_correction_ +=
          staged_energy[i] - 0.5 * staged_step * (staged_start[i] + power[i]);
    }
    // the rows' acceleration at the sub-step's start (RK4's first stage),
    // which the touches within it are foreseen from
    Rk4Start(t, force, x, rate);
    const double* start_acc = stage_.data() + 3 * rows;
    // the sub-step, ended just past a touch within it (as the auto timestep
    // does), so that a force that jumps at d = 0+ acts from the touch on
    double step = std::min(delta, h_ - t);
    // no point in contact: the rows move freely, x'' = b + t b1 - D P with P
    // held, a cubic that RK4 takes exactly in one sub-step: the whole sub-steps
    // before the first touch in one (the touch's own sub-step, below, then
    // starts where sub-steps of delta would have started it)
    bool free = true;
    for (int i = 0; i < n && free; ++i) free = !(x[i] > 0);
    if (free) {
      double touch = std::numeric_limits<double>::infinity();
      for (int i = 0; i < n; ++i) {
        touch = std::min(touch, FirstCrossing(x[i], rate[i], start_acc[i],
                                              moving_ ? b1_[i] : 0.0, h_ - t));
      }
      if (touch > delta) {
        step = std::isinf(touch) ? h_ - t : (std::ceil(touch / delta) - 1) * delta;
      } else {
        free = false;
      }
    }
    // a point out of contact: its touch from its acceleration at the
    // sub-step's start, its neighbours' forces with it (b alone missed the
    // touches of points that those forces pushed into contact)
    for (int i = 0; !free && i < n; ++i) {
      const double a = start_acc[i];
      if (x[i] > 0 || x[i] + step * rate[i] + 0.5 * step * step * a <= 0) continue;
      const double touch = TimeToSurface(x[i], rate[i], a, step);
      const double shortest = kShortestSubStep * std::min(delta, TouchSubStep(i, rate[i] + a * step));
      step = std::min(step, std::max(touch * (1 + kPastTouch), shortest));
    }
    // classical RK4 on (x, x'), the points in contact at the sub-step's
    // start the ones with a force (a touch ends a sub-step), each at its v0
    // of the sample; exact in the free acceleration b
    std::vector<char>& acting = acting_;
    acting.resize(n);
    for (int i = 0; i < n; ++i) acting[i] = x[i] > 0;
    x_start_ = x;
    rate_start_ = rate;
    Rk4SubStep(t, step, force, contact_v0, &x, &rate);
    for (int i = 0; i < n; ++i) {
      staged[i] = acting[i] && !resting_[i];
      if (!staged[i]) continue;
      const double* stages = stage_power_.data() + 3 * i;
      staged_start[i] = power[i];
      staged_energy[i] = step / 6 * (power[i] + 2 * stages[0] + 2 * stages[1] + stages[2]);
    }
    staged_step = step;
    RestingShift(m, step, acting, &x);
    ImplicitRows(step, acting, force, contact_v0, &x, &rate);
    t += step;
    ++substeps_;
  }
  // the step's last sub-step: the ledger's trapezoid ends it at the next
  // step's start (LastSubStep)
  last_staged_.assign(n, LastStaged());
  for (int i = 0; i < n && staged_step > 0; ++i) {
    if (!staged[i]) continue;
    last_staged_[i].energy = staged_energy[i] - 0.5 * staged_step * staged_start[i];
    last_staged_[i].half_step = 0.5 * staged_step;
  }
  end_.resize(n);
  for (int i = 0; i < n; ++i) {
    end_[i].pair = points_[i].pair;
    vec3::Copy(end_[i].pos, points_[i].pos);
    end_[i].rate = rate[i];
  }
  // the step's mean contact force: the rows' forces f(t) act along J(t) =
  // J + J' t, -(J^T P + J'^T Q) / h with Q the impulse's first moment,
  // int t f dt = h P - int P dt
  for (int r = 0; r < rows; ++r) {
    j_rows_.AddTo(r, -impulse_[r] / h_, force_.data());
    if (moving_) jdot_rows_.AddTo(r, -(h_ * impulse_[r] - impulse_sum_[r]) / h_, force_.data());
  }
  ApplyForce(m, d);
}

FrictionOutput ContactStepper::Friction(int i, double fn, double v0, const double* x,
                                        const double* rate, double slip[3],
                                        double* stiffness, double* damping) const {
  const GeomPair& pair = model_.pairs()[points_[i].pair];
  const FrictionParams& params = pair.friction;
  const int r = tangent_row_[i];
  const double* t = tangents_.data() + 6 * i;
  const FrictionMemory& memory = memory_[i];
  // the slip, and the stretch since the last sub-sample, in the world frame
  FrictionInput in;
  for (int c = 0; c < 3; ++c) {
    slip[c] = rate[r] * t[c] + rate[r + 1] * t[3 + c];
    in.slip[c] = slip[c];
    in.stretch[c] = (x[r] - memory.at[0]) * t[c] + (x[r + 1] - memory.at[1]) * t[3 + c];
    in.committed[c] = memory.spring[c];
  }
  in.was_sliding = memory.sliding;
  in.normal_force = std::max(fn, 0.0);
  in.mass = pair.friction_mass;
  in.committed_stiffness = memory.stiffness;
  // k_t and c_t at this depth, as the evaluator takes them
  const bool rolling = params.torsional > 0 || params.rolling > 0;
  // (a weighted point's springs and dampers are its weight's share)
  const double weight = points_[i].weight;
  const double kt = ReadsTangentialSpring(params.kind) || rolling
                        ? TangentialStiffness(params, pair.params, x[i])
                        : 0.0;
  in.stiffness = weight * kt;
  if (ReadsTangentialSpring(params.kind)) {
    const ContactState state{x[i], rate[i], v0, 0.0};
    in.damping = weight * TangentialDamping(params, pair.params, state, kt, pair.friction_mass);
  }
  *stiffness = in.stiffness;
  if (damping) *damping = in.damping + params.viscous;
  return EvaluateFriction(params, in);
}

void ContactStepper::RestingShift(const mjModel* m, double step, const std::vector<char>& acting,
                                  std::vector<double>* x) {
  const int n = static_cast<int>(points_.size());
  bool any = false;
  for (int i = 0; i < n; ++i) {
    if (!acting[i]) continue;
    if (!resting_[i]) return;
    any = true;
  }
  if (!any) return;
  // the dofs of the resting points' trees: their acceleration at the
  // sub-step's start, a_free - M^-1 J^T f0 (Rk4SubStep's first stage left
  // M^-1 J^T f0 in stage_spread_), over step^2 / 2 more
  root_marked_.resize(m->nbody, 0);
  for (int i = 0; i < n; ++i) {
    if (!acting[i]) continue;
    for (const int body : model_.pairs()[points_[i].pair].body) root_marked_[m->body_rootid[body]] = 1;
  }
  std::vector<double>& shift = spread_rate_;
  shift.assign(nv_, 0.0);
  const double* u = stage_spread_.data();
  int dofs = 0;  // of the marked trees
  double largest = 0;  // their largest acceleration, m/s^2 or rad/s^2
  for (int k = 0; k < nv_; ++k) {
    if (root_marked_[m->body_rootid[m->dof_bodyid[k]]]) {
      shift[k] = 0.5 * step * step * (a_free_[k] - u[k]);
      largest = std::max(largest, std::abs(a_free_[k] - u[k]));
      ++dofs;
    }
  }
  for (int i = 0; i < n; ++i) {
    for (const int body : model_.pairs()[points_[i].pair].body) root_marked_[m->body_rootid[body]] = 0;
  }
  // only along the resting rows where the trees accelerate (a stack at rest
  // takes the whole trees' shift: kRestAcceleration)
  if (largest >= kRestAcceleration) ProjectOntoRestingRows(acting, dofs, &shift);
  for (int k = 0; k < nv_; ++k) rest_shift_[k] += shift[k];
  for (int r = 0; r < rows_; ++r) (*x)[r] += j_rows_.Dot(r, shift.data());
}

void ContactStepper::ProjectOntoRestingRows(const std::vector<char>& acting, int dofs,
                                            std::vector<double>* shift) {
  // only along the resting rows R (the normal rows, and the tangential ones
  // of a stick spring ImplicitRows holds): the shift s' = M^-1 J_R^T l
  // nearest s (in M's norm) with J_R s' = J_R s, A_RR l = J_R s over the
  // rows no other kept row's span holds (a box's four corners on a plane
  // span three dofs). What the rows leave (a ball rolling or sliding along
  // a surface) moves as RK4 takes it: the whole tree's shift put a ball on a
  // slope h a t / 2 ahead of its path (1.7 mm in 1 s at 2 ms, 2.9e-3 J
  // frictionless). The kept rows are independent in the trees' dofs: at
  // most dofs of them, L's rows dofs apart.
  const int n = static_cast<int>(points_.size());
  std::vector<int>& kept = rest_rows_;
  std::vector<double>& l = rest_factor_;
  std::vector<double>& rhs = rest_rhs_;
  kept.clear();
  rhs.clear();
  l.assign(static_cast<size_t>(dofs) * dofs, 0.0);
  const auto consider = [&](int i) {
    const int k = static_cast<int>(kept.size());
    double* row = l.data() + static_cast<size_t>(k) * dofs;
    for (int j = 0; j < k; ++j) {
      double sum = Coupling(i, kept[j]);
      const double* lj = l.data() + static_cast<size_t>(j) * dofs;
      for (int c = 0; c < j; ++c) sum -= row[c] * lj[c];
      row[j] = sum / lj[j];
    }
    double diagonal = a_diag_[i];
    for (int c = 0; c < k; ++c) diagonal -= row[c] * row[c];
    if (!(diagonal > kRestRowDependence * a_diag_[i])) {
      std::fill(row, row + k, 0.0);
      return;
    }
    row[k] = std::sqrt(diagonal);
    kept.push_back(i);
    rhs.push_back(j_rows_.Dot(i, shift->data()));
  };
  for (int i = 0; i < n && static_cast<int>(kept.size()) < dofs; ++i) {
    if (!acting[i]) continue;
    consider(i);
    const int r = tangent_row_[i];
    if (r >= 0 && Implicit(model_.pairs()[points_[i].pair].friction.kind) && !memory_[i].sliding) {
      for (int c = r; c < r + 2 && static_cast<int>(kept.size()) < dofs; ++c) consider(c);
    }
  }
  // rows that span every dof of the trees: the shift is theirs already (a
  // box at rest on its four corners with their stick springs)
  const int count = static_cast<int>(kept.size());
  if (count == dofs) return;
  rest_first_.assign(count, 0);
  EnvelopeSolve(l.data(), count, rest_first_, rhs.data(), rhs.data(), dofs);
  shift->assign(nv_, 0.0);
  for (int a = 0; a < count; ++a) minv_jt_rows_.AddTo(kept[a], rhs[a], shift->data());
}

void ContactStepper::ImplicitRows(double step, const std::vector<char>& acting,
                                  const std::vector<double>& start_force,
                                  const std::vector<double>& v0, std::vector<double>* x,
                                  std::vector<double>* rate) {
  const int n = static_cast<int>(points_.size());
  const int rows = rows_;
  // the rows held over the sub-step: a resting point's normal row and a
  // stick spring's two tangential ones; the force g at RK4's end state (a
  // resting point's: linear from the sub-step's start), and its change delta
  // over the held f0
  std::vector<int>& held = implicit_rows_;
  std::vector<int>& solve = solve_;     // rows solved for: a group's rows together
  std::vector<double>& gain = gain_;    // per solved row: k step^2 w2 + c step w
  std::vector<double>& cap = cap_;      // per solved row: its group's cap (N; < 0: normal)
  solve.clear();
  gain.clear();
  cap.clear();
  held.clear();
  delta_.assign(rows, 0.0);
  g_.assign(rows, 0.0);
  // the rule: the trapezoid when every held row is a stick spring the
  // sub-step resolves (kTrapezoidRate), else backward Euler; solved rows'
  // k and c kept until the rule is known
  bool trapezoid = true;
  std::vector<double>& stiffness = still_gain_;
  std::vector<double>& damping = still_cap_;
  stiffness.clear();
  damping.clear();
  auto hold = [&](int r, double g, double k, double c, double group_cap) {
    held.push_back(r);
    delta_[r] = g_[r] = g - start_force[r];
    if (k * step * step + c * step > 0) {
      solve.push_back(r);
      stiffness.push_back(k);
      damping.push_back(c);
      cap.push_back(group_cap);
      const double inverse_mass = a_diag_[r];
      trapezoid = trapezoid && group_cap >= 0 &&
                  k * inverse_mass * step * step <= kTrapezoidRate * kTrapezoidRate &&
                  c * inverse_mass * step <= kTrapezoidRate;
    }
  };
  for (int i = 0; i < n; ++i) {
    if (!acting[i]) continue;
    const GeomPair& pair = model_.pairs()[points_[i].pair];
    const int r = tangent_row_[i];
    const bool stick = r >= 0 && Implicit(pair.friction.kind);
    if (!resting_[i] && !stick) continue;
    if (resting_[i]) {
      // linearly implicit about the sub-step's start, where the point is in
      // contact (the law at RK4's end state, with the forces held over a
      // long sub-step, may be out of it): f = f0 + k dx + c dx', the law's
      // spring and damper there, and the friction's likewise
      const double x0 = x_start_[i];
      const ContactState start{x0, rate_start_[i], v0[i], mass_[i]};
      const double weight = points_[i].weight;
      const double k = weight * NormalStiffness(pair.params, x0);
      const double c = weight * DampingCoefficient(pair.params, start);
      const double gn =
          start_force[i] + k * ((*x)[i] - x0) + c * ((*rate)[i] - rate_start_[i]);
      hold(i, gn, k, c, -1);
      if (!stick) continue;
      const FrictionParams& f = pair.friction;
      const double kt1 = TangentialStiffness(f, pair.params, x0);
      const double kt = weight * kt1;
      const double ct =
          weight * TangentialDamping(f, pair.params, start, kt1, pair.friction_mass) + f.viscous;
      const double speed = std::hypot((*rate)[r], (*rate)[r + 1]);
      const double limit =
          std::max(gn, 0.0) * (memory_[i].sliding ? SlidingMu(f, speed) : f.mu_static);
      for (int j = 0; j < 2; ++j) {
        const int t = r + j;
        hold(t, start_force[t] + kt * ((*x)[t] - x_start_[t]) + ct * ((*rate)[t] - rate_start_[t]),
             kt, ct, limit);
      }
      continue;
    }
    if (!((*x)[i] > 0)) {
      // out of contact at the sub-step's end: no force there
      for (int j = 0; j < 2; ++j) hold(r + j, 0.0, 0.0, 0.0, 0);
      continue;
    }
    const ContactState state{(*x)[i], (*rate)[i], v0[i], mass_[i]};
    const double fn = points_[i].weight * EvaluateLaw(pair.params, state).total;
    double slip[3], k = 0, c = 0;
    const FrictionOutput out = Friction(i, fn, v0[i], x->data(), rate->data(), slip, &k, &c);
    const FrictionParams& f = pair.friction;
    const double limit =
        std::max(fn, 0.0) * (memory_[i].sliding ? SlidingMu(f, mju_norm3(slip)) : f.mu_static);
    // a sliding point keeps its force at the cap (g)
    const bool linear = !out.sliding;
    for (int j = 0; j < 2; ++j) {
      const double g = -vec3::Dot(out.force, tangents_.data() + 6 * i + 3 * j);
      hold(r + j, g, linear ? k : 0.0, linear ? c : 0.0, limit);
    }
  }
  if (held.empty()) return;
  // the share of the change of force delta that acts over the sub-step: on
  // the rate, w (backward Euler: the end force throughout, 1; the trapezoid:
  // the mean of the start's and the end's, 1/2), on the position, w2 (1;
  // 1/4, x' averaged)
  const double w = trapezoid ? 0.5 : 1.0;
  const double w2 = trapezoid ? 0.25 : 1.0;
  for (size_t a = 0; a < solve.size(); ++a) {
    gain.push_back(stiffness[a] * step * step * w2 + damping[a] * step * w);
  }
  // the solved rows: f = g - K A delta (x and x' at the sub-step's end
  // moved by -w2 step^2 A delta and -w step A delta), an SPD system, solved
  // in the rows or in the dofs of their trees, whichever is smaller. A
  // normal force below 0 is put at 0, a friction force beyond its cap at
  // the cap, and the others are solved again (once).
  std::vector<char>& solved = solved_;
  solved.assign(rows, 0);
  for (int pass = 0; pass < 2 && !solve.empty(); ++pass) {
    const int m = static_cast<int>(solve.size());
    std::fill(solved.begin(), solved.end(), 0);
    for (const int r : solve) solved[r] = 1;
    std::vector<double>& f = solution_;
    f.assign(m, 0.0);
    const bool in_dofs = MarkTrees() < m;
    const bool solved_ok =
        in_dofs ? SolveInDofs(held, start_force, f.data()) : SolveInRows(held, start_force, f.data());
    for (const int r : solve) {
      const PointEvaluation& e = points_[row_point_[r]];
      for (const int body : model_.pairs()[e.pair].body) {
        root_marked_[model_.model()->body_rootid[body]] = 0;
      }
    }
    if (!solved_ok) break;
    std::vector<int>& still = still_;
    std::vector<double>& still_gain = still_gain_;
    std::vector<double>& still_cap = still_cap_;
    still.clear();
    still_gain.clear();
    still_cap.clear();
    for (int a = 0; a < m;) {
      // a group: a normal row (cap < 0), or a point's two tangential rows
      const int size = cap[a] < 0 ? 1 : 2;
      double scale = 1;
      if (size == 1 && f[a] < 0) scale = 0;
      if (size == 2) {
        const double force = std::hypot(f[a], f[a + 1]);
        if (force > cap[a]) scale = cap[a] / force;
      }
      for (int j = 0; j < size; ++j) {
        delta_[solve[a + j]] = scale * f[a + j] - start_force[solve[a + j]];
        if (scale < 1) continue;
        still.push_back(solve[a + j]);
        still_gain.push_back(gain[a + j]);
        still_cap.push_back(cap[a + j]);
      }
      a += size;
    }
    if (still.size() == solve.size()) break;
    solve.swap(still);
    gain.swap(still_gain);
    cap.swap(still_cap);
  }
  // the change of force over the whole sub-step, on every row: A delta =
  // J M^-1 J_H^T delta_H
  std::vector<double>& spread = spread_;
  spread.resize(nv_);
  std::vector<double>& held_delta = coefficients_;
  held_delta.assign(rows, 0.0);
  for (const int l : held) held_delta[l] = delta_[l];
  Spread(held_delta.data(), spread.data());
  for (int r = 0; r < rows; ++r) {
    const double pushed = j_rows_.Dot(r, spread.data());
    (*rate)[r] -= w * step * pushed;
    (*x)[r] -= w2 * step * step * pushed;
  }
  for (const int l : held) {
    impulse_sum_[l] += w2 * step * step * delta_[l];
    impulse_[l] += w * step * delta_[l];
  }
}

int ContactStepper::MarkTrees() {
  const mjModel* m = model_.model();
  root_marked_.resize(m->nbody, 0);
  int dofs = 0;
  for (const int r : solve_) {
    const PointEvaluation& e = points_[row_point_[r]];
    for (const int body : model_.pairs()[e.pair].body) {
      const int root = m->body_rootid[body];
      if (!root_marked_[root]) dofs += root_dofs_[root];
      root_marked_[root] = 1;
    }
  }
  return dofs;
}

bool ContactStepper::SolveInRows(const std::vector<int>& held,
                                 const std::vector<double>& start_force, double* f) {
  const std::vector<int>& solve = solve_;
  const int m = static_cast<int>(solve.size());
  // the right-hand side's A_SS f0_S - A_SL delta_L = J_S M^-1 (J_S^T f0_S
  // - J_L^T delta_L)
  std::vector<double>& coefficients = coefficients_;
  coefficients.assign(rows_, 0.0);
  for (const int l : held) coefficients[l] = solved_[l] ? start_force[l] : -delta_[l];
  std::vector<double>& spread = spread_;
  spread.resize(nv_);
  Spread(coefficients.data(), spread.data());
  std::vector<double>& rhs = rhs_;
  rhs.resize(m);
  system_.assign(static_cast<size_t>(m) * m, 0.0);
  for (int a = 0; a < m; ++a) {
    const int r = solve[a];
    for (int b = 0; b <= a; ++b) system_[a * m + b] = Coupling(r, solve[b]);
    system_[a * m + a] += 1 / gain_[a];
    rhs[a] = (start_force[r] + g_[r]) / gain_[a] + j_rows_.Dot(r, spread.data());
  }
  if (!EnvelopeCholesky(system_.data(), m, &envelope_)) return false;
  EnvelopeSolve(system_.data(), m, envelope_, rhs.data(), f);
  return true;
}

bool ContactStepper::SolveInDofs(const std::vector<int>& held,
                                 const std::vector<double>& start_force, double* f) {
  const mjModel* model = model_.model();
  const int nv = nv_;
  // the dofs of the marked trees, in order (a dof's ancestors come before it)
  local_.resize(nv);
  dofs_.clear();
  for (int k = 0; k < nv; ++k) {
    const bool in = root_marked_[model->body_rootid[model->dof_bodyid[k]]];
    local_[k] = in ? static_cast<int>(dofs_.size()) : -1;
    if (in) dofs_.push_back(k);
  }
  const int size = static_cast<int>(dofs_.size());
  // the lower triangle of M + J_S^T K J_S (M: each dof's row from its
  // diagonal along its ancestors, as MuJoCo's qM keeps it)
  system_.assign(static_cast<size_t>(size) * size, 0.0);
  for (int a = 0; a < size; ++a) {
    int k = dofs_[a];
    int address = model->dof_Madr[k];
    double* row = system_.data() + static_cast<size_t>(a) * size;
    row[a] = mass_matrix_[address];
    for (int parent = model->dof_parentid[k]; parent >= 0; parent = model->dof_parentid[parent]) {
      row[local_[parent]] = mass_matrix_[++address];
    }
  }
  std::vector<double>& rhs = rhs_;
  rhs.assign(size, 0.0);
  const std::vector<int>& solve = solve_;
  const SparseRows& j = j_rows_;
  std::vector<int>& columns = columns_;  // a row's entries' local dofs
  for (size_t a = 0; a < solve.size(); ++a) {
    const int r = solve[a];
    const int first = j.start[r];
    const int count = j.start[r + 1] - first;
    columns.resize(count);
    const double* value = j.value.data() + first;
    for (int e = 0; e < count; ++e) columns[e] = local_[j.column[first + e]];
    for (int e = 0; e < count; ++e) {
      double* row = system_.data() + static_cast<size_t>(columns[e]) * size;
      const double scaled = gain_[a] * value[e];
      for (int o = 0; o <= e; ++o) row[columns[o]] += scaled * value[o];
      rhs[columns[e]] += g_[r] * value[e];
    }
  }
  for (const int l : held) {
    if (solved_[l]) continue;
    for (int e = j.start[l]; e < j.start[l + 1]; ++e) {
      const int k = local_[j.column[e]];
      if (k >= 0) rhs[k] += delta_[l] * j.value[e];
    }
  }
  if (!EnvelopeCholesky(system_.data(), size, &envelope_)) return false;
  std::vector<double>& z = spread_;
  z.resize(size);
  EnvelopeSolve(system_.data(), size, envelope_, rhs.data(), z.data());
  // f_S = g_S - K J_S z
  for (size_t a = 0; a < solve.size(); ++a) {
    const int r = solve[a];
    double velocity = 0;
    for (int e = j.start[r]; e < j.start[r + 1]; ++e) velocity += j.value[e] * z[local_[j.column[e]]];
    f[a] = start_force[r] + g_[r] - gain_[a] * velocity;
  }
  return true;
}

void ContactStepper::Rk4Start(double t0, const std::vector<double>& start_force,
                              const std::vector<double>& x, const std::vector<double>& rate) {
  const int rows = rows_;
  const int nv = nv_;
  stage_.resize(static_cast<size_t>(16) * rows);
  stage_spread_.resize(static_cast<size_t>(10) * nv);
  // stage 0 (Rk4SubStep's layout): the sub-step's start
  double* d0 = stage_.data();
  double* r0 = stage_.data() + rows;
  double* f0 = stage_.data() + 2 * rows;
  double* acc0 = stage_.data() + 3 * rows;
  std::copy(x.begin(), x.end(), d0);
  std::copy(rate.begin(), rate.end(), r0);
  std::copy(start_force.begin(), start_force.end(), f0);
  double* u0 = stage_spread_.data();
  double* w0 = stage_spread_.data() + 4 * nv;
  double* p = stage_spread_.data() + 8 * nv;
  double* stage_p = stage_spread_.data() + 9 * nv;
  if (moving_) {
    Spread(impulse_.data(), p);
    std::copy(p, p + nv, stage_p);
  }
  SpreadForces(f0, nullptr, nullptr, nullptr, u0, w0);
  Acceleration(t0, u0, w0, stage_p, acc0);
}

void ContactStepper::Rk4SubStep(double t0, double step, const std::vector<double>& start_force,
                                const std::vector<double>& v0, std::vector<double>* x,
                                std::vector<double>* rate) {
  const int n = static_cast<int>(points_.size());
  const int rows = rows_;
  // stage s: position, rate, force, and the acceleration b - A f, per row;
  // stage 0 is Rk4Start's
  double* d[4];
  double* r[4];
  double* f[4];
  double* acc[4];
  for (int s = 0; s < 4; ++s) {
    d[s] = stage_.data() + (4 * s + 0) * rows;
    r[s] = stage_.data() + (4 * s + 1) * rows;
    f[s] = stage_.data() + (4 * s + 2) * rows;
    acc[s] = stage_.data() + (4 * s + 3) * rows;
  }
  // per stage: u = M^-1 J^T f; with J', w = M^-1 J'^T f, and p = M^-1 J^T
  // P at the sub-step's start and at the stage
  const int nv = nv_;
  double* u[4];
  double* w[4];
  for (int s = 0; s < 4; ++s) {
    u[s] = stage_spread_.data() + s * nv;
    w[s] = stage_spread_.data() + (4 + s) * nv;
  }
  double* p = stage_spread_.data() + 8 * nv;
  double* stage_p = stage_spread_.data() + 9 * nv;
  const double offsets[4] = {0, 0.5 * step, 0.5 * step, step};
  stage_power_.assign(static_cast<size_t>(3) * n, 0.0);
  for (int s = 1; s < 4; ++s) {
    for (int i = 0; i < rows; ++i) {
      d[s][i] = (*x)[i] + offsets[s] * r[s - 1][i];
      r[s][i] = (*rate)[i] + offsets[s] * acc[s - 1][i];
      f[s][i] = 0.0;
    }
    for (int i = 0; i < n; ++i) {
      const bool acting = (*x)[i] > 0;  // in contact at the sub-step's start
      if (acting && resting_[i]) {
        // held over the sub-step; ImplicitRows corrects it at its end
        f[s][i] = start_force[i];
      } else if (acting && d[s][i] > 0) {
        const LawParams& law = model_.pairs()[points_[i].pair].params;
        const ContactForce law_force =
            EvaluateLaw(law, ContactState{d[s][i], r[s][i], v0[i], mass_[i]});
        f[s][i] = points_[i].weight * law_force.total;
        stage_power_[3 * i + s - 1] = points_[i].weight * law_force.dissipated_power(r[s][i]);
      }
      // (a resting point's force is held whatever the stage's depth, and
      // so is its implicit friction: the stages' predicted depths, from
      // forces held over a long sub-step, can leave the contact)
      const bool held = acting && resting_[i];
      if (!held && (!acting || !(d[s][i] > 0))) continue;
      // the friction at the stage's normal force, against the sub-sample's
      // memory
      const int t = tangent_row_[i];
      if (t < 0) continue;
      if (Implicit(model_.pairs()[points_[i].pair].friction.kind)) {
        // held over the sub-step; ImplicitRows corrects it at its end
        f[s][t] = start_force[t];
        f[s][t + 1] = start_force[t + 1];
        continue;
      }
      if (!(d[s][i] > 0)) continue;
      double slip[3], stiffness;
      const FrictionOutput out = Friction(i, f[s][i], v0[i], d[s], r[s], slip, &stiffness);
      for (int j = 0; j < 2; ++j) {
        f[s][t + j] = -vec3::Dot(out.force, tangents_.data() + 6 * i + 3 * j);
      }
    }
    // the impulse at the stage, as RK4 takes P' = f: M^-1 J^T P = p + offset
    // u of the stage before (p: the sub-step's start), and x''
    for (int k = 0; moving_ && k < nv; ++k) stage_p[k] = p[k] + offsets[s] * u[s - 1][k];
    // u and w of a later stage from the first's, through the rows whose
    // force the stage changed
    SpreadForces(f[s], f[0], u[0], w[0], u[s], w[s]);
    Acceleration(t0 + offsets[s], u[s], w[s], stage_p, acc[s]);
  }
  for (int i = 0; i < rows; ++i) {
    // x'' = b - A f: x moves by step x' + step^2 / 6 (a1 + a2 + a3), whose
    // contact part is the position impulse added to impulse_sum_
    impulse_sum_[i] += step * impulse_[i] + step * step / 6 * (f[0][i] + f[1][i] + f[2][i]);
    impulse_[i] += step / 6 * (f[0][i] + 2 * f[1][i] + 2 * f[2][i] + f[3][i]);
    (*x)[i] += step * (*rate)[i] + step * step / 6 * (acc[0][i] + acc[1][i] + acc[2][i]);
    (*rate)[i] += step / 6 * (acc[0][i] + 2 * acc[1][i] + 2 * acc[2][i] + acc[3][i]);
  }
}

void ContactStepper::ApplyForce(const mjModel* m, mjData* d) const {
  if (active_) mju_addTo(d->qfrc_passive, force_.data(), m->nv);
}

void ContactStepper::CorrectPositions(const mjModel* m, mjData* d) const {
  if (!active_) return;
  // the inner trajectory's displacement over the step:
  //   h v_n + h^2/2 a_free - M^-1 J^T (delta sum_k P_k);
  // the integrator's under the constant force -J^T P / h:
  //   h v_n + c h^2 a_free - c h M^-1 J^T P, c = 1 (Euler, implicit: q + h v_{n+1}),
  //   c = 1/2 (RK4, exact for a constant acceleration)
  const double c = m->opt.integrator == mjINT_RK4 ? 0.5 : 1.0;
  const int nv = m->nv;
  std::vector<double> shift(nv);
  for (int k = 0; k < nv; ++k) shift[k] = (0.5 - c) * h_ * h_ * a_free_[k] + rest_shift_[k];
  for (int i = 0; i < static_cast<int>(impulse_.size()); ++i) {
    minv_jt_rows_.AddTo(i, -(impulse_sum_[i] - c * h_ * impulse_[i]), shift.data());
  }
  mj_integratePos(m, d->qpos, shift.data(), 1.0);
}

}  // namespace contactlaws::internal
