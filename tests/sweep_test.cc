// Copyright contactlaws authors.
//
// The comparison harness: option lists, run summaries computed by hand, the
// contact estimates, and the restitution sweep held against the closed form
// and against an independent high-accuracy integration of the same 1-D drop.

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cli/options.h"
#include "cli/runner.h"
#include "contactlaws/contactlaws.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

using cli::ParseLawList;
using cli::ParseRestitutionList;

// The message of the Error fn throws, or "" when it throws none.
template <typename Fn>
std::string ErrorOf(Fn fn) {
  try {
    fn();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(OptionsTest, RestitutionRangeGivesTheDecimalValues) {
  const std::vector<double> values = ParseRestitutionList("--restitution", "0.1:1.0:0.1");
  // rounded to 12 decimals: 0.1 + 2 * 0.1 is 0.30000000000000004 unrounded
  EXPECT_EQ(values, (std::vector<double>{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0}));
  EXPECT_EQ(ParseRestitutionList("--restitution", "0.05:1:0.05").size(), 20u);
  EXPECT_EQ(ParseRestitutionList("--restitution", "0.5:0.5:0.1"), std::vector<double>{0.5});
  EXPECT_EQ(ParseRestitutionList("--restitution", "0:1:0.3"),
            (std::vector<double>{0.0, 0.3, 0.6, 0.9}));
  EXPECT_EQ(ParseRestitutionList("--restitution", "0.9,0.6,0.3"),
            (std::vector<double>{0.9, 0.6, 0.3}));
  EXPECT_EQ(ParseRestitutionList("--restitution", "1"), std::vector<double>{1.0});
}

TEST(OptionsTest, BadRestitutionListsAreRefusedByName) {
  const struct {
    const char* text;
    const char* message;
  } cases[] = {
      {"1:0:0.1", "--restitution=1:0:0.1 must have start <= stop (start:stop:step)"},
      {"0:1:0", "--restitution=0:1:0 must have a step > 0 (start:stop:step)"},
      {"0:1:-0.1", "--restitution=0:1:-0.1 must have a step > 0 (start:stop:step)"},
      {"0:1", "--restitution=0:1 must be E1,E2,... or start:stop:step"},
      {"0.5,abc", "--restitution=0.5,abc has 'abc', which is not a finite number"},
      {"0.5,", "--restitution=0.5, has '', which is not a finite number"},
      {"nan", "--restitution=nan has 'nan', which is not a finite number"},
      {"0.5,1.5", "--restitution=0.5,1.5 has 1.5, outside [0, 1]"},
      {"0.5:1.5:0.5", "--restitution=0.5:1.5:0.5 has 1.5, outside [0, 1]"},
      {"0.5,0.5", "--restitution=0.5,0.5 has 0.5 twice"},
      {"0:1:1e-9", "--restitution=0:1:1e-9 expands to more than 100000 values"},
  };
  for (const auto& c : cases) {
    EXPECT_EQ(ErrorOf([&] { ParseRestitutionList("--restitution", c.text); }), c.message);
  }
}

TEST(OptionsTest, LawLists) {
  EXPECT_EQ(ParseLawList("--laws", "all"),
            std::vector<LawKind>(std::begin(kAllLaws), std::end(kAllLaws)));
  EXPECT_EQ(ParseLawList("--laws", "flores,hertz"),
            (std::vector<LawKind>{LawKind::kFlores, LawKind::kHertz}));
  EXPECT_EQ(ErrorOf([] { ParseLawList("--laws", "flores,hooke"); }),
            "--laws=flores,hooke has 'hooke', which is not a law (all, hertz, kelvin-voigt, "
            "hunt-crossley, lankarani-nikravesh, flores)");
  EXPECT_EQ(ErrorOf([] { ParseLawList("--laws", "flores,flores"); }),
            "--laws=flores,flores names flores twice");
}

// An episode of pair p from t0 to t1 (open when t1 < 0).
Impact Episode(int pair, double t0, double t1, double depth = 1e-3, double force = 1e3) {
  Impact i;
  i.tag = 0;
  i.pair = pair;
  i.time_contact = t0;
  i.impact_velocity = 2.0;
  i.open = t1 < 0;
  if (!i.open) {
    i.time_separation = t1;
    i.separation_velocity = 1.5;
  }
  i.max_depth = depth;
  i.max_force = force;
  return i;
}

TEST(SummaryTest, ImpactsAndTimeToRestByHand) {
  // three bounces of 0.10, 0.15 and 0.05 s, then a contact from 0.8 s on
  const std::vector<Impact> impacts = {Episode(0, 0.1, 0.2, 2e-3, 5e3),
                                       Episode(0, 0.5, 0.65, 3e-3, 4e3),
                                       Episode(0, 0.7, 0.75), Episode(0, 0.8, -1)};
  const RunSummary s = Summarize(impacts, 2.0);
  EXPECT_EQ(s.impacts, 4);
  EXPECT_EQ(s.restitution_post, 0.75);  // 1.5 / 2.0, the first episode's
  EXPECT_EQ(s.impact_velocity, 2.0);
  EXPECT_NEAR(*s.contact_duration, 0.1, 1e-15);
  EXPECT_EQ(s.max_depth, 3e-3);
  EXPECT_EQ(s.max_force, 5e3);
  EXPECT_EQ(s.time_to_rest, 0.8);

  // the last contact has lasted 0.1 s at 0.9 s: not longer than the 0.15 s
  // bounce before it, so it may be one more bounce
  EXPECT_FALSE(Summarize(impacts, 0.9).time_to_rest);
  EXPECT_EQ(Summarize(impacts, 0.96).time_to_rest, 0.8);  // 0.16 s > 0.15 s

  // the run ends in flight: not at rest
  EXPECT_FALSE(Summarize({Episode(0, 0.1, 0.2), Episode(0, 0.5, 0.6)}, 2.0).time_to_rest);
  // a first episode still open: no post-restitution, no duration; resting from t = 0
  const RunSummary resting = Summarize({Episode(0, 0.0, -1)}, 1.0);
  EXPECT_FALSE(resting.restitution_post);
  EXPECT_FALSE(resting.contact_duration);
  EXPECT_EQ(resting.time_to_rest, 0.0);
  // no contact at all
  const RunSummary none = Summarize({}, 1.0);
  EXPECT_EQ(none.impacts, 0);
  EXPECT_FALSE(none.time_to_rest);
  EXPECT_FALSE(none.impact_velocity);
}

TEST(SummaryTest, EveryPairMustRestAndTheLatestDecides) {
  std::vector<Impact> impacts = {Episode(0, 0.1, 0.2), Episode(1, 0.15, 0.25),
                                 Episode(0, 0.4, -1), Episode(1, 0.6, -1)};
  EXPECT_EQ(Summarize(impacts, 2.0).time_to_rest, 0.6);
  impacts.push_back(Episode(2, 0.5, 0.55));  // a third pair that touched and left
  EXPECT_FALSE(Summarize(impacts, 2.0).time_to_rest);
}

class EstimateTest : public testing::MujocoTest {};

TEST_F(EstimateTest, HertzContactDurationMatchesTheSimulatedContact) {
  // t_c = 2.9432 d_max / v for n = 3/2 (B(2/5, 1/2) / (5/2) = 1.4716).
  EXPECT_NEAR(HertzContactDuration(1.0, 1.5, 1.0, 1.0) / HertzMaxDepth(1.0, 1.5, 1.0, 1.0),
              2.9432, 1e-4);
  // Against the simulated Hertz drop (gravity off): the simulated duration is
  // extrapolated to d = 0 at both ends, O(h^2 / tau^2) ~ 1e-4 at h = 1e-5;
  // the integrator's energy error adds ~1e-4.
  constexpr double kDurationTolerance = 1e-3;  // relative
  for (double v : {0.5, 4.2}) {
    Simulation& sim = MakeSimulation(testing::DropXml(
        "law=hertz stiffness=1.4e8 exponent=1.5", v, "RK4"));
    const Impact impact = testing::FirstImpact(sim);
    const double simulated = impact.time_separation - impact.time_contact;
    EXPECT_NEAR(simulated / HertzContactDuration(1.4e8, 1.5, 1.0, v), 1.0, kDurationTolerance)
        << "v = " << v;
  }
}

TEST_F(EstimateTest, ThePaperBallFallsFromItsGap) {
  Simulation& sim = MakeSceneSimulation("bouncing_ball.xml");
  mj_forward(sim.model(), sim.data());
  const ContactEstimate e = EstimateContact(sim.contacts(), 0);
  EXPECT_EQ(e.effective_mass, 1.0);
  ASSERT_TRUE(e.gap);
  EXPECT_NEAR(*e.gap, 0.9, 1e-12);
  EXPECT_NEAR(e.impact_velocity, std::sqrt(2 * 9.81 * 0.9), 1e-12);
  EXPECT_EQ(e.contact_duration, HertzContactDuration(1.4e8, 1.5, 1.0, e.impact_velocity));
  EXPECT_EQ(e.timestep(), e.contact_duration / kStepsPerContact);
  // a stated impact velocity replaces the estimate
  EXPECT_EQ(EstimateContact(sim.contacts(), 0, 1.0).impact_velocity, 1.0);
}

TEST_F(EstimateTest, DrivenTableAddsItsTopSpeed) {
  Simulation& sim = MakeSceneSimulation("ball_table.xml");
  mj_forward(sim.model(), sim.data());
  const ContactEstimate e = EstimateContact(sim.contacts(), 0);
  EXPECT_EQ(e.effective_mass, 1.0);  // the table is driven: infinitely heavy
  ASSERT_TRUE(e.gap);
  EXPECT_NEAR(*e.gap, 0.4, 1e-12);
  EXPECT_NEAR(e.impact_velocity, std::sqrt(2 * 9.81 * 0.4) + 0.1 * 7.5, 1e-12);
}

// The sweep as `contactlaws restitution` runs it: a scene, each (law, e) to
// the end of its first contact episode.
Impact SweepFirstImpact(const cli::Scene& scene, LawKind law, double e,
                        std::optional<double> timestep = std::nullopt,
                        std::optional<AutoTimestepOptions> auto_timestep = std::nullopt,
                        long* steps = nullptr) {
  SimulationOptions options;
  options.overrides.law = law;
  options.overrides.restitution = e;
  options.timestep = timestep;
  std::unique_ptr<Simulation> sim = scene.Make(options);
  const cli::AdvanceResult result =
      cli::Advance(sim.get(), {2.0, 0.0, true, auto_timestep}, nullptr);
  if (steps) *steps = auto_timestep ? result.steps : std::lround(sim->time() / *timestep);
  const std::vector<Impact>& impacts = sim->contacts().impacts();
  if (impacts.empty() || impacts.front().open) {
    ADD_FAILURE() << LawName(law) << " e = " << e << ": no closed first episode";
    return Impact{};
  }
  return impacts.front();
}

TEST(SweepTest, HertzFamilyMatchesTheClosedForm) {
  // Gravity off, 4.2 m/s, h = 1e-5, Euler: measured errors up to 5.7e-5 (the
  // semi-implicit step's O(h / tau) energy error over a ~1.5 ms contact);
  // 2e-4 leaves room for a platform's rounding without hiding an O(h) bug
  // (doubling h doubles the error).
  constexpr double kReboundTolerance = 2e-4;
  const std::string xml = testing::DropXml("law=flores restitution=0.5 stiffness=1.4e8", 4.2);
  const cli::Scene scene("drop.xml", LoadModelString(xml, "drop.xml"));
  for (LawKind law : {LawKind::kHuntCrossley, LawKind::kLankaraniNikravesh, LawKind::kFlores}) {
    for (double e : ParseRestitutionList("--restitution", "0.1:1.0:0.1")) {
      const Impact impact = SweepFirstImpact(scene, law, e);
      EXPECT_NEAR(impact.restitution_post(), ExactRebound(HysteresisCoefficient(law, e)),
                  kReboundTolerance)
          << LawName(law) << " e = " << e;
    }
  }
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

double ReferenceForce(const Drop& drop, LawKind law, double e, double v0, double d,
                      double rate) {
  if (d <= 0) return 0;
  double f = 0;
  if (law == LawKind::kKelvinVoigt) {
    // c = 2 zeta sqrt(k m), zeta from e for a linear oscillator
    const double zeta = -std::log(e) / std::sqrt(M_PI * M_PI + std::log(e) * std::log(e));
    f = drop.linear_stiffness * d + 2 * zeta * std::sqrt(drop.linear_stiffness * drop.mass) * rate;
  } else {
    double a = 0;  // paper eqs. 44 (flores), Hunt-Crossley, Lankarani-Nikravesh
    if (law == LawKind::kHuntCrossley) a = 1.5 * (1 - e);
    if (law == LawKind::kLankaraniNikravesh) a = 0.75 * (1 - e * e);
    if (law == LawKind::kFlores) a = 8 * (1 - e) / (5 * e);
    f = drop.stiffness * std::pow(d, drop.exponent) * (1 + a * rate / v0);
  }
  return std::max(f, 0.0);
}

Reference IntegrateDrop(const Drop& drop, LawKind law, double e, int steps = 20000) {
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

TEST(ReferenceTest, IndependentIntegrationConvergesAndMatchesTheClosedForm) {
  // the reference is itself checked: halving its step changes nothing that
  // matters (1e-5 relative: Kelvin-Voigt's clamp at F = 0 is a kink RK4
  // integrates to first order, measured 3.5e-6 in e_post; the others 1e-10),
  // and with gravity off it gives the closed-form rebound
  Drop drop;
  for (LawKind law : kAllLaws) {
    const Reference a = IntegrateDrop(drop, law, 0.3);
    const Reference fine = IntegrateDrop(drop, law, 0.3, 40000);
    constexpr double kConverged = 1e-5;
    EXPECT_NEAR(a.restitution_post, fine.restitution_post, kConverged) << LawName(law);
    EXPECT_NEAR(a.max_depth / fine.max_depth, 1.0, kConverged) << LawName(law);
    EXPECT_NEAR(a.max_force / fine.max_force, 1.0, kConverged) << LawName(law);
    EXPECT_NEAR(a.contact_duration / fine.contact_duration, 1.0, kConverged) << LawName(law);
  }
  const Reference a = IntegrateDrop(drop, LawKind::kFlores, 0.3);
  drop.gravity = 1e-9;  // effectively off; v0 comes from a fall at g
  drop.fall = 0.9 * 9.81 / drop.gravity;
  const Reference b = IntegrateDrop(drop, LawKind::kFlores, 0.3);
  EXPECT_NEAR(b.restitution_post, ExactRebound(HysteresisCoefficient(LawKind::kFlores, 0.3)),
              1e-7);
  EXPECT_GT(std::abs(a.restitution_post - b.restitution_post), 1e-4)
      << "gravity must matter at the measured size";
}

TEST(ReferenceTest, SweepAgreesWithTheIndependentIntegration) {
  // The paper's drop (mjcf/bouncing_ball.xml: 1 kg, K = 1.4e8, 0.9 m fall,
  // gravity on, RK4) at h = 1e-5, against IntegrateDrop. Tolerances (the
  // issue's): 2e-3 in e_post, 1% in max depth, max force and contact duration.
  // Measured: Hertz family e_post within 2.1e-5, depth, force and duration
  // within 3e-4.
  // Kelvin-Voigt's force jumps from 0 to c v0 at first touch. A fixed step
  // first sees the contact a fraction f of a step after it began, and RK4's
  // stages apply the jump over quantized parts (0, 1/6, 5/6, 1) of the step,
  // not over f: the impulse is off by up to c v0 h, e_post by up to about
  // zeta omega h (zeta = 0.59, omega = 2236/s at e = 0.1: 1.3e-2), with a sign
  // and size set by f. At this drop and h = 1e-5, f gives 8.7e-4 (at 2e-5 it
  // gives 2.5e-3); it shrinks with h, first order, like the bound. The 1%
  // bounds hold for it with room (depth -3.4e-3, force -8.7e-3 at e = 0.1).
  constexpr double kRebound = 2e-3;
  constexpr double kRelative = 1e-2;
  const std::string path = std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf/bouncing_ball.xml";
  const cli::Scene scene(path);
  const Drop drop;
  std::map<LawKind, double> worst;  // largest e_post error per law, printed
  for (LawKind law : kAllLaws) {
    for (double e : ParseRestitutionList("--restitution", "0.1:1.0:0.1")) {
      const Impact sim = SweepFirstImpact(scene, law, e, 1e-5);
      const Reference ref = IntegrateDrop(drop, law, e);
      const std::string what = fmt::format("{} e = {}", LawName(law), e);
      const double error = std::abs(sim.restitution_post() - ref.restitution_post);
      worst[law] = std::max(worst[law], error);
      EXPECT_LT(error, kRebound) << what;
      EXPECT_NEAR(sim.max_depth / ref.max_depth, 1.0, kRelative) << what;
      EXPECT_NEAR(sim.max_force / ref.max_force, 1.0, kRelative) << what;
      EXPECT_NEAR((sim.time_separation - sim.time_contact) / ref.contact_duration, 1.0,
                  kRelative)
          << what;
      std::printf("%-20s e=%.1f  e_post sim %.6f ref %.6f  depth %+.2e  force %+.2e  "
                  "duration %+.2e\n",
                  std::string(LawName(law)).c_str(), e, sim.restitution_post(),
                  ref.restitution_post, sim.max_depth / ref.max_depth - 1,
                  sim.max_force / ref.max_force - 1,
                  (sim.time_separation - sim.time_contact) / ref.contact_duration - 1);
    }
  }
  for (const auto& [law, error] : worst) {
    std::printf("largest |e_post - reference|, %s: %.2e\n", std::string(LawName(law)).c_str(),
                error);
  }
}

TEST(AutoTimestepTest, SweepAgreesWithTheReferenceAndTheFixedStepInATenthOfTheSteps) {
  // The issue's goal: with auto, every e_post within 2e-3 of the fixed 1e-5 s
  // answer (Kelvin-Voigt 5e-3), in <= 0.10 of the work. Work is counted in
  // steps here (the wall-time ratio is scripts/bench.sh's); both runs are
  // also held to the independent reference with the fixed step's tolerance.
  // Measured: e_post within 1.6e-4 of the fixed step (Hertz family) and
  // 4.7e-4 (Kelvin-Voigt); steps 0.7% of the fixed step's.
  constexpr double kRebound = 2e-3;
  constexpr double kKelvinVoigtRebound = 5e-3;
  constexpr double kStepRatio = 0.10;
  const cli::Scene scene(std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf/bouncing_ball.xml");
  const Drop drop;
  long fixed_steps = 0;
  long auto_steps = 0;
  std::map<LawKind, double> worst;
  for (LawKind law : kAllLaws) {
    for (double e : {0.1, 0.5, 0.9}) {
      const std::string what = fmt::format("{} e = {}", LawName(law), e);
      long steps = 0;
      const Impact fixed = SweepFirstImpact(scene, law, e, 1e-5, std::nullopt, &steps);
      fixed_steps += steps;
      const Impact automatic =
          SweepFirstImpact(scene, law, e, std::nullopt, AutoTimestepOptions{}, &steps);
      auto_steps += steps;
      const double tolerance = law == LawKind::kKelvinVoigt ? kKelvinVoigtRebound : kRebound;
      const double error = std::abs(automatic.restitution_post() - fixed.restitution_post());
      worst[law] = std::max(worst[law], error);
      EXPECT_LT(error, tolerance) << what;
      EXPECT_LT(std::abs(automatic.restitution_post() -
                         IntegrateDrop(drop, law, e).restitution_post),
                kRebound)
          << what;
      // the reference test's 1% on the peak force
      EXPECT_NEAR(automatic.max_force / fixed.max_force, 1.0, 1e-2) << what;
    }
  }
  for (const auto& [law, error] : worst) {
    std::printf("largest |e_post(auto) - e_post(1e-5 s)|, %s: %.2e\n",
                std::string(LawName(law)).c_str(), error);
  }
  std::printf("steps: auto %ld, fixed 1e-5 s %ld, ratio %.4f\n", auto_steps, fixed_steps,
              static_cast<double>(auto_steps) / fixed_steps);
  EXPECT_LT(auto_steps, kStepRatio * fixed_steps);
}

TEST(AutoTimestepTest, TheStepShrinksOnApproachAndIsFineInContact) {
  // the paper's ball from 1 m: long steps in flight, the fine step
  // (t_c / 20) from just before the touch to the separation
  const cli::Scene scene(std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf/bouncing_ball.xml");
  std::unique_ptr<Simulation> sim = scene.Make({});
  mjData* d = sim->data();
  AutoTimestep stepper(sim->contacts());
  const double fine = HertzContactDuration(1.4e8, 1.5, 1.0, std::sqrt(2 * 9.81 * 0.9)) / 20;
  double largest = 0;
  double in_contact = 0;  // largest step taken while in contact
  double before_touch = 0;
  while (sim->contacts().impacts().empty() || sim->contacts().impacts()[0].open) {
    const double h = stepper.Next(1.0);
    largest = std::max(largest, h);
    const bool touching = !sim->contacts().latest().empty();
    if (touching) in_contact = std::max(in_contact, h);
    sim->Step(h);
    if (!touching && !sim->contacts().latest().empty()) before_touch = h;
    ASSERT_LT(d->time, 1.0);
  }
  EXPECT_EQ(largest, AutoTimestepOptions{}.max_step);
  // the fine step is t_c at the impact speed it measured (just before the
  // touch, not the exact free fall): 5% covers the difference, t_c ~ v^-1/5
  EXPECT_NEAR(in_contact, fine, 0.05 * fine);
  EXPECT_LE(before_touch, 1.0001 * fine);
  // 0.43 s of flight at the 1e-3 s max step, about 20 steps of contact and a
  // few on the approach; a fixed 1e-5 s step takes 43000
  EXPECT_LT(stepper.steps(), 430 + 60);
}

TEST(AutoTimestepTest, APairInContactWithManyPointsDoesNotHideAnApproachingPair) {
  // a box resting on the floor under a soft Kelvin-Voigt tag (4 contact
  // points, a long contact: fine step ~5e-4 s) and a ball falling at 5 m/s
  // under a stiff Hertz tag (fine step ~6e-5 s): the ball's approach must
  // still end on its touch, not a soft fine step (2.5 mm) into the floor
  const std::string xml = R"(<mujoco>
  <option integrator="RK4"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <body pos="0 0 0.0902"><freejoint/><geom name="box" type="box" size="0.1 0.1 0.1" mass="1"/></body>
    <body pos="2 0 0.2"><freejoint/><geom name="ball" type="sphere" size="0.1" mass="1"/></body>
  </worldbody>
  <keyframe><key qvel="0 0 0 0 0 0 0 0 -5 0 0 0"/></keyframe>
  <custom>
    <text name="contactlaw:box" data="geom1=box geom2=floor law=kelvin-voigt restitution=0.5
      linear_stiffness=1e3"/>
    <text name="contactlaw:ball" data="geom1=ball geom2=floor law=hertz stiffness=1.4e8"/>
  </custom>
</mujoco>)";
  Simulation sim(LoadModelString(xml, "box_ball.xml"), "box_ball.xml");
  AutoTimestep stepper(sim.contacts());
  double first_ball_depth = 0;
  while (sim.time() < 0.1 && first_ball_depth == 0) {
    sim.Step(stepper.Next(1.0));
    first_ball_depth = sim.contacts().Reading(1).depth;
  }
  ASSERT_GT(sim.contacts().Reading(0).depth, 0) << "the box rests in contact";
  ASSERT_GT(first_ball_depth, 0) << "the ball reached the floor";
  // the first state in contact is at most one Hertz fine step past the touch
  const double fine = HertzContactDuration(1.4e8, 1.5, 1.0, 5.0) / 20;
  EXPECT_LT(first_ball_depth, 5.0 * fine);
}

}  // namespace
}  // namespace contactlaws
