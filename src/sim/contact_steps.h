// Copyright contactlaws authors.
//
// The steps the auto timestep (auto_timestep.h) gives a contact, as functions
// of the accuracy's steps per contact: the step that resolves a normal
// contact of a known duration, the step of its tangential dynamics and that
// of a settled contact, and the lag of a pair's law damping. `check` reports
// them from the same functions.

#ifndef CONTACTLAWS_SIM_CONTACT_STEPS_H_
#define CONTACTLAWS_SIM_CONTACT_STEPS_H_

#include <algorithm>
#include <vector>

#include "contactlaws/auto_timestep.h"
#include "contactlaws/contact_data.h"
#include "contactlaws/contact_model.h"

namespace contactlaws {

// The step the auto timestep takes, as its rules bound it, and the pace it
// keeps: the same step but for the cuts that land it on a pair's predicted
// touch or separation. The next step grows from the pace: a landing is a
// sliver of a fine step (kTouchOvershoot of it past a touch), and growing
// from it took ~10 steps back to the fine step after every touch (64 balls
// in a box: 2/3 of the steps).
struct StepBound {
  double step;  // s
  double pace;  // s, >= step
  // A rule's bound on both.
  void Limit(double bound) {
    step = std::min(step, bound);
    pace = std::min(pace, bound);
  }
  // A landing at landing (s) on a pair that asks for pace_bound otherwise.
  void Land(double landing, double pace_bound) {
    Limit(pace_bound);
    step = std::min(step, landing);
  }
};

// Steps per contact duration, by the law's family.
class ContactSteps {
 public:
  // The accuracy's (StepsPerContact, KelvinVoigtStepsPerContact).
  explicit ContactSteps(double accuracy);
  ContactSteps(double hertz_family, double kelvin_voigt)
      : hertz_family_(hertz_family), kelvin_voigt_(kelvin_voigt) {}

  // Steps per contact duration of law.
  double PerContact(LawId law) const;
  // The step that resolves a contact of law lasting duration (s).
  double NormalStep(LawId law, double duration) const { return duration / PerContact(law); }
  // The step of a tangential dynamics of TangentialDuration duration
  // (s): its period, twice that, as a contact's duration.
  double TangentialStep(double duration) const { return 2 * duration / hertz_family_; }

 private:
  double hertz_family_;
  double kelvin_voigt_;
};

// The law's view of an evaluated point of a pair of effective mass m (kg):
// its depth, depth rate and v0.
ContactState PointState(const PointEvaluation& e, double effective_mass);

// The lag m / c (s) of a pair's law damping: its points' dampers
// (DampingCoefficient at PointState) act in parallel, c (N s/m) their sum,
// on the pair's effective mass m (kg). Infinite without damping. The auto
// timestep keeps a contact's steps within one lag; a fixed step is warned
// beyond kFixedStepDamperLags (estimate.h).
double DamperLag(double effective_mass, double damping);

// c of pair's points at the latest evaluation of contacts, added (N s/m).
double PairDamping(const ContactData& contacts, int pair, double effective_mass);

// The fine and settled steps of each pair of a model: its elastic contact
// duration (as a power of the impact speed) over ContactSteps.
class PairSteps {
 public:
  // effective_mass: per pair, kg (PairEffectiveMass).
  PairSteps(const ContactModel& cm, const std::vector<double>& effective_mass,
            const ContactSteps& steps);

  // The fine step of pair at impact speed v (m/s), floored at the law's
  // min_impact_velocity.
  double Fine(int pair, double v) const;
  // The step of a settled contact of pair: the elastic contact
  // duration at the floor speed over kSettledStepsPerContact.
  double Settled(int pair) const;
  // Steps per contact duration of pair's law.
  double PerContact(int pair) const { return steps_.PerContact(law_[pair]); }
  const ContactSteps& steps() const { return steps_; }

 private:
  // the elastic contact duration of pair at speed v, s
  double Duration(int pair, double v) const;

  ContactSteps steps_;
  std::vector<LawId> law_;
  std::vector<double> floor_;  // min_impact_velocity, m/s
  // the elastic contact duration at 1 m/s, and its exponent of v: t_c is
  // proportional to v^((1 - n) / (1 + n)) (Hertz family; Kelvin-Voigt: v^0)
  std::vector<double> duration_at_unit_speed_;
  std::vector<double> duration_speed_exponent_;
  std::vector<double> fine_at_floor_;  // Fine at the floor speed, s
  std::vector<double> settled_;        // Settled, s
};

}  // namespace contactlaws

#endif  // CONTACTLAWS_SIM_CONTACT_STEPS_H_
