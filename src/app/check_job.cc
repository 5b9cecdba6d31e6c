// Copyright contactlaws authors.

#include "app/check_job.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <memory>
#include <utility>

#include "sim/contact_steps.h"
#include "sim/estimate.h"
#include "sim/start_contact.h"
#include "sim/timestep_advice.h"

namespace contactlaws::app {

namespace {

// Appends the formatted text to out.
template <typename... Args>
void Print(std::string* out, fmt::format_string<Args...> format, Args&&... args) {
  fmt::format_to(std::back_inserter(*out), format, std::forward<Args>(args)...);
}

// A number in its shortest exact form (fmt's "{}"), "" when not known.
std::string Shortest(const std::optional<double>& value) {
  return value && std::isfinite(*value) ? fmt::format("{}", *value == 0 ? 0.0 : *value) : "";
}

// The scene's MuJoCo settings, and the rule the estimates are held to.
void PrintSettings(const Simulation& sim, std::string* out) {
  const mjModel* m = sim.model();
  const char* integrators[] = {"euler", "rk4", "implicit"};

  Print(out, "{}: MuJoCo {}.{}.{}, timestep {} s, integrator {}, gravity ({}, {}, {}) m/s^2\n",
        sim.source(), MujocoVersion() / 100, MujocoVersion() / 10 % 10, MujocoVersion() % 10,
        m->opt.timestep,
        m->opt.integrator >= 0 && m->opt.integrator < 3 ? integrators[m->opt.integrator] : "?",
        m->opt.gravity[0], m->opt.gravity[1], m->opt.gravity[2]);
  Print(out, "rule: a contact is resolved by >= {} steps of its estimated duration\n",
        kStepsPerContact);
}

// The friction of a tag's pair, and the step its tangential dynamics need
// (EstimateTangential: kStepsPerContact steps per period); true when the
// timestep is too coarse.
bool PrintFriction(const ContactModel& cm, int pair_index, const ContactEstimate& estimate,
                   double dt, std::optional<double> accuracy, const OptionReader& names,
                   std::string* out) {
  const GeomPair& pair = cm.pairs()[pair_index];
  const FrictionParams& f = pair.friction;
  if (f.kind == FrictionKind::kNone) {
    Print(out, "  friction none{}\n",
          pair.condim == 1 ? " (condim 1: frictionless, as in MuJoCo)" : "");
    return false;
  }
  Print(out, "  friction {}: mu_static {}, mu_kinetic {}, condim {}{}{}\n", FrictionName(f.kind),
        f.mu_static, f.mu_kinetic, pair.condim,
        f.torsional > 0 ? fmt::format(", torsional {} m", f.torsional) : "",
        f.rolling > 0 ? fmt::format(", rolling {} m", f.rolling) : "");
  const TangentialEstimate t = EstimateTangential(cm, pair_index, estimate);
  if (accuracy) {
    // the auto timestep's own rule at that accuracy (auto_timestep.h)
    Print(out, "  tangential: {}: {}: {}: steps of <= {:.3g} s in contact\n", t.what, t.Span(),
          names.Given("timestep", "auto"), ContactSteps(*accuracy).TangentialStep(t.duration));
    return false;
  }
  const double step = t.timestep();
  const bool ok = !(std::isfinite(step)) || dt <= step;
  Print(out, "  tangential: {}: {}: {} (needs timestep <= {:.3g} s)\n", t.what, t.Span(),
        ok ? "ok" : "TOO COARSE", step);
  return !ok;
}

// The lag of the law's damping at rest under the pair's weight (a contact
// settling at the v0 floor: EstimateResting); true when the timestep is too
// coarse for it.
bool PrintResting(const ContactModel& cm, int pair_index, const ContactEstimate& estimate,
                  double dt, bool automatic, const OptionReader& names, std::string* out) {
  const RestingEstimate r = EstimateResting(cm, pair_index, estimate);
  if (!std::isfinite(r.lag)) return false;
  const bool ok = automatic || dt <= r.timestep();
  Print(out,
        "  at rest: damping lag {:.3g} s under the weight {:.4g} N at the v0 floor {} m/s: "
        "{} (needs timestep <= {:.3g} s{})\n",
        r.lag, r.load, cm.pairs()[pair_index].params.min_impact_velocity,
        automatic ? names.Given("timestep", "auto") + " keeps to it"
        : ok      ? "ok"
                  : "TOO COARSE",
        r.timestep(), ok ? "" : ", or a larger min_impact_velocity");
  return !ok;
}

// The lag of the law's damping where the tag's pairs start in contact when it
// is shorter than rest_lag, the one at rest (s: ShorterStartLag); true when
// the timestep is too coarse for it.
bool PrintStart(const Simulation& sim, int tag, const std::vector<StartContact>& starts,
                double rest_lag, bool automatic, const OptionReader& names, std::string* out) {
  const StartContact* shortest = ShorterStartLag(sim.contact_model(), tag, starts, rest_lag);
  if (!shortest) return false;
  const bool ok = automatic || sim.model()->opt.timestep <= shortest->timestep();
  Print(out,
        "  at the start: damping lag {:.3g} s at the depth {:.4g} m of {}, its law's force "
        "{:.4g} N against the load {:.4g} N: {} (needs timestep <= {:.3g} s{})\n",
        shortest->lag, shortest->depth, PairName(sim, shortest->pair), shortest->force,
        shortest->load,
        automatic ? names.Given("timestep", "auto") + " keeps to it"
        : ok      ? "ok"
                  : "TOO COARSE",
        shortest->timestep(), ok ? "" : ", or " + names.Set("settle"));
  return !ok;
}

// Tag t resolved, its estimated contact and the timestep it needs; true when
// the timestep is too coarse for the estimate.
bool PrintTag(Simulation* sim, int t, const std::vector<StartContact>& starts,
              std::optional<double> impact_velocity, std::optional<double> accuracy,
              const OptionReader& names, std::string* out) {
  const mjModel* m = sim->model();
  const ContactModel& cm = sim->contact_model();
  const double dt = m->opt.timestep;
  const PairTag& tag = cm.tags()[t];
  const LawParams& law = cm.pairs()[tag.pairs.front()].params;
  Print(out, "\ncontactlaw:{}: {} - {}, {} geom pair(s), law {}\n", tag.label, tag.geom1, tag.geom2,
        tag.pairs.size(), LawName(law.law));
  if (Law(law.law).family == LawFamily::kLinear) {
    Print(out, "  restitution {}, linear_stiffness k {} N/m, damping c {}\n", law.restitution,
          law.linear_stiffness,
          law.damping ? fmt::format("{} N s/m", *law.damping)
                      : std::string("from e and the effective mass at each contact"));
  } else {
    const std::string damping =
        ReadsDissipation(law.law)
            ? fmt::format("dissipation c {} s/m (a = c v0)", *law.dissipation)
            : fmt::format("restitution {}{}",
                          Shortest(ReportedRestitution(law.law, law.restitution)),
                          IsElastic(law.law) ? " (elastic)" : "");
    Print(out, "  {}, stiffness K {:.6g} N/m^{}, exponent n {}\n", damping, law.stiffness,
          law.exponent, law.exponent);
  }
  Print(out, "  min_impact_velocity {} m/s{}\n", law.min_impact_velocity,
        law.allow_tension ? ", allow_tension" : "");

  // the pair of this tag whose contact is shortest decides the timestep
  const TagEstimate shortest = EstimateTag(sim->contacts(), t, impact_velocity);
  const int worst = shortest.pair;
  const ContactEstimate& estimate = shortest.estimate;
  const GeomPair& pair = cm.pairs()[worst];
  Print(out, "  {}geoms {} - {}: effective mass {:.6g} kg, gap {}\n",
        tag.pairs.size() > 1 ? "shortest contact: " : "", ObjectName(m, mjOBJ_GEOM, pair.named[0]),
        ObjectName(m, mjOBJ_GEOM, pair.named[1]), estimate.effective_mass,
        estimate.gap ? fmt::format("{:.6g} m", *estimate.gap) : "out of reach");
  const std::string how =
      impact_velocity ? names.Name("impact_velocity")
      : estimate.looked_ahead
          ? fmt::format(
                "stepped ahead to the touch, {:.4g} s from now, through the joint "
                "chains",
                *estimate.looked_ahead)
          : std::string(
                "estimated: closing speed, gravity over the gap, driven bodies' top "
                "speed");
  Print(out, "  impact velocity {:.6g} m/s ({})\n", estimate.impact_velocity, how);
  // both lines are printed, whatever the first says
  const bool friction_coarse = PrintFriction(cm, worst, estimate, dt, accuracy, names, out);
  const bool resting_coarse =
      PrintResting(cm, worst, estimate, dt, accuracy.has_value(), names, out);
  const bool start_coarse = PrintStart(*sim, t, starts, EstimateResting(cm, worst, estimate).lag,
                                       accuracy.has_value(), names, out);
  // beside the duration
  const bool side_coarse = friction_coarse || resting_coarse || start_coarse;
  if (!std::isfinite(estimate.contact_duration)) {
    Print(out,
          "  contact duration: not estimated (nothing brings the geoms together, or "
          "neither can move); give {}\n",
          names.Name("impact_velocity"));
    return side_coarse;  // nothing to hold the normal's timestep to
  }
  Print(out, "  elastic ({}) contact: max depth {:.4g} m, duration {:.4g} s\n",
        Law(law.law).family == LawFamily::kLinear ? "k d" : "K d^n", estimate.max_depth,
        estimate.contact_duration);
  if (accuracy) {
    // the auto timestep's own rule at that accuracy (auto_timestep.h)
    const ContactSteps steps(*accuracy);
    Print(out,
          "  {}: steps of {:.3g} s near and in this contact ({:.0f} per "
          "contact, accuracy {})\n",
          names.Given("timestep", "auto"), steps.NormalStep(law.law, estimate.contact_duration),
          steps.PerContact(law.law), *accuracy);
    return side_coarse;
  }
  const double steps = estimate.contact_duration / dt;
  const bool ok = steps >= kStepsPerContact;
  Print(out, "  {:.1f} steps per contact at {} s: {} (needs timestep <= {:.3g} s)\n", steps, dt,
        ok ? "ok" : "TOO COARSE", estimate.timestep());
  if (!ok) {
    // the contact integrated inside the step instead, at the contact steps'
    // own count per contact (ContactStepsOptions)
    const ContactStepsOptions inner;
    const ContactSteps per(inner.per_contact_hertz, inner.per_contact_linear);
    Print(out,
          "  or {}: {:.0f} sub-steps of its law and friction inside each {} s "
          "step near and in this contact ({:.0f} per contact)\n",
          names.Given("contact_steps", "auto"),
          std::ceil(dt / per.NormalStep(law.law, estimate.contact_duration)), dt,
          per.PerContact(law.law));
  }
  return !ok || side_coarse;
}

void PrintDrives(const Simulation& sim, std::string* out) {
  const mjModel* m = sim.model();
  const ContactModel& cm = sim.contact_model();
  Print(out, "\n{} driven bod{}\n", cm.drives().size(), cm.drives().size() == 1 ? "y" : "ies");
  for (const Drive& drive : cm.drives()) {
    if (drive.motion == Drive::Motion::kLinear) {
      Print(out, "contactdrive:{}: body {}, p(t) = ({}, {}, {}) + ({}, {}, {}) * {} m/s * t\n",
            drive.label, ObjectName(m, mjOBJ_BODY, drive.body), drive.ref[0], drive.ref[1],
            drive.ref[2], drive.axis[0], drive.axis[1], drive.axis[2], drive.speed);
      continue;
    }
    Print(out,
          "contactdrive:{}: body {}, p(t) = ({}, {}, {}) + ({}, {}, {}) * {} m * sin({} rad/s "
          "* t + {} rad), top speed {:.6g} m/s\n",
          drive.label, ObjectName(m, mjOBJ_BODY, drive.body), drive.ref[0], drive.ref[1],
          drive.ref[2], drive.axis[0], drive.axis[1], drive.axis[2], drive.amplitude, drive.omega,
          drive.phase, std::abs(drive.amplitude * drive.omega));
  }
}

}  // namespace

CheckRequest ReadCheck(const OptionReader& reader, const CheckInput& input) {
  CheckRequest request;
  SimulationOptions& options = request.options;
  reader.LawOverrides(input.law, input.restitution, &options.overrides);
  if (input.dissipation) options.overrides.dissipation = reader.Dissipation(*input.dissipation);
  reader.FrictionOverrides(input.friction, input.mu, &options.overrides);
  // auto (or accuracy): the contact steps are the auto timestep's;
  // otherwise a fixed step
  if (input.accuracy) request.accuracy = reader.Accuracy(*input.accuracy, input.timestep);
  const std::string* word = input.timestep ? std::get_if<std::string>(&*input.timestep) : nullptr;
  if (word && *word == "auto" && !request.accuracy) request.accuracy = kDefaultAccuracy;
  if (input.timestep && !request.accuracy) {
    options.timestep = reader.Positive("timestep", *input.timestep, "s");
  }
  if (input.impact_velocity) {
    request.impact_velocity = reader.Positive("impact_velocity", *input.impact_velocity, "m/s");
  }
  return request;
}

CheckReport Check(Simulation* sim, const CheckRequest& request, const OptionReader& reader) {
  CheckReport report;
  std::string* out = &report.text;
  const std::vector<StartContact> starts = StartContacts(sim);  // calls mj_forward
  PrintSettings(*sim, out);
  const int tags = static_cast<int>(sim->contact_model().tags().size());
  Print(out, "\n{} contactlaw tag(s)\n", tags);
  for (int t = 0; t < tags; ++t) {
    report.coarse +=
        PrintTag(sim, t, starts, request.impact_velocity, request.accuracy, reader, out);
  }
  PrintDrives(*sim, out);
  if (report.coarse) {
    Print(out, "\nwarning: {} tag(s) need a smaller timestep ({})\n", report.coarse,
          reader.Name("timestep"));
  }
  return report;
}

}  // namespace contactlaws::app
