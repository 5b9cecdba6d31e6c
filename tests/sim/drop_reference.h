// Copyright contactlaws authors.
//
// What the sweep tests hold the library against: the first impact of a run
// as `contactlaws restitution` takes it, and an independent integration of the
// paper's drop.

#ifndef CONTACTLAWS_TESTS_SIM_DROP_REFERENCE_H_
#define CONTACTLAWS_TESTS_SIM_DROP_REFERENCE_H_

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "contactlaws/contactlaws.h"

namespace contactlaws::testing {

// The restitutions of the paper's Fig. 7, as `--restitution 0.1:1.0:0.1`
// gives them.
inline constexpr double kPaperSweep[] = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};


// The paper's five laws: the ones the independent integration below writes
// out. The laws added since are held to the closed form (SweepTest).
inline const std::vector<LawId> kPaperLaws = {*ParseLawName("hertz"), *ParseLawName("kelvin-voigt"),
                                                *ParseLawName("hunt-crossley"),
                                                *ParseLawName("lankarani-nikravesh"), *ParseLawName("flores")};

// The sweep as `contactlaws restitution` runs it: a scene with options (the
// overrides of one run), to the end of its first contact episode.
inline Episode SweepFirstImpact(const Scene& scene, const SimulationOptions& options,
                               std::optional<AutoTimestepOptions> auto_timestep = std::nullopt,
                               long* steps = nullptr) {
  std::unique_ptr<Simulation> sim = scene.Make(options);
  AdvanceOptions advance;
  advance.duration = 2.0;
  advance.until_first_episode = true;
  advance.auto_timestep = auto_timestep;
  const AdvanceResult result = Advance(sim.get(), advance, nullptr);
  if (steps) *steps = auto_timestep ? result.steps : std::lround(sim->time() / *options.timestep);
  const std::vector<Episode>& impacts = sim->contacts().impacts();
  if (impacts.empty() || impacts.front().open) {
    ADD_FAILURE() << LawName(*options.overrides.law) << ": no closed first episode";
    return Episode{};
  }
  return impacts.front();
}

// Each (law, e) of the sweep.
inline Episode SweepFirstImpact(const Scene& scene, LawId law, double e,
                               std::optional<double> timestep = std::nullopt,
                               std::optional<AutoTimestepOptions> auto_timestep = std::nullopt,
                               long* steps = nullptr) {
  SimulationOptions options;
  options.overrides.law = law;
  options.overrides.restitution = e;
  options.timestep = timestep;
  return SweepFirstImpact(scene, options, auto_timestep, steps);
}

// ---------------------------------------------------------------------------
// An independent integration of the paper's drop: the 1-D equation
//   m d'' = m g - F(d, d'),   d = depth of the ball below the floor,
// from first touch (d = 0, d' = v0 = sqrt(2 g h0), the exact free fall) to
// separation, by classical RK4 at a step 1/20000 of the contact, with the law
// written out here from the paper's equations, not taken from the library.

struct Drop {
  double mass = 1.0;        // kg
  double gravity = 9.81;    // m/s^2
  double fall = 0.9;        // m, bottom of the ball above the floor at rest
  double stiffness = 1.4e8; // K, N/m^1.5
  double exponent = 1.5;
  double linear_stiffness = 5e6;  // k, N/m (kelvin-voigt)
};

struct Reference {
  double restitution_post = 0;
  double impact_velocity = 0;
  double max_depth = 0;
  double max_force = 0;
  double contact_duration = 0;
};

inline double ReferenceForce(const Drop& drop, LawId law, double e, double v0, double d,
                      double rate) {
  // d = 0 is the first touch (the integration starts there, separation ends
  // it before any evaluation at d <= 0): Kelvin-Voigt's force is c v0 from it
  if (d < 0) return 0;
  double f = 0;
  if (law == *ParseLawName("kelvin-voigt")) {
    // c = 2 zeta sqrt(k m), zeta from e for a linear oscillator
    const double zeta = -std::log(e) / std::sqrt(M_PI * M_PI + std::log(e) * std::log(e));
    f = drop.linear_stiffness * d + 2 * zeta * std::sqrt(drop.linear_stiffness * drop.mass) * rate;
  } else {
    double a = 0;  // paper eqs. 44 (flores), Hunt-Crossley, Lankarani-Nikravesh
    if (law == *ParseLawName("hunt-crossley")) a = 1.5 * (1 - e);
    if (law == *ParseLawName("lankarani-nikravesh")) a = 0.75 * (1 - e * e);
    if (law == *ParseLawName("flores")) a = 8 * (1 - e) / (5 * e);
    f = drop.stiffness * std::pow(d, drop.exponent) * (1 + a * rate / v0);
  }
  return std::max(f, 0.0);
}

inline Reference IntegrateDrop(const Drop& drop, LawId law, double e, int steps = 20000) {
  Reference r;
  const double v0 = std::sqrt(2 * drop.gravity * drop.fall);
  r.impact_velocity = v0;
  const double h = HertzContactDuration(drop.stiffness, drop.exponent, drop.mass, v0) / steps;
  auto accel = [&](double d, double rate) {
    return drop.gravity - ReferenceForce(drop, law, e, v0, d, rate) / drop.mass;
  };
  double t = 0, d = 0, rate = v0;
  // the force is discontinuous at d = 0 (kelvin-voigt: c v0): take the
  // one-sided limit at first touch
  r.max_force = ReferenceForce(drop, law, e, v0, 1e-300, v0);
  while (t < 1.0) {
    const double k1d = rate, k1v = accel(d, rate);
    const double k2d = rate + 0.5 * h * k1v, k2v = accel(d + 0.5 * h * k1d, rate + 0.5 * h * k1v);
    const double k3d = rate + 0.5 * h * k2v, k3v = accel(d + 0.5 * h * k2d, rate + 0.5 * h * k2v);
    const double k4d = rate + h * k3v, k4v = accel(d + h * k3d, rate + h * k3v);
    const double d_next = d + h / 6 * (k1d + 2 * k2d + 2 * k3d + k4d);
    const double rate_next = rate + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (d_next <= 0) {
      // separation inside this step: linear interpolation to d = 0, O(h^2)
      const double s = d / (d - d_next);
      r.contact_duration = t + s * h;
      r.restitution_post = -(rate + s * (rate_next - rate)) / v0;
      return r;
    }
    t += h;
    d = d_next;
    rate = rate_next;
    r.max_depth = std::max(r.max_depth, d);
    r.max_force = std::max(r.max_force, ReferenceForce(drop, law, e, v0, d, rate));
  }
  ADD_FAILURE() << "reference: no separation within 1 s";
  return r;
}

}  // namespace contactlaws::testing

#endif  // CONTACTLAWS_TESTS_SIM_DROP_REFERENCE_H_
