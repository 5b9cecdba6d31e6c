// Copyright contactlaws authors.

#include "sim/contact_steps.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/estimate.h"

namespace contactlaws {

ContactSteps::ContactSteps(double accuracy)
    : ContactSteps(StepsPerContact(accuracy), KelvinVoigtStepsPerContact(accuracy)) {}

double ContactSteps::PerContact(LawId law) const {
  return Law(law).family == LawFamily::kLinear ? kelvin_voigt_ : hertz_family_;
}

ContactState PointState(const PointEvaluation& e, double effective_mass) {
  ContactState state;
  state.depth = e.depth;
  state.depth_rate = e.depth_rate;
  state.impact_velocity = e.impact_velocity;
  state.effective_mass = effective_mass;
  return state;
}

double DamperLag(double effective_mass, double damping) {
  return damping > 0 ? effective_mass / damping : std::numeric_limits<double>::infinity();
}

double PairDamping(const ContactData& contacts, int pair, double effective_mass) {
  const LawParams& law = contacts.model().pairs()[pair].params;
  double damping = 0;
  for (const PointEvaluation& e : contacts.latest()) {
    if (e.pair == pair) damping += DampingCoefficient(law, PointState(e, effective_mass));
  }
  return damping;
}

PairSteps::PairSteps(const ContactModel& cm, const std::vector<double>& effective_mass,
                     const ContactSteps& steps)
    : steps_(steps) {
  for (size_t p = 0; p < cm.pairs().size(); ++p) {
    const LawParams& law = cm.pairs()[p].params;
    law_.push_back(law.law);
    floor_.push_back(law.min_impact_velocity);
    const double n = Law(law.law).family == LawFamily::kLinear ? 1.0 : law.exponent;
    duration_at_unit_speed_.push_back(ElasticContactDuration(law, effective_mass[p], 1.0));
    duration_speed_exponent_.push_back((1 - n) / (1 + n));
    // at and below the floor speed: asked at every step of a resting contact
    const int i = static_cast<int>(p);
    fine_at_floor_.push_back(Duration(i, floor_[p]) / PerContact(i));
    settled_.push_back(Duration(i, floor_[p]) / kSettledStepsPerContact);
  }
}

double PairSteps::Duration(int pair, double v) const {
  return duration_at_unit_speed_[pair] * std::pow(v, duration_speed_exponent_[pair]);
}

double PairSteps::Fine(int pair, double v) const {
  if (v <= floor_[pair]) return fine_at_floor_[pair];  // (a NaN v stays NaN below)
  return Duration(pair, v) / PerContact(pair);
}

double PairSteps::Settled(int pair) const { return settled_[pair]; }

}  // namespace contactlaws
