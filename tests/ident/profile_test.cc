// Copyright contactlaws authors.

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "contactlaws/fit.h"
#include "ident_scenes.h"

namespace contactlaws {
namespace {

using testing::Simulated;

// A rubber-like ball of 40 mm, 50 g, bouncing on a floor.
Scene BallScene(const std::string& tag) {
  const std::string xml = fmt::format(R"(
<mujoco model="ball">
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body name="ball" pos="0 0 0.2">
      <freejoint/>
      <inertial pos="0 0 0" mass="0.05" diaginertia="8e-6 8e-6 8e-6"/>
      <geom name="ball" type="sphere" size="0.02"/>
    </body>
  </worldbody>
  <custom>
    <text name="contactlaw:ball-floor" data="geom1=ball geom2=floor {}"/>
  </custom>
</mujoco>)",
                                      tag);
  return Scene("ball.xml", LoadModelString(xml, "ball.xml"));
}

// The drops' truth. The floor is frictionless: a drop's spin plays no part.
constexpr double kRestitution = 0.6;
constexpr double kStiffness = 1e6;  // N/m^1.5
constexpr char kTruth[] = "law=flores restitution=0.6 stiffness=1e6 friction=none";

// Its rollouts: 0.1 ms steps, a tenth of the stiffest contact's ~0.5 ms.
ReplayOptions DropOptions() {
  ReplayOptions options;
  options.simulation.timestep = 1e-4;
  return options;
}

// count drops from 0.1-0.25 m, falling at 0-1 m/s, sideways at up to
// 0.5 m/s, spinning; sampled at 148 Hz over 0.7 s (two to four bounces),
// simulated with the truth. Measured as a camera tracker would: each
// position blurred by 1 mm, each orientation by ~0.01 rad, and each drop's
// positions shifted by its own offset of ~3 mm per axis (the calibration,
// the marker's place on the ball), an error of either sign from drop to
// drop that no parameter fits, as a real contact's differences from the
// law are. Only the velocities of the first sample are given, as
// TossStarts does.
MeasuredData NoisyDrops(int count) {
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  MeasuredData starts;
  starts.source = "drops";
  for (const char* q : kBodyQuantities) starts.columns.push_back(fmt::format("ball.{}", q));
  for (int i = 0; i < count; ++i) {
    MeasuredTrajectory t;
    t.name = fmt::format("{}", i);
    const double heading = 2 * M_PI * u(random);
    const double side = 0.5 * u(random);
    const std::vector<double> first = {0, 0, 0.1 + 0.15 * u(random), 1, 0, 0, 0,
                                       side * std::cos(heading), side * std::sin(heading),
                                       -u(random), 20 * (u(random) - 0.5), 20 * (u(random) - 0.5),
                                       20 * (u(random) - 0.5)};
    for (int k = 0; k < 104; ++k) {
      t.time.push_back(k / 148.0);
      t.values.insert(t.values.end(), first.begin(), first.end());
    }
    starts.trajectories.push_back(std::move(t));
  }
  MeasuredData noisy = Simulated(BallScene(kTruth), starts, DropOptions());
  noisy.source = "noisy drops";
  std::normal_distribution<double> noise(0.0, 1.0);
  for (MeasuredTrajectory& t : noisy.trajectories) {
    double offset[3];
    for (double& o : offset) o = 3e-3 * noise(random);
    for (int k = 0; k < t.samples(); ++k) {
      double* x = t.values.data() + k * noisy.columns.size();
      for (int c = 0; c < 3; ++c) x[c] += offset[c] + 1e-3 * noise(random);
      for (int c = 3; c < 7; ++c) x[c] += 0.005 * noise(random);  // ~0.01 rad of turn
      mju_normalize4(x + 3);
    }
  }
  return noisy;
}

// The grid: ends at the bounds exactly, log-spaced on a log parameter, the
// fitted value inserted where it falls.
TEST(ProfileTest, PointsSpanTheRangeAndHoldTheFittedValue) {
  const Scene scene = BallScene(kTruth);
  const std::vector<FitParameter> p =
      ParseFitParameters("restitution=0.2:1,stiffness=1e4:1e8:log", scene.model());
  EXPECT_EQ(ProfileValues(p[0], 0.6, 5), (std::vector<double>{0.2, 0.4, 0.6, 0.8, 1}));
  const std::vector<double> k = ProfileValues(p[1], 3e5, 5);
  ASSERT_EQ(k.size(), 6u);
  EXPECT_EQ(k.front(), 1e4);
  EXPECT_EQ(k.back(), 1e8);
  EXPECT_EQ(k[2], 3e5);
  for (int i : {1, 3, 4}) {
    EXPECT_NEAR(std::log10(k[i]), i < 2 ? 4 + i : 3 + i, 1e-12);  // exp(log) rounds
  }
  EXPECT_THROW(ProfileValues(p[0], 0.6, 2), Error);
  // a decade on a log scale, half the range on either
  EXPECT_FALSE(SpanUndetermined(p[1], 1e5, 9e5));
  EXPECT_TRUE(SpanUndetermined(p[1], 1e5, 1e6));
  EXPECT_FALSE(SpanUndetermined(p[0], 0.3, 0.69));
  EXPECT_TRUE(SpanUndetermined(p[0], 0.3, 0.7));
  const std::vector<FitParameter> narrow =
      ParseFitParameters("stiffness=1e6:4e6:log", scene.model());
  EXPECT_TRUE(SpanUndetermined(narrow[0], 1e6, 2e6));  // half the range, not a decade
}

// The must-hold: on drops simulated with a known stiffness, that stiffness
// and one a decade above score the same (paired); profiled through the
// truth (what the data say about it; the fit's recovery is fit_test's),
// stiffness is reported not determined over at least that decade, and
// restitution determined with the truth in its span.
TEST(ProfileTest, ReportsWhatTheDataDetermineAndWhatNot) {
  const MeasuredData noisy = NoisyDrops(12);
  const Scene scene = BallScene("law=flores restitution=0.3 stiffness=1e7 friction=none");
  const Replay replay(scene, noisy);
  FitOptions fit;
  fit.replay = DropOptions();
  fit.replay.jobs = 2;
  fit.parameters =
      ParseFitParameters("restitution=0.2:0.95,stiffness=1e4:1e8:log", scene.model());
  CheckFit(scene, fit.replay, fit.parameters);
  auto scores = [&](double stiffness) {
    std::vector<double> s;
    for (const ReplayedTrajectory& r :
         replay.Run(WithParameters(fit.replay, fit.parameters, {kRestitution, stiffness}))) {
      s.push_back(r.score.e_q);
    }
    return s;
  };
  // the premise: a decade stiffer scores the same, drop by drop; a hundred
  // times softer does not (the profile can tell values apart)
  const std::vector<double> at_truth = scores(kStiffness);
  EXPECT_FALSE(ComparePaired(scores(10 * kStiffness), at_truth, 5).Distinguishable());
  EXPECT_TRUE(ComparePaired(scores(kStiffness / 100), at_truth, 5).Distinguishable());

  const std::vector<double> truth = {kRestitution, kStiffness};
  ProfileOptions options;
  options.points = 9;  // stiffness: every half decade
  options.seed = 5;
  const std::vector<ParameterProfile> profiles = Profile(replay, fit, truth, {0, 1}, options);
  ASSERT_EQ(profiles.size(), 2u);
  const ParameterProfile& e = profiles[0];
  const ParameterProfile& k = profiles[1];
  EXPECT_EQ(e.parameter, 0u);
  EXPECT_EQ(k.parameter, 1u);
  EXPECT_FALSE(e.interrupted);
  EXPECT_FALSE(k.interrupted);
  EXPECT_EQ(e.points.size(), 10u);  // 9 and the truth beside them
  EXPECT_EQ(k.points.size(), 9u);   // the truth on the grid (to rounding): the grid's point
  for (const ParameterProfile* pr : {&e, &k}) {
    // the best's interval against itself is [0, 0]
    EXPECT_EQ(pr->points[pr->best].versus_best.interval.lo, 0);
    EXPECT_EQ(pr->points[pr->best].versus_best.interval.hi, 0);
    int fitted = 0;
    for (size_t i = 0; i < pr->points.size(); ++i) {
      const ProfilePoint& point = pr->points[i];
      if (i > 0) {
        EXPECT_LT(pr->points[i - 1].value, point.value);
      }
      fitted += point.fitted;
      EXPECT_EQ(point.fitted, point.value == truth[pr->parameter]);
      EXPECT_LE(point.score.mean.lo, point.score.value.mean);
      EXPECT_GE(point.score.mean.hi, point.score.value.mean);
    }
    EXPECT_EQ(fitted, 1);
  }
  // stiffness: flat over the truth's decade above it at least
  EXPECT_FALSE(k.determined);
  EXPECT_LE(k.span_lo(), kStiffness);
  EXPECT_GE(k.span_hi(), 10 * kStiffness * (1 - 1e-12));  // the grid's exp(log) rounds
  // and not over all of the range: the soft end scores worse
  EXPECT_FALSE(k.points.front().Indistinguishable());
  // restitution: narrow, about the truth (each bounce is e times the last's speed)
  EXPECT_TRUE(e.determined);
  EXPECT_LE(e.span_lo(), kRestitution);
  EXPECT_GE(e.span_hi(), kRestitution);
  EXPECT_FALSE(e.points.front().Indistinguishable());
  EXPECT_FALSE(e.points.back().Indistinguishable());

  // the same seed, the same numbers, whatever the threads
  fit.replay.jobs = 1;
  const std::vector<ParameterProfile> again = Profile(replay, fit, truth, {1}, options);
  ASSERT_EQ(again.size(), 1u);
  ASSERT_EQ(again[0].points.size(), k.points.size());
  for (size_t i = 0; i < k.points.size(); ++i) {
    EXPECT_EQ(again[0].points[i].score.value.mean, k.points[i].score.value.mean);
    EXPECT_EQ(again[0].points[i].versus_best.interval.lo, k.points[i].versus_best.interval.lo);
    EXPECT_EQ(again[0].points[i].versus_best.interval.hi, k.points[i].versus_best.interval.hi);
  }
  EXPECT_EQ(again[0].span_first, k.span_first);
  EXPECT_EQ(again[0].span_last, k.span_last);
}

// With a budget, the other parameters are re-fitted at each point from
// their fitted values: the re-fit's first evaluation is the held point, so
// every point scores no worse than held, and the profiled value stays put.
TEST(ProfileTest, ABudgetRefitsTheOthersFromTheFittedValues) {
  const MeasuredData noisy = NoisyDrops(3);
  const Scene scene = BallScene(kTruth);
  const Replay replay(scene, noisy);
  FitOptions fit;
  fit.replay = DropOptions();
  fit.replay.jobs = 2;
  fit.parameters =
      ParseFitParameters("restitution=0.2:0.95,stiffness=1e4:1e8:log", scene.model());
  // off the truth: a re-fit has somewhere to go
  const std::vector<double> through = {0.5, 1e5};
  ProfileOptions options;
  options.points = 3;
  options.seed = 5;
  const ParameterProfile held = Profile(replay, fit, through, {0}, options).at(0);
  options.budget = 4;
  const ParameterProfile refitted = Profile(replay, fit, through, {0}, options).at(0);
  ASSERT_EQ(held.points.size(), refitted.points.size());
  bool moved = false;
  for (size_t i = 0; i < held.points.size(); ++i) {
    const ProfilePoint& h = held.points[i];
    const ProfilePoint& r = refitted.points[i];
    EXPECT_EQ(r.value, h.value);
    EXPECT_EQ(r.values[0], h.value);
    EXPECT_EQ(h.values[1], 1e5);
    EXPECT_LE(r.score.value.mean, h.score.value.mean);
    moved = moved || r.values[1] != 1e5;
  }
  EXPECT_TRUE(moved);  // the re-fit did move stiffness somewhere
}

// Bad calls refused naming what is wrong.
TEST(ProfileTest, RefusesBadCalls) {
  const Scene scene = BallScene(kTruth);
  const MeasuredData drop = NoisyDrops(1);  // the replay reads it
  const Replay replay(scene, drop);
  FitOptions fit;
  fit.replay = DropOptions();
  fit.parameters = ParseFitParameters("restitution=0.2:0.95", scene.model());
  ProfileOptions options;
  auto refusal = [&](const std::vector<double>& fitted, const std::vector<size_t>& which) {
    try {
      Profile(replay, fit, fitted, which, options);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal({0.6, 1}, {0}), "a profile through 2 values of 1 parameters");
  EXPECT_EQ(refusal({0.1}, {0}), "restitution=0.1: outside its bounds [0.2, 0.95]");
  EXPECT_EQ(refusal({0.6}, {1}), "a profile of parameter 1: there are 1");
  // a rounding outside a bound is the bound (a fit's At(1) may land there)
  EXPECT_EQ(refusal({0.95 * (1 + 1e-15)}, {0}), "accepted");
  EXPECT_EQ(refusal({0.96}, {0}),
            "restitution=0.96: outside its bounds [0.2, 0.95]");
  options.points = 2;
  EXPECT_EQ(refusal({0.6}, {0}), "a profile of 2 points: needs 3 at least");
}

}  // namespace
}  // namespace contactlaws
