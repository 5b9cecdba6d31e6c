// Copyright contactlaws authors.
//
// Peer program: the bouncing ball of mjcf/bouncing_ball.xml in Simbody, with
// Simbody's own HuntCrossleyForce, so that contactlaws' Hunt-Crossley ball can
// be compared with an independent engine (bench/peer_simbody.sh).
//
// Scene (mjcf/bouncing_ball.xml): a free ball, mass 1 kg, inertia 0.1 kg m^2,
// radius R = 0.1 m, centre released from rest at z = 1 m above the plane z = 0,
// gravity 9.81 m/s^2 along -z, K = 1.4e8 N/m^1.5, n = 1.5, no friction.
//
// Force-law mapping (exact; read from Simbody 3.7's HuntCrossleyForceImpl.h
// and HuntCrossleyForce.cpp, which the header's prose does not spell out):
//   setBodyParameters(surface, stiffness s_i, dissipation c_i, ...) stores
//   p_i = s_i^(2/3); per contact s1 = p2 / (p1 + p2), k = p1 s1,
//   c = c1 s1 + c2 (1 - s1), fH = 4/3 k x sqrt(R k x) = 4/3 k^(3/2) sqrt(R) x^(3/2),
//   f = fH (1 + 3/2 c x') (no force if f <= 0), x = depth, x' = depth rate
//   (> 0 approaching), R = the sphere radius for a sphere on a half-space.
// contactlaws' Hunt-Crossley: F = K x^1.5 (1 + a x'/v0), a = 3 (1 - e) / 2,
// clamped to F >= 0. Give both surfaces the same s and c: then s1 = 1/2,
//   k^(3/2) = (s^(2/3) / 2)^(3/2) = s / 2^(3/2), fH = (sqrt(2) / 3) sqrt(R) s x^1.5,
// so   s = 3 K / sqrt(2 R)                 (K = 1.4e8, R = 0.1: s = 9.3915e8)
// and  3/2 c = a / v0  =>  c = (1 - e) / v0 (s/m),
// with v0 the impact speed. contactlaws takes v0 = d' at first touch; here v0
// is the analytic free-fall speed at touch, sqrt(vz0^2 + 2 g (z0 - R)), which
// is the same number (4.2021423107743 m/s), so the first impact sees the same
// force law. (Later impacts would need a per-impact v0; only the first
// rebound is measured.)
//
// Measured: e_post = separation speed / impact speed of the first impact.
// Outside the contact the ball is in free fall, so the speeds at the touch and
// separation height z = R are recovered exactly from the last state before
// touch and the first state after separation: v(R)^2 = vz^2 + 2 g (z - R).
//
// Usage: simbody_ball [--restitution E] [--accuracy TOL] [--duration T]
//                     [--max-step H] [--check-force]
// --check-force: instead of simulating, set the ball at a few depths and depth
// rates, ask Simbody's HuntCrossleyForce for its force, print it against
// K x^1.5 (1 + a x'/v0) and exit 1 if any differs by more than 1e-12 relative.
// Prints key=value lines: e_post, impact_speed, separation_speed, steps,
// loop_wall_s (the stepping loop only), and the parameters used.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "Simbody.h"

using namespace SimTK;

namespace {

constexpr double kMass = 1.0;        // kg
constexpr double kInertia = 0.1;     // kg m^2
constexpr double kRadius = 0.1;      // m
constexpr double kHeight = 1.0;      // m, initial centre height
constexpr double kVz0 = 0.0;         // m/s, initial vertical velocity
constexpr double kGravity = 9.81;    // m/s^2
constexpr double kStiffness = 1.4e8; // K, N/m^1.5

[[noreturn]] void Usage(const char* why) {
  std::fprintf(stderr,
               "simbody_ball: %s\n"
               "usage: simbody_ball [--restitution E] [--accuracy TOL] "
               "[--duration T] [--max-step H]\n",
               why);
  std::exit(2);
}

double Number(int argc, char** argv, int& i) {
  if (i + 1 >= argc) Usage("missing value");
  char* end = nullptr;
  double v = std::strtod(argv[++i], &end);
  if (end == argv[i] || *end != '\0') Usage("not a number");
  return v;
}

// Speed at z = R of a ball in free fall at height z with vertical speed vz.
double SpeedAtTouchHeight(double z, double vz) {
  return std::sqrt(vz * vz + 2.0 * kGravity * (z - kRadius));
}

}  // namespace

int main(int argc, char** argv) {
  double restitution = 0.8, accuracy = 1e-6, duration = 2.0, max_step = 0.0;
  bool check_force = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--restitution")) restitution = Number(argc, argv, i);
    else if (!std::strcmp(argv[i], "--accuracy")) accuracy = Number(argc, argv, i);
    else if (!std::strcmp(argv[i], "--duration")) duration = Number(argc, argv, i);
    else if (!std::strcmp(argv[i], "--max-step")) max_step = Number(argc, argv, i);
    else if (!std::strcmp(argv[i], "--check-force")) check_force = true;
    else Usage((std::string("unknown option ") + argv[i]).c_str());
  }
  if (!(restitution >= 0 && restitution <= 1)) Usage("restitution not in [0, 1]");
  if (!(accuracy > 0) || !(duration > 0) || !(max_step >= 0)) Usage("bad value");

  // The force-law mapping (see the top of this file).
  const double v0 = SpeedAtTouchHeight(kHeight, kVz0);
  const double a = 1.5 * (1.0 - restitution);
  const double simbody_stiffness = 3.0 * kStiffness / std::sqrt(2.0 * kRadius);
  const double simbody_dissipation = (1.0 - restitution) / v0;

  MultibodySystem system;
  SimbodyMatterSubsystem matter(system);
  GeneralForceSubsystem forces(system);
  Force::UniformGravity gravity(forces, matter, Vec3(0, 0, -kGravity));
  GeneralContactSubsystem contacts(system);
  const ContactSetIndex set = contacts.createContactSet();

  Body::Rigid body(MassProperties(kMass, Vec3(0), Inertia(kInertia)));
  MobilizedBody::Free ball(matter.Ground(), Transform(), body, Transform());
  contacts.addBody(set, ball, ContactGeometry::Sphere(kRadius), Transform());
  // A HalfSpace occupies x > 0 of its frame; turn +x to -z: the floor is z <= 0.
  contacts.addBody(set, matter.updGround(), ContactGeometry::HalfSpace(),
                   Transform(Rotation(Pi / 2, YAxis), Vec3(0)));

  HuntCrossleyForce hc(forces, contacts, set);
  for (int s = 0; s < 2; ++s)
    hc.setBodyParameters(ContactSurfaceIndex(s), simbody_stiffness,
                         simbody_dissipation, 0, 0, 0);

  State state = system.realizeTopology();
  ball.setQToFitTranslation(state, Vec3(0, 0, kHeight));
  ball.setUToFitLinearVelocity(state, Vec3(0, 0, kVz0));

  if (check_force) {
    double worst = 0;
    for (double x : {1e-5, 3e-4, 1.7e-3}) {
      for (double xdot : {v0, 0.3 * v0, 0.0, -0.5 * v0}) {
        State s = state;
        ball.setQToFitTranslation(s, Vec3(0, 0, kRadius - x));
        ball.setUToFitLinearVelocity(s, Vec3(0, 0, -xdot));
        system.realize(s, Stage::Dynamics);
        Vector_<SpatialVec> body_forces(matter.getNumBodies(), SpatialVec(Vec3(0), Vec3(0)));
        Vector_<Vec3> particle_forces(0);
        Vector mobility_forces(matter.getNumMobilities(), Real(0));
        hc.calcForceContribution(s, body_forces, particle_forces, mobility_forces);
        const double simbody = body_forces[ball.getMobilizedBodyIndex()][1][2];
        const double law =
            std::max(0.0, kStiffness * std::pow(x, 1.5) * (1.0 + a * xdot / v0));
        const double rel = std::abs(simbody - law) / law;
        worst = std::max(worst, rel);
        std::printf("depth=%-8g rate=%-10.6g simbody_N=%-22.17g law_N=%-22.17g rel=%.2e\n",
                    x, xdot, simbody, law, rel);
      }
    }
    std::printf("worst_rel=%.2e\n", worst);
    return worst <= 1e-12 ? 0 : 1;
  }

  RungeKuttaMersonIntegrator integ(system);
  integ.setAccuracy(accuracy);
  if (max_step > 0) integ.setMaximumStepSize(max_step);
  integ.setReturnEveryInternalStep(true);
  integ.initialize(state);

  // Phases of the first impact: 0 before touch, 1 in contact, 2 done.
  int phase = 0;
  double prev_z = kHeight, prev_vz = kVz0;
  double impact_speed = 0, separation_speed = 0, t_touch = 0, t_sep = 0;

  const auto start = std::chrono::steady_clock::now();
  while (integ.getTime() < duration) {
    const Integrator::SuccessfulStepStatus status = integ.stepTo(duration);
    if (status == Integrator::EndOfSimulation) break;
    if (phase == 2) continue;
    const State& s = integ.getState();
    system.realize(s, Stage::Velocity);
    const double z = ball.getBodyOriginLocation(s)[2];
    const double vz = ball.getBodyOriginVelocity(s)[2];
    if (phase == 0 && z < kRadius) {
      impact_speed = SpeedAtTouchHeight(prev_z, prev_vz);
      t_touch = s.getTime();
      phase = 1;
    } else if (phase == 1 && z >= kRadius) {
      separation_speed = SpeedAtTouchHeight(z, vz);
      t_sep = s.getTime();
      phase = 2;
    }
    prev_z = z;
    prev_vz = vz;
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::printf("engine=simbody\n");
  std::printf("restitution=%.17g\naccuracy=%.17g\nduration=%.17g\n", restitution,
              accuracy, duration);
  std::printf("hc_coefficient_a=%.17g\nv0=%.17g\n", a, v0);
  std::printf("simbody_stiffness=%.17g\nsimbody_dissipation=%.17g\n",
              simbody_stiffness, simbody_dissipation);
  if (phase == 2) {
    std::printf("e_post=%.17g\n", separation_speed / impact_speed);
    std::printf("impact_speed=%.17g\nseparation_speed=%.17g\n", impact_speed,
                separation_speed);
    std::printf("first_step_in_contact_t=%.17g\nfirst_step_after_t=%.17g\n", t_touch,
                t_sep);
  } else {
    std::printf("e_post=nan\n");
  }
  std::printf("steps=%d\nsteps_attempted=%d\nloop_wall_s=%.9g\n",
              integ.getNumStepsTaken(), integ.getNumStepsAttempted(), wall);
  std::printf("final_t=%.17g\n", integ.getTime());
  return phase == 2 ? 0 : 1;
}
