// Copyright contactlaws authors.

#include "sim/start_contact.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "contactlaws/contact_model.h"
#include "sim/contact_steps.h"
#include "sim/settle.h"
#include "sim/timestep_advice.h"

namespace contactlaws {
namespace {

// The force (N, world) pair's points at the latest evaluation put on body[1]
// (body[0] takes its opposite): normal and friction.
void PairForce(const ContactData& contacts, int pair, mjtNum force[3]) {
  mju_zero3(force);
  for (const PointEvaluation& e : contacts.latest()) {
    if (e.pair != pair) continue;
    mju_addToScl3(force, e.normal, e.force);
    mju_addTo3(force, e.friction);
  }
}

// The mass times acceleration (N, world) of body's subtree in d, whose
// accelerations (cacc: mj_rnePostConstraint) are a - gravity.
void SubtreeMassAcceleration(const mjModel* m, mjData* d, int body, mjtNum out[3]) {
  mju_zero3(out);
  // MuJoCo numbers a body's descendants after it
  for (int i = body; i < m->nbody; ++i) {
    int a = i;
    while (a > body) a = m->body_parentid[a];
    if (a != body) continue;
    mjtNum acc[6];
    mj_objectAcceleration(m, d, mjOBJ_BODY, i, acc, 0);
    mju_addTo3(acc + 3, m->opt.gravity);
    mju_addToScl3(out, acc + 3, m->body_mass[i]);
  }
}

// StartContact::load of pair, whose points' force on body[1] is force, along
// the normal of its deepest point; accelerated: the data after
// mj_rnePostConstraint.
double Load(const ContactModel& cm, const mjModel* m, mjData* accelerated, int pair,
            const mjtNum force[3], const mjtNum normal[3]) {
  double load = std::numeric_limits<double>::infinity();
  for (int side = 0; side < 2; ++side) {
    const int body = cm.pairs()[pair].body[side];
    if (Immovable(cm, body)) continue;
    // the direction the pair pushes this side
    mjtNum push[3];
    mju_scl3(push, normal, side == 1 ? 1.0 : -1.0);
    mjtNum ma[3];
    SubtreeMassAcceleration(m, accelerated, body, ma);
    const double own = (side == 1 ? 1.0 : -1.0) * mju_dot3(force, push);
    load = std::min(load, std::max(0.0, own - mju_dot3(ma, push)));
  }
  return std::isfinite(load) ? load : 0.0;
}

}  // namespace

double DeepStartFactor(const LawParams& law) {
  return 1 + (Law(law.law).family == LawFamily::kLinear ? 1.0 : law.exponent);
}

std::vector<StartContact> StartContacts(Simulation* sim) {
  const mjModel* m = sim->model();
  mj_forward(m, sim->data());
  const ContactData& contacts = sim->contacts();
  const ContactModel& cm = sim->contact_model();
  // each pair's points, the deepest's normal
  std::map<int, StartContact> found;
  std::map<int, const PointEvaluation*> deepest;
  for (const PointEvaluation& e : contacts.latest()) {
    StartContact& s = found[e.pair];
    s.pair = e.pair;
    ++s.points;
    s.force += e.force;
    if (e.depth > s.depth) {
      s.depth = e.depth;
      deepest[e.pair] = &e;
    }
  }
  std::vector<StartContact> starts;
  for (auto& [pair, s] : found) {
    if (s.depth > kTouchingGap) starts.push_back(s);
  }
  if (starts.empty()) return starts;
  // the accelerations of the bodies, on a copy (mj_rnePostConstraint writes
  // the data's cacc, cfrc_int and cfrc_ext)
  UniqueData accelerated(mj_makeData(m));
  mj_copyData(accelerated.get(), m, sim->data());
  mj_rnePostConstraint(m, accelerated.get());
  for (StartContact& s : starts) {
    const double mass = PairEffectiveMass(cm, s.pair);
    s.lag = DamperLag(mass, PairDamping(contacts, s.pair, mass));
    mjtNum force[3];
    PairForce(contacts, s.pair, force);
    s.load = Load(cm, m, accelerated.get(), s.pair, force, deepest[s.pair]->normal);
    s.deep = s.force > DeepStartFactor(cm.pairs()[s.pair].params) * s.load;
  }
  return starts;
}

std::vector<std::string> DeepStartWarnings(const Simulation& sim,
                                           const std::vector<StartContact>& starts,
                                           const Spelling& spelling) {
  const ContactModel& cm = sim.contact_model();
  std::vector<std::string> warnings;
  for (int t = 0; t < static_cast<int>(cm.tags().size()); ++t) {
    const StartContact* worst = nullptr;
    int deep = 0;
    for (const StartContact& s : starts) {
      if (!s.deep || cm.pairs()[s.pair].tag != t) continue;
      ++deep;
      // the largest force per load (a load of 0: any force is infinitely many)
      if (!worst || s.force * worst->load > worst->force * s.load) worst = &s;
    }
    if (!worst) continue;
    const LawParams& law = cm.pairs()[worst->pair].params;
    const std::string others =
        deep > 1 ? fmt::format(" (and {} more pair{} of its tag)", deep - 1, deep > 2 ? "s" : "")
                 : "";
    const std::string against =
        worst->load > 0
            ? fmt::format("{:.3g} times, beyond the {:.3g} times of a body placed touching; at "
                          "rest under that load its {} point{} would be {:.3g} m deep",
                          worst->force / worst->load, DeepStartFactor(law), worst->points,
                          worst->points == 1 ? "" : "s",
                          RestingDepth(law, worst->load / worst->points))
            : std::string("nothing presses it: at rest it would not touch");
    warnings.push_back(fmt::format(
        "{}{}: starts {:.4g} m deep in contact: its law pushes with {:.4g} N against the {:.4g} "
        "N that presses it ({}): the spring throws the bodies apart at t = 0, and its damper "
        "needs a shorter step there ({}); {} moves the bodies in contact into the static "
        "equilibrium of their contacts before t = 0",
        PairName(sim, worst->pair), others, worst->depth, worst->force, worst->load, against,
        spelling.command("check"), spelling.set("settle")));
  }
  return warnings;
}

}  // namespace contactlaws
