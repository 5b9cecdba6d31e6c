// Copyright contactlaws authors.
//
// A contact-aware timestep: long steps while every tagged pair is too far
// apart to touch within the step, steps that resolve the contact while any
// pair is near or in it. A stiff contact lasts about a millisecond and needs
// steps of ~1e-5 s, but it is a small part of a run: a fixed step spends most
// of its work on free flight.
//
// The rule, from the state at the start of each step:
//   1. A pair in contact (the last hook evaluation found depth > 0) asks for
//      its fine step: its estimated contact duration at the impact speed v0,
//      divided by steps_per_contact. The duration is the law's elastic one
//      (HertzContactDuration for the Hertz family, pi sqrt(m/k) for
//      Kelvin-Voigt) with the pair's effective mass (root subtree masses in
//      series, as EstimateContact).
//   2. A pair apart, with surface gap g (bounding spheres, or the exact
//      distance to a plane), closing speed v (the geom centres' relative
//      velocity along the line between them, plus what spinning can add,
//      |w| times the bounding radius, none for a sphere, whose surface
//      turns within itself) and closing acceleration a (gravity on
//      a body that can fall towards a static one, and a driven body's top
//      acceleration A w^2), asks for the time in which it could close
//      gap_fraction of g: h with v h + a h^2 / 2 = gap_fraction g. Once that
//      time is below its fine step (at the predicted impact speed), it asks
//      for the fine step, cut to end at the predicted touch (v h + a h^2 / 2
//      = g) when that comes within it: a force that jumps at d = 0+
//      (Kelvin-Voigt's c v0) then acts from a step's start, not for an
//      unknown part of a step.
//   3. A pair in contact that separates (depth rate < 0) and would reach
//      d = 0 within its fine step asks for the step that ends just past
//      d = 0: the first state after the separation, from which the impact
//      log reads the separation speed, is then not slowed by gravity over
//      a part of a fine step (a first-order error in the rebound).
//   4. A pair in contact with friction also asks for its tangential step:
//      the period of its stick spring (2 pi sqrt(m / k_t), m the pair's
//      friction_mass), LuGre's bristles or the regularized curve (twice
//      TangentialDuration), or of its rolling and torsional springs, divided
//      by steps_per_contact, as the normal contact's duration is (the fixed
//      step's rule likewise asks 20 steps of either). With Mindlin's k_t the
//      period is ~2x the normal contact's duration: it binds only for a
//      stiffer spring.
//   5. A pair in contact also asks for no more than the lag m / c of its
//      law's damping, its points' DampingCoefficient added: a box placed on
//      a floor (v0 at the law's floor, 1e-3 m/s) under flores e = 0.2 is a
//      damper of lag 1.6e-5 s, and steps of 6e-5 s hung it at 60% of its
//      weight. A pair of several points also asks for no more than 2 lags
//      of those dampers on the inertia the bodies show at the points
//      (mujoco/damper_rate.h, normal part): a 1 x 1 x 0.1 m box under 25
//      balls, settled on a floor, rocks against its corners' dampers 3x
//      faster than it moves its mass against them, and m / c's steps (3
//      lags of the rocking, past RK4's 2.785) fed it 0.11 J in 0.5 s.
//      An impact's damping (v0 of metres per second) never binds.
//      Likewise no more than 2 lags 1 / lambda of its friction's dampers
//      (TangentialDynamics: the stick spring's, the bristles', the
//      regularized curve's slope), its points in parallel, on the inertia
//      the bodies show at the points (mujoco/damper_rate.h): a 2 cm die
//      resting on four corners turns about the vertical against them 12x
//      faster than one of them moves its mass, and steps of 3.6e-5 s (rule
//      4's, 0.4 of the period on its mass) were beyond RK4's 2.785 lags: the
//      die spun at 5e-3 rad/s for ever, its friction dissipating what the
//      integration fed in.
//   6. Under RK4, a settled contact point (its depth rate below the law's
//      floor of v0, min_impact_velocity, and its episode touched within
//      kSettledTouchFactor of the floor or has lasted kSettledDurations
//      elastic contact durations at its v0: past its impact) has no
//      impact to resolve (Kelvin-Voigt's ball came to rest on the table
//      from a touch at 1.15e-3 m/s, and took 1.4M steps of 7 us for it;
//      Flores e = 0.3's from a touch at 0.1 m/s): its step is the
//      elastic contact duration at the floor speed over
//      kSettledStepsPerContact (6: the contact's spring at about 0.5 rad a
//      step, RK4 being stable to 2.8; its static load compresses it more
//      than a touch at the floor speed, ~1.2x the rate for a ball's weight,
//      ~1.5x for a stack's bottom cube), whatever the accuracy, which is
//      about impacts. The tangential step and the dampers' lags still
//      bound it. A ball resting on the driven table of Figs. 8-10 for most
//      of its 10 s took 138k steps.
//   7. The step is the smallest asked for, at most max_step (none by
//      default: free flight under gravity alone is a parabola, which RK4
//      integrates exactly, so the gap closure of a pair apart is what limits
//      it), and grows at most by `growth` from one step to the next: from
//      the step the rules asked for, not from a step cut to land on a
//      predicted touch or separation or at `until` (StepBound). A scene with
//      dynamics of its own (anything but free bodies, gravity, the tags and
//      drives: joints with springs, damping or limits, actuators, tendons,
//      equality constraints) keeps its own opt.timestep as the flight
//      step's bound: the author chose it for those dynamics. A pair that
//      MuJoCo's own contact handles (untagged) asks for that step only while
//      its bounding spheres are within MuJoCo's margin or could close
//      gap_fraction of their gap beyond it within that step (a tagged pair's
//      closing speed and acceleration); farther, for the time to close that
//      fraction.
//      A hinge or a ball joint is dynamics of the scene's own: its bodies
//      swing under gravity (a pendulum), no parabola; a slide joint's do not.
//      Under Euler or implicit integration the flight step is also bounded
//      by the accuracy: they integrate a parabola with a first-order error.
//   8. A free body whose inertia is not a sphere's (a box, a capsule, a
//      domino; not a ball or a cube) turns its angular velocity in its own
//      frame as it spins (Euler's equations: a precession, or a tumble about
//      its intermediate axis), at up to |w| (I_max - I_min) / I_min: that
//      rate's period over steps_per_contact bounds the step, whatever the
//      integrator. A 10 x 20 x 40 cm box spinning at 10 rad/s through free
//      flight took RK4 steps as long as its flight and its kinetic energy
//      went from 0.7 J to 1.4e10 J in 2 s; now 4.2 ms at the default
//      accuracy.
// Re-evaluated before every step, a pair's allowed step shrinks with its gap
// geometrically, so the first touch comes within a fine step whatever the
// approach speed. A step ends at Next's `until` (the run's end; Advance
// interpolates the trajectory's rows inside the steps).
//
// The step chosen is the data's: ContactData::Step(timestep) steps with it
// and keeps it in the data's options (ContactData::options), never in the
// model, which data on other threads may share.

#ifndef CONTACTLAWS_AUTO_TIMESTEP_H_
#define CONTACTLAWS_AUTO_TIMESTEP_H_

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "contactlaws/contact_data.h"

namespace contactlaws {

// The accuracy the auto timestep delivers by default: the relative error
// accepted in an impact's rebound (e_post), peak force and contact
// duration.
inline constexpr double kDefaultAccuracy = 1e-3;

// How the accuracy sets the steps (docs/timestep.md):
// for the Hertz family, steps per contact = 50 (tol0 / tol)^0.45, tol0 =
// kDefaultAccuracy: with its steps cut at touch and separation, RK4's errors
// in the rebound, the duration (each end extrapolated to d = 0) and the peak
// force (PeakForce) are of the second order or higher, measured below tol on
// the paper's sweep at tol = 1e-3, 1e-4, 1e-5 (auto_accuracy_test).
// Kelvin-Voigt's clamp F >= 0 puts a kink inside its contact: 200 (tol0 /
// tol)^(1/2) steps.
inline constexpr double kDefaultStepsPerContact = 50;
inline constexpr double kStepsExponent = 0.45;
inline constexpr double kKelvinVoigtStepsAtDefault = 200;
// The accepted range of accuracy (the option refuses what is outside).
inline constexpr double kMaxAccuracy = 0.1;

struct AutoTimestepOptions {
  // The relative error accepted in an impact's rebound, peak force and
  // duration, in (0, kMaxAccuracy]: sets the steps per contact (above) and,
  // under Euler or implicit integration, the flight step.
  double accuracy = kDefaultAccuracy;
  // s: an optional cap on every step (none by default: the dynamics bound
  // the flight step, as the rule above says).
  double max_step = std::numeric_limits<double>::infinity();
  // Overrides of what the accuracy sets (0: from the accuracy): the fine
  // step is the estimated contact duration / steps_per_contact (Hertz
  // family) or / kelvin_voigt_steps_per_contact.
  double steps_per_contact = 0;
  double kelvin_voigt_steps_per_contact = 0;
  // A step may close at most this fraction of a pair's gap.
  double gap_fraction = 0.5;
  // A step is at most this many times the one before.
  double growth = 2.0;
};

// The steps per contact the accuracy asks for: Hertz family, Kelvin-Voigt.
double StepsPerContact(double accuracy);
double KelvinVoigtStepsPerContact(double accuracy);

// A settled contact's steps per elastic contact duration at the floor speed.
inline constexpr double kSettledStepsPerContact = 6;
// A touch slower than this many floors of v0 is a settling, not a
// impact whose rebound a figure reads (1e-2 m/s at the default floor).
inline constexpr double kSettledTouchFactor = 10;
// A contact open this many of its elastic durations is past its
// impact (an impact lasts one, its rebound included).
inline constexpr double kSettledDurations = 3;

class PairSteps;      // src/sim/contact_steps.h
struct StepBound;     // src/sim/contact_steps.h
class ApproachSteps;  // src/sim/approach_steps.h
namespace internal {
class DamperRate;     // src/mujoco/damper_rate.h
enum class DamperDirection;
}  // namespace internal

class AutoTimestep {
 public:
  // contacts must outlive this object.
  explicit AutoTimestep(const ContactData& contacts, const AutoTimestepOptions& options = {});
  ~AutoTimestep();
  AutoTimestep(AutoTimestep&&) noexcept;

  // The step to take from the current state of d, the contacts' data (after
  // mj_step or mj_forward), at most until (s, > 0). Computes d's kinematics
  // (mj_kinematics, mj_comPos, mj_comVel) when no pair is in contact.
  // ContactData::Step(Next(d, until)) takes it.
  double Next(mjData* d, double until);

  // Forget the previous step (after a reset).
  void Reset() { previous_ = 0; }

  const AutoTimestepOptions& options() const { return options_; }
  // Steps taken at the fine step of a contact, and all steps.
  long fine_steps() const { return fine_steps_; }
  long steps() const { return steps_; }
  // The shortest step the rules asked for at a contact's fine step, s (the
  // landings on a touch or a separation and the growth limit aside): a
  // fixed step as fine as the auto step's finest (infinite before any).
  double finest_step() const { return finest_step_; }

 private:
  // Limits *bound by the step a pair in contact allows at evaluation e: its
  // fine step, landed just past d = 0 when it separates within it.
  void ContactStep(const ContactData::Evaluation& e, StepBound* bound) const;
  // The law's view of an evaluated point.
  ContactState State(const ContactData::Evaluation& e) const;
  // The step the friction of a pair in contact allows at evaluation e: the
  // period 2 TangentialDuration (stick spring, bristles or regularized curve,
  // at e's stiffness and normal force, on the pair's friction_mass), and that
  // of its rolling and torsional springs, over steps_per_contact; infinite
  // without friction.
  double TangentialStep(const ContactData::Evaluation& e) const;
  // The bound from the friction dampers of the points latest()[first, end)
  // (one pair's) in d; infinite without friction. A bound of it when that
  // shows it no shorter than pace (s, the step's bound so far): it does not
  // bind then, and its eigenvalue solve is left out.
  double FrictionLag(mjData* d, size_t first, size_t end, double pace);
  // The bound from the laws' normal dampers of those points on the
  // inertia at them (kNormalDamperLags, their dampers law_damping_);
  // infinite without damping. As
  // FrictionLag, a bound of it when that is no shorter than pace.
  double NormalLag(mjData* d, size_t first, size_t end, double pace);
  // lags / the rate (1/s) of the dampers damping(i) (N s/m) at those points,
  // resisting direction's part of their relative velocity; or lags / an
  // upper bound of that rate, when that is at least pace.
  template <typename Damping>
  double DampersLag(mjData* d, size_t first, size_t end, internal::DamperDirection direction,
                    double lags, double pace, const Damping& damping);
  // The bound of the flight step: the data's timestep (options()) when the
  // scene has dynamics of its own, the accuracy's under Euler or implicit.
  double FlightStep() const;
  // The bound the spinning free bodies set in d (Spinner): infinite when
  // none turns its angular velocity.
  double SpinStep(const mjData* d) const;

  const ContactData& contacts_;
  AutoTimestepOptions options_;
  double flight_step_;  // s, FlightStep() of the data's options as they were given
  // per pair: effective mass (kg, inf when neither body moves)
  std::vector<double> effective_mass_;
  std::unique_ptr<PairSteps> pair_steps_;   // each pair's fine and settled steps
  std::unique_ptr<ApproachSteps> approach_;  // the steps the pairs apart allow
  std::vector<uint8_t> in_contact_;       // per pair, within Next (all 0 between calls)
  std::vector<double> pair_damping_;      // per pair, N s/m, within Next (all 0 between calls)
  std::vector<double> law_damping_;       // per point of latest(), N s/m, within Next
  // per pair and DamperDirection: its dampers' lag bound the step when last
  // computed (DampersLag)
  std::vector<uint8_t> binding_;
  // DampersLag's: the points' positions, normals and dampers, and their rate
  std::vector<double> point_pos_, point_normal_, point_damping_;
  std::unique_ptr<internal::DamperRate> damper_rate_;
  // A free joint whose bodies' inertia (composite, about their centre of
  // mass) is not a sphere's: its angular velocities at dof + 3, and
  // (I_max - I_min) / I_min of that inertia.
  struct Spinner {
    int dof;
    double anisotropy;
  };
  static std::vector<Spinner> Spinners(const mjModel* m);
  std::vector<Spinner> spinners_;
  bool settled_rule_ = false;             // the settled contact's step: RK4 only
  double previous_ = 0;
  long fine_steps_ = 0;
  long steps_ = 0;
  double finest_step_ = std::numeric_limits<double>::infinity();
};

}  // namespace contactlaws

#endif  // CONTACTLAWS_AUTO_TIMESTEP_H_
