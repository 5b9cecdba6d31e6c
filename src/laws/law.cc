// Copyright contactlaws authors.

#include "contactlaws/law.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "laws/param_range.h"

namespace contactlaws {

const LawInfo& Law(LawId id) { return Laws()[static_cast<int>(id)]; }

const std::vector<LawId>& AllLaws() {
  static const std::vector<LawId> ids = [] {
    std::vector<LawId> all;
    for (const LawInfo& law : Laws()) all.push_back(law.id);
    return all;
  }();
  return ids;
}

std::string_view LawName(LawId id) { return Law(id).name; }

const std::string& LawNameList() {
  static const std::string list = [] {
    std::string names;
    for (const LawInfo& law : Laws()) {
      if (!names.empty()) names += ", ";
      names += law.name;
    }
    return names;
  }();
  return list;
}

std::optional<LawId> ParseLawName(std::string_view name) {
  for (const LawInfo& law : Laws()) {
    if (law.name == name) return law.id;
  }
  return std::nullopt;
}

double HysteresisCoefficient(LawId id, double restitution) {
  const LawInfo& law = Law(id);
  return law.hysteresis ? law.hysteresis(restitution) : 0.0;
}

void ResolveLawParams(LawParams* params) {
  params->hysteresis = HysteresisCoefficient(params->law, params->restitution);
}

namespace {

// The restitutions the law accepts.
const ParamRange& RestitutionRange(const LawInfo& law) {
  return law.restitution_excludes_zero ? kUnitRangeWithoutZero : kUnitRange;
}

}  // namespace

std::optional<double> EffectiveRestitution(LawId id, double restitution) {
  const LawInfo& law = Law(id);
  if (law.family != LawFamily::kHysteresis || !RestitutionRange(law).Contains(restitution)) {
    return std::nullopt;
  }
  return ExactRebound(HysteresisCoefficient(id, restitution));
}

bool IsElastic(LawId id) {
  const LawInfo& law = Law(id);
  return law.family == LawFamily::kHysteresis && !law.hysteresis;
}

bool ReadsRestitution(LawId id) {
  return !IsElastic(id) && Law(id).family != LawFamily::kConstantDissipation;
}

bool ReadsDissipation(LawId id) {
  return Law(id).family == LawFamily::kConstantDissipation;
}

std::optional<double> ReportedRestitution(LawId id, double restitution) {
  if (IsElastic(id)) return 1.0;
  if (!ReadsRestitution(id)) return std::nullopt;
  return restitution;
}

std::optional<ParamError> ValidateLawParams(const LawParams& p) {
  const LawInfo& law = Law(p.law);
  if (ReadsRestitution(p.law) && !RestitutionRange(law).Contains(p.restitution)) {
    const std::string requirement = RestitutionRange(law).Requirement();
    return ParamError{"restitution", p.restitution,
                      law.restitution_excludes_zero ? requirement + " for " + std::string(law.name)
                                                    : requirement};
  }
  if (law.family != LawFamily::kLinear) {
    if (!kPositiveRange.Contains(p.stiffness)) {
      return ParamError{"stiffness", p.stiffness, kPositiveRange.Requirement("N/m^n")};
    }
    if (!kExponentRange.Contains(p.exponent)) {
      return ParamError{"exponent", p.exponent, kExponentRange.Requirement()};
    }
  } else if (!kPositiveRange.Contains(p.linear_stiffness)) {
    return ParamError{"linear_stiffness", p.linear_stiffness, kPositiveRange.Requirement("N/m")};
  }
  if (p.damping && !kNonNegativeRange.Contains(*p.damping)) {
    return ParamError{"damping", *p.damping, kNonNegativeRange.Requirement("N s/m")};
  }
  if (ReadsDissipation(p.law) && !kNonNegativeRange.Contains(p.dissipation.value_or(NAN))) {
    return ParamError{"dissipation", p.dissipation.value_or(NAN),
                      "must be given, " + std::string(kNonNegativeRange.bounds) + " (s/m), for " +
                          std::string(law.name)};
  }
  if (!kPositiveRange.Contains(p.min_impact_velocity)) {
    return ParamError{"min_impact_velocity", p.min_impact_velocity,
                      kPositiveRange.Requirement("m/s")};
  }
  return std::nullopt;
}

bool ReadsEffectiveMass(const LawParams& p) {
  return Law(p.law).family == LawFamily::kLinear && !p.damping;
}

namespace {

// The spring K d^n of a Hertz-family law at depth d > 0 (pow is half the
// law's cost: computed once per depth); 0 for the linear family, whose
// spring LawForce makes.
double HertzSpring(const LawParams& p, double depth) {
  return Law(p.law).family == LawFamily::kLinear ? 0.0
                                                 : HertzForce(p.stiffness, p.exponent, depth);
}

// The law at s (depth > 0), its Hertz spring given: the spring, then its
// factor (HysteresisForce and DissipationForce, to the bit).
ContactForce LawForce(const LawParams& p, const ContactState& s, double hertz_spring) {
  ContactForce f;
  switch (Law(p.law).family) {
    case LawFamily::kLinear: {
      const double c = p.damping ? *p.damping
                                 : KelvinVoigtDamping(p.linear_stiffness, s.effective_mass,
                                                      p.restitution);
      f.elastic = p.linear_stiffness * s.depth;
      f.total = KelvinVoigtForce(p.linear_stiffness, c, s.depth, s.depth_rate);
      break;
    }
    case LawFamily::kHysteresis:
      f.elastic = hertz_spring;
      f.total = f.elastic * HysteresisFactor(p.hysteresis, s.depth_rate, s.impact_velocity);
      break;
    case LawFamily::kConstantDissipation:
      f.elastic = hertz_spring;
      f.total = f.elastic * DissipationFactor(*p.dissipation, s.depth_rate);
      break;
  }

  // a contact pushes, it does not pull
  if (!p.allow_tension) f.total = std::max(f.total, 0.0);
  return f;
}

}  // namespace

ContactForce EvaluateLaw(const LawParams& p, const ContactState& s) {
  if (s.depth <= 0.0) return ContactForce{};
  return LawForce(p, s, HertzSpring(p, s.depth));
}

double ElasticEnergy(const LawParams& p, double depth) {
  if (depth <= 0.0) return 0.0;
  if (Law(p.law).family == LawFamily::kLinear) {
    return 0.5 * p.linear_stiffness * depth * depth;
  }
  return HertzEnergy(p.stiffness, p.exponent, depth);
}

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
}  // namespace

double DampingCoefficient(const LawParams& p, const ContactState& state) {
  if (!(state.depth > 0)) return 0;
  // every law is linear in d' away from its clamp: a small step in d'
  // (a thousandth of v0) measures c
  ContactState faster = state;
  const double delta =
      1e-3 * std::max({std::abs(state.depth_rate), state.impact_velocity, p.min_impact_velocity});
  faster.depth_rate += delta;
  // the same depth: the same spring
  const double spring = HertzSpring(p, state.depth);
  return std::max(0.0,
                  (LawForce(p, faster, spring).total - LawForce(p, state, spring).total) / delta);
}

double ElasticContactDuration(const LawParams& law, double mass, double speed) {
  if (std::isinf(mass)) return std::numeric_limits<double>::infinity();
  if (Law(law.law).family == LawFamily::kLinear) return M_PI * std::sqrt(mass / law.linear_stiffness);
  return HertzContactDuration(law.stiffness, law.exponent, mass, speed);
}

double RestingDepth(const LawParams& p, double load) {
  if (!(load > 0)) return 0;
  return Law(p.law).family == LawFamily::kLinear ? load / p.linear_stiffness
                                                  : std::pow(load / p.stiffness, 1.0 / p.exponent);
}

double RestingDamperLag(const LawParams& p, double load, double mass) {
  if (!(load > 0)) return kInfinity;
  ContactState rest;
  rest.depth = RestingDepth(p, load);
  rest.impact_velocity = p.min_impact_velocity;
  rest.effective_mass = mass;
  const double c = DampingCoefficient(p, rest);
  return c > 0 && mass > 0 && std::isfinite(mass) ? mass / c : kInfinity;
}

}  // namespace contactlaws
