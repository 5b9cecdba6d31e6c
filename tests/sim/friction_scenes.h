// Copyright contactlaws authors.
//
// The inline scenes of the friction tests: a ball or a block (1 kg) on a
// floor under gravity that may be tilted (an incline), with a soft contact
// (K = 1e6 N/m^1.5, static depth ~0.5 mm) so that the stick spring is
// resolved at 1e-4 s (its period ~0.02 s); RK4.

#ifndef CONTACTLAWS_TESTS_SIM_FRICTION_SCENES_H_
#define CONTACTLAWS_TESTS_SIM_FRICTION_SCENES_H_

#include <cmath>
#include <cstdio>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "contactlaws/simulation.h"

namespace contactlaws::testing {

inline constexpr double kG = 9.81;          // m/s^2
inline constexpr double kRadius = 0.1;      // ball, m
inline constexpr double kHalf = 0.05;       // block half size, m
inline constexpr double kStiffness = 1e6;   // N/m^1.5
inline constexpr double kTimestep = 1e-4;   // s

// The depth at which K d^1.5 carries load (N), m.
inline double StaticDepth(double load) { return std::pow(load / kStiffness, 2.0 / 3.0); }

// The lever of a ball resting at depth d: the contact point sits midway
// between the surfaces, R - d/2 below the centre.
inline double Lever(double load) { return kRadius - 0.5 * StaticDepth(load); }

// A scene: gravity (gx, 0, -gz), a floor, and one body (a ball or a block,
// 1 kg) resting on it at its static depth with velocity qvel (6 numbers);
// friction_keys added to the tag.
inline std::string FrictionScene(bool ball, double gx, double gz, const std::string& qvel,
                                 const std::string& friction_keys,
                                 const std::string& geom_extra = "") {
  const double z = ball ? kRadius - StaticDepth(gz) : kHalf - StaticDepth(gz / 4);
  const std::string geom =
      ball ? fmt::format(R"(type="sphere" size="{}")", kRadius)
           : fmt::format(R"(type="box" size="{0} {0} {0}")", kHalf);
  return fmt::format(R"(<mujoco>
  <option timestep="{0}" integrator="RK4" gravity="{1} 0 {2}"/>
  <worldbody>
    <geom name="floor" type="plane" size="50 50 0.1" {7}/>
    <body name="body" pos="0 0 {3}"><freejoint/>
      <geom name="body" {4} mass="1" {7}/></body>
  </worldbody>
  <keyframe><key qpos="0 0 {3} 1 0 0 0" qvel="{5}"/></keyframe>
  <custom><text name="contactlaw:contact" data="geom1=body geom2=floor law=hunt-crossley
    restitution=0.5 stiffness={6} {8}"/></custom>
</mujoco>)",
                     kTimestep, gx, -gz, z, geom, qvel, kStiffness, geom_extra, friction_keys);
}

// Gravity tilted by theta about y: an incline along +x.
inline std::string Incline(bool ball, double tan_theta, const std::string& keys) {
  const double c = 1 / std::sqrt(1 + tan_theta * tan_theta);
  return FrictionScene(ball, kG * tan_theta * c, kG * c, "0 0 0 0 0 0", keys);
}

// Gravity off, a ball 0.1 mm above the floor, moving down at 1 m/s and
// along x at vt, no spin: an oblique impact; mu the tag's friction.
inline std::string ObliqueImpact(double vt, double mu) {
  const double z = kRadius + 1e-4;
  return fmt::format(R"(<mujoco>
  <option timestep="{0}" integrator="RK4" gravity="0 0 0"/>
  <worldbody>
    <geom name="floor" type="plane" size="50 50 0.1"/>
    <body name="ball" pos="0 0 {1}"><freejoint/>
      <geom name="ball" type="sphere" size="{2}" mass="1"/></body>
  </worldbody>
  <keyframe><key qpos="0 0 {1} 1 0 0 0" qvel="{3} 0 -1 0 0 0"/></keyframe>
  <custom><text name="contactlaw:c" data="geom1=ball geom2=floor law=hunt-crossley restitution=0.5
    stiffness={4} mu={5}"/></custom>
</mujoco>)",
                     kTimestep, z, kRadius, vt, kStiffness, mu);
}

// Steps sim until time t (to within half its step).
inline void RunUntil(Simulation& sim, double t) {
  while (sim.time() < t - 0.5 * sim.model()->opt.timestep) sim.Step();
}

inline double X(const Simulation& sim) { return sim.data()->qpos[0]; }
inline double Vx(const Simulation& sim) { return sim.data()->qvel[0]; }
// the spin about y (> 0 rolls forwards along +x)
inline double Wy(const Simulation& sim) { return sim.data()->qvel[4]; }

// The block of FrictionScene launched at v0 along +x on a level floor, at
// rest by now: it stopped after v0^2 / (2 mu g), its kinetic energy went to
// friction (and a little to the normal law's damping as it settled), and
// the ledger's total is the start's. name labels the printed numbers.
inline void ExpectKineticStop(Simulation& sim, double mu, double v0, double start_total,
                              const char* name) {
  const double distance = v0 * v0 / (2 * mu * kG);
  // The four corners share the weight through springs that rock a little as
  // the friction tips the block forward (the moment mu m g h): measured
  // 8.1e-4 of the distance short (coulomb), 4.1e-4 long (lugre, its
  // presliding mu / sigma0 = 4 um included), 6.9e-4 long (lugre under auto).
  constexpr double kDistanceTolerance = 5e-3;  // relative
  EXPECT_NEAR(X(sim), distance, kDistanceTolerance * distance);
  // at rest: the block rocks a little on its corner springs after the stop
  // (measured 3.3e-5 m/s at 0.5 s, 0.37 s after it)
  constexpr double kRestSpeed = 1e-4;  // m/s
  EXPECT_NEAR(Vx(sim), 0, kRestSpeed);
  mj_forward(sim.model(), sim.data());
  const EnergyLedger e = sim.Energy();
  // Measured, the total against the start: below 2e-6 of 1/2 m v0^2
  // (coulomb); +3.9e-4 and +7.1e-4 (lugre at 1e-4 s and under auto: the bristles settle
  // at the start within less than a step's slip, which the trapezoid of
  // friction's power misses in part, as in friction_energy_test)
  const double kinetic = 0.5 * v0 * v0;
  constexpr double kLedgerTolerance = 1e-2;  // relative to 1/2 m v0^2
  EXPECT_NEAR(e.dissipated, kinetic, kLedgerTolerance * kinetic);
  EXPECT_NEAR(e.total(), start_total, kLedgerTolerance * kinetic);
  std::printf("%s: x %.7f of %.7f, dissipated %.6f, total %.6f -> %.6f\n", name, X(sim), distance,
              e.dissipated, start_total, e.total());
}

// The ball of ObliqueImpact(vt0, mu) after its first impact, in gross
// sliding (vt0 > 7/2 mu (1 + e) v_n): the impulse law, v_t' = vt0 - mu (1 +
// e) v_n and w R = 5/2 mu (1 + e) v_n.
inline void ExpectImpulseLaw(const Simulation& sim, const Episode& impact, double mu, double vt0,
                             const char* name) {
  const double e = impact.restitution_post();
  const double vn = impact.impact_velocity;
  // the contact point sits at R - d/2 during the impact (d up to 4.2% of R):
  // the spin's lever is short by up to 2.1% (measured 1.7%)
  constexpr double kImpulseTolerance = 2.5e-2;  // relative
  const double vt = vt0 - mu * (1 + e) * vn;
  EXPECT_NEAR(Vx(sim), vt, kImpulseTolerance * (vt0 - vt));
  const double spin = 2.5 * mu * (1 + e) * vn;
  EXPECT_NEAR(sim.data()->qvel[4] * kRadius, spin, kImpulseTolerance * spin);
  std::printf("%s: e %.4f, vt' %.5f (%.5f), wR %.5f (%.5f)\n", name, e, Vx(sim), vt,
              sim.data()->qvel[4] * kRadius, spin);
}

}  // namespace contactlaws::testing

#endif  // CONTACTLAWS_TESTS_SIM_FRICTION_SCENES_H_
