// Copyright contactlaws authors.
//
// The inline scenes of the friction tests: a ball or a block (1 kg) on a
// floor under gravity that may be tilted (an incline), with a soft contact
// (K = 1e6 N/m^1.5, static depth ~0.5 mm) so that the stick spring is
// resolved at 1e-4 s (its period ~0.02 s); RK4.

#ifndef CONTACTLAWS_TESTS_SIM_FRICTION_SCENES_H_
#define CONTACTLAWS_TESTS_SIM_FRICTION_SCENES_H_

#include <cmath>
#include <string>

#include <fmt/format.h>

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

}  // namespace contactlaws::testing

#endif  // CONTACTLAWS_TESTS_SIM_FRICTION_SCENES_H_
