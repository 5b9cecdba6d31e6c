// Copyright contactlaws authors.
//
// Before a run: how fast a tagged pair will hit, how long its contact will
// last, and the timestep that resolves it. `contactlaws check` prints these;
// they are estimates from the elastic part of the law, stated as such.

#ifndef CONTACTLAWS_SIM_ESTIMATE_H_
#define CONTACTLAWS_SIM_ESTIMATE_H_

#include <array>
#include <limits>
#include <optional>
#include <string>

#include "contactlaws/contact_data.h"

namespace contactlaws {

// The rule this library uses: a contact is resolved when the timestep puts at
// least this many steps in its estimated duration. At 20 steps the paper's
// drop rebounds within 1.7e-4 of its 1e-5 s value (e = 0.5, Hertz family;
// docs/paper-reproduction.md).
inline constexpr int kStepsPerContact = 20;

struct ContactEstimate {
  // Translational effective mass along the line of impact, kg: the two
  // bodies' root subtree masses in series; a world, static or driven body
  // counts as infinitely heavy. Infinite when neither body can move.
  double effective_mass = 0;
  // Surface distance at the current state, m (< 0: already interpenetrating);
  // nullopt when the narrowphase finds no contact within reach.
  std::optional<double> gap;
  // Closing speed at first touch, m/s: the current closing speed accelerated
  // by gravity over the gap (bodies with dofs fall, others do not), plus the
  // greatest speed of each driven body. 0 when nothing brings them together.
  double impact_velocity = 0;
  // Elastic contact at that speed: Hertz family K d^n, HertzMaxDepth and
  // HertzContactDuration; kelvin-voigt k d, (v sqrt(m/k)) and pi sqrt(m/k).
  // Infinite when impact_velocity is 0 (Hertz) or the mass is infinite.
  double max_depth = 0;
  double contact_duration = 0;
  // Found by stepping the scene ahead (LookAhead) rather than from the
  // current speeds and gravity: the seconds until the touch.
  std::optional<double> looked_ahead;
  // contact_duration / kStepsPerContact.
  double timestep() const { return contact_duration / kStepsPerContact; }
};

// A body the contact force cannot move: the world, a static body, a driven one.
// What a pair brings to its first touch, found by stepping ahead.
struct Approach {
  double rate = 0;            // d' at the last state before the touch, m/s
  double effective_mass = 0;  // along the normal through the joint chains, kg
  double time = 0;            // s from now
};

// Steps a copy of the data (MuJoCo alone, the laws not acting: nothing
// changes before the first touch) until pair is about to touch, for at most
// 2 s of simulated time: what a pendulum, a body on a free body or anything
// jointed brings to the contact. nullopt when it does not touch by then.
std::optional<Approach> LookAhead(const ContactData& contacts, int pair);

// A tag with more pairs than this is not looked ahead (a group tag of many
// bodies would step the scene once per pair).
inline constexpr int kLookAheadPairs = 16;

bool Immovable(const ContactModel& model, int body);

// The rate at which gravity closes pair's gap along normal (from geom[0]
// towards geom[1]), m/s^2: the difference of the two bodies' accelerations
// (a body that cannot move does not fall).
double GravityClosingAcceleration(const ContactModel& model, const GeomPair& pair,
                                  const mjtNum normal[3]);
// The same for any two bodies (body[0] moving away from normal's origin).
double GravityClosingAcceleration(const ContactModel& model, const std::array<int, 2>& body,
                                  const mjtNum normal[3]);

// The closing speed at touch, m/s, of a gap (m, < 0 counts as 0) closing at
// speed closing and acceleration accel (> 0: closing): sqrt(v^2 + 2 a gap),
// 0 when the gap never closes.
double SpeedAtTouch(double closing, double accel, double gap);

// The translational effective mass of pair along the line of impact, kg, as
// ContactEstimate::effective_mass.
double PairEffectiveMass(const ContactModel& model, int pair);

// Estimates pair (ContactModel::pairs() index) at the data's current state
// (call mj_forward first). impact_velocity, when given (m/s, > 0), replaces
// the estimated closing speed.
ContactEstimate EstimateContact(const ContactData& contacts, int pair,
                                std::optional<double> impact_velocity = std::nullopt);

// The pair of a tag whose estimated contact is shortest (it decides the
// timestep), and its estimate.
struct TagEstimate {
  int pair = -1;  // ContactModel::pairs() index
  ContactEstimate estimate;
  // Steps of timestep in the estimated contact (infinite when not estimated).
  double StepsPerContact(double timestep) const { return estimate.contact_duration / timestep; }
};
TagEstimate EstimateTag(const ContactData& contacts, int tag,
                        std::optional<double> impact_velocity = std::nullopt);

// The tangential dynamics of a pair with friction, before the run: its
// TangentialDuration on the pair's friction_mass, at the estimated elastic
// depth of normal (or the overlap at the start): the stick spring's k_t given
// by the tag or Mindlin's there, and the load the larger of the pair's weight
// (friction_mass |gravity|) and the law's spring force there.
struct TangentialEstimate {
  double stiffness = 0;     // N/m: k_t, or LuGre's sigma0 F_n; 0 for regularized
  double damping = 0;       // N s/m: c_t (coulomb, stribeck: TangentialDamping)
  double mass = 0;          // kg, GeomPair::friction_mass
  double normal_force = 0;  // N, the load assumed
  // s, TangentialDuration (infinite: none, or not estimated)
  double duration = std::numeric_limits<double>::infinity();
  // "stick spring (coulomb, k_t 1e+07 N/m, mass 1 kg)": what sets it
  std::string what;
  // The period 2 duration in kStepsPerContact steps (a critically damped
  // spring: 2 pi sqrt(m / k) / 20).
  double timestep() const { return 2 * duration / kStepsPerContact; }
  // "period 0.0002 s", or for a damper (regularized: no spring, no period)
  // "lag 1e-05 s", the step it needs
  std::string Span() const;
};
TangentialEstimate EstimateTangential(const ContactModel& model, int pair,
                                      const ContactEstimate& normal);

// The longest fixed step on a law's damper, in its lags: an explicit step is
// stable on a damper up to 2.8 lags (RK4; 2, Euler): measured, a box placed
// on a floor rests right at 2.5 lags and hangs at 60% of its weight at 3.1.
inline constexpr double kFixedStepDamperLags = 2;

// The law's damping of a pair at rest under its weight, before the run: a
// contact settling at the v0 floor is a stiff damper (RestingDamperLag).
struct RestingEstimate {
  double load = 0;  // N, the weight: normal.effective_mass x |gravity|
  // s, RestingDamperLag (infinite: elastic, no gravity, an immovable pair)
  double lag = std::numeric_limits<double>::infinity();
  double timestep() const { return kFixedStepDamperLags * lag; }
};
RestingEstimate EstimateResting(const ContactModel& model, int pair,
                                const ContactEstimate& normal);

}  // namespace contactlaws

#endif  // CONTACTLAWS_SIM_ESTIMATE_H_
