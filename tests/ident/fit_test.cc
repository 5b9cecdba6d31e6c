// Copyright contactlaws authors.

#include "contactlaws/fit.h"

#include <cmath>
#include <functional>
#include <optional>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "ident_scenes.h"

namespace contactlaws {
namespace {

using testing::CubeScene;
using testing::Simulated;
using testing::TossStarts;

// The message of the Error that check throws, or "accepted".
std::string Refused(const std::function<void()>& check) {
  try {
    check();
  } catch (const Error& e) {
    return e.what();
  }
  return "accepted";
}

std::string Refusal(const std::string& params) {
  const Scene scene = CubeScene("law=flores restitution=0.3 stiffness=3e5 friction=coulomb mu=0.3");
  return Refused(
      [&] { CheckFit(scene, ReplayOptions(), ParseFitParameters(params, scene.model())); });
}

TEST(FitTest, RefusesParametersNamingTheKey) {
  EXPECT_EQ(Refusal("restitution=0.1:0.9,stiffness=1e4:1e7:log,cube.mass_scale=0.9:1.1,"
                    "board.offset=-0.004:0.001"),
            "accepted");
  EXPECT_EQ(Refusal("restitutoin=0.1:0.9"),
            "restitutoin=0.1:0.9: 'restitutoin' is not a contactlaw tag key (did you "
            "mean 'restitution'?), nor OBJECT.KEY (mass_scale, inertia_scale, offset, mujoco.*)");
  EXPECT_EQ(Refusal("law=0:1"),
            "law=0:1: 'law' is not a numeric key (laws and friction models are "
            "compared, not fitted)");
  EXPECT_EQ(Refusal("restitution=0.9:0.1"),
            "restitution=0.9:0.1: the bounds are empty (0.9 >= 0.1)");
  EXPECT_EQ(Refusal("restitution=0.1"),
            "restitution=0.1: bounds must be LO:HI or LO:HI:log");
  EXPECT_EQ(Refusal("stiffness=0:1e6:log"),
            "stiffness=0:1e6:log: a log scale needs LO > 0, not 0");
  EXPECT_EQ(Refusal("mu=0.1:x"), "mu=0.1:x: 'x' is not a finite number");
  EXPECT_EQ(Refusal("mu=0.1:0.2,mu=0.2:0.3"), "mu=0.2:0.3: key 'mu' is given twice");
  EXPECT_EQ(Refusal("ball.mass_scale=0.5:2"),
            "ball.mass_scale=0.5:2: the scene has no moving body 'ball'");
  EXPECT_EQ(Refusal("cube.mass_scale=0:2"),
            "cube.mass_scale=0:2: mass_scale must be > 0");
  EXPECT_EQ(Refusal("mujoco.dmin=0.5:1.5"), "mujoco.dmin=0.5:1.5: dmin must be in (0, 1)");
  EXPECT_EQ(Refusal("cube.speed=0:1"),
            "cube.speed=0:1: 'cube.speed' is not a model parameter: BODY.mass_scale, "
            "BODY.inertia_scale, GEOM.offset, mujoco.timeconst|dampratio|dmin|dmax|width|friction");
  // the tag's own checks, at the bounds
  EXPECT_EQ(Refusal("restitution=0.5:1.5"),
            "restitution=0.5:1.5: the bound 1.5 is refused: cube.xml: "
            "contactlaw:cube-board: restitution=1.5 must be in [0, 1]");
  // a key the law or friction model does not read
  EXPECT_EQ(Refusal("transition_velocity=1e-4:1e-2:log"),
            "transition_velocity: no tag of cube.xml reads it (law=flores, "
            "friction=coulomb)");
  EXPECT_EQ(Refusal("linear_stiffness=1e4:1e6"),
            "linear_stiffness: no tag of cube.xml reads it (law=flores, "
            "friction=coulomb)");
}

TEST(FitTest, ParametersMapToTagKeysAndModelEdits) {
  const Scene scene = CubeScene("law=flores restitution=0.3 stiffness=3e5");
  const std::vector<FitParameter> p =
      ParseFitParameters("stiffness=1e4:1e8:log,board.offset=-0.01:0.01", scene.model());
  EXPECT_NEAR(p[0].At(0.5), 1e6, 1e6 * 1e-14);  // exp(log) rounds
  EXPECT_DOUBLE_EQ(p[1].At(0.25), -0.005);
  const ReplayOptions o = WithParameters(ReplayOptions(), p, {2.5e5, -0.002});
  // the tag key as a number, no word
  EXPECT_TRUE(o.simulation.overrides.keys.empty());
  ASSERT_EQ(o.simulation.overrides.values.size(), 1u);
  EXPECT_EQ(o.simulation.overrides.values[0].key, "stiffness");
  EXPECT_EQ(o.simulation.overrides.values[0].value, 2.5e5);
  ASSERT_EQ(o.edits.size(), 1u);
  UniqueModel m(mj_copyModel(nullptr, scene.model()));
  ApplyEdits(m.get(), o.edits);
  EXPECT_DOUBLE_EQ(m->geom_pos[2], -0.002);  // the board, along its normal
}

// The edits act on a simulation: the cube placed on the board rests 2 mm
// lower on a board moved down 2 mm, and twice as heavy it sinks deeper.
TEST(FitTest, ModelEditsMoveTheBoardAndWeighTheCube) {
  const Scene scene = CubeScene("law=hunt-crossley restitution=0.3 stiffness=1e6");
  auto rest_z = [&](const std::vector<ModelEdit>& edits) {
    UniqueModel m(mj_copyModel(nullptr, scene.model()));
    ApplyEdits(m.get(), edits);
    Simulation sim(std::move(m), "cube.xml");
    sim.data()->qpos[2] = 0.0524;  // placed on the board's nominal plane
    while (sim.time() < 1.0) sim.Step(1e-4);
    return sim.data()->qpos[2];
  };
  const int board = 0, cube = 1;
  const double nominal = rest_z({});
  // the static depth of 4 corners, K d^1.5 = m g / 4: 0.16 mm, and 2^(2/3) deeper
  const double depth = std::pow(0.37 * 9.81 / 4 / 1e6, 1 / 1.5);
  EXPECT_NEAR(nominal, 0.0524 - depth, 1e-7);
  EXPECT_NEAR(rest_z({{ModelEdit::Kind::kOffset, board, -0.002}}), nominal - 0.002, 1e-9);
  EXPECT_NEAR(rest_z({{ModelEdit::Kind::kMassScale, cube, 2.0}}),
              0.0524 - depth * std::pow(2.0, 1 / 1.5), 1e-7);
}

// The recovery tests' truth, and their rollouts' options.
constexpr char kTruth[] = "law=flores restitution=0.3 stiffness=3e5 friction=coulomb mu=0.35";
ReplayOptions TossOptions() {
  ReplayOptions options;
  options.simulation.timestep = 6.756756756756757e-4;  // the published 10 steps per sample
  return options;
}

// 12 tosses simulated with kTruth, their positions and orientations blurred
// as a camera tracker's.
MeasuredData NoisyTosses() {
  const MeasuredData data = Simulated(CubeScene(kTruth), TossStarts(12, 7), TossOptions());
  // 1 mm of position and 0.01 rad of orientation noise: the order of the
  // tracking's (the tosses rest ~2 mm from the board's plane); no velocity
  // columns, the refit takes them from the positions
  std::mt19937_64 random(11);
  std::normal_distribution<double> noise(0.0, 1.0);
  MeasuredData noisy;
  noisy.source = "noisy";
  noisy.columns.assign(data.columns.begin(), data.columns.begin() + 7);
  for (const MeasuredTrajectory& t : data.trajectories) {
    MeasuredTrajectory n = t;
    n.values.clear();
    for (int k = 0; k < t.samples(); ++k) {
      const double* x = t.values.data() + k * data.columns.size();
      double q[4] = {x[3], x[4], x[5], x[6]};
      for (double& c : q) c += 0.005 * noise(random);  // ~0.01 rad of turn
      mju_normalize4(q);
      n.values.insert(n.values.end(), {x[0] + 1e-3 * noise(random), x[1] + 1e-3 * noise(random),
                                       x[2] + 1e-3 * noise(random), q[0], q[1], q[2], q[3]});
    }
    noisy.trajectories.push_back(std::move(n));
  }
  return noisy;
}

// Tosses simulated with a known tag, blurred, fitted back.
TEST(FitTest, RecoversKnownParametersFromNoisyTosses) {
  const MeasuredData noisy = NoisyTosses();
  const ReplayOptions options = TossOptions();
  const Scene scene = CubeScene("law=flores restitution=0.7 stiffness=1e6 friction=coulomb mu=0.8");
  const Replay replay(scene, noisy);
  FitOptions fit;
  fit.replay = options;
  fit.replay.start = StartRule::kRefit;
  fit.replay.jobs = 2;
  fit.parameters =
      ParseFitParameters("restitution=0.05:0.9,stiffness=3e4:3e6:log,mu=0.05:1", scene.model());
  CheckFit(scene, fit.replay, fit.parameters);
  fit.budget = 90;
  fit.seed = 3;
  const FitResult result = Fit(replay, fit);
  EXPECT_GT(result.evaluations, 60);  // BOBYQA may stop early, at its tolerance
  EXPECT_LE(result.evaluations, 90);
  EXPECT_FALSE(result.interrupted);
  // The tolerances: what 12 noisy tosses determine. e shapes each bounce
  // (0.05 of its range); mu the slide after landing (0.05); K only the
  // depth (d ~ K^-0.4: a factor of 3 in K is 0.2 mm of a corner's 0.5 mm,
  // under the 1 mm noise) and the duration of contacts that last ~10 ms,
  // which 148 Hz samples barely see.
  EXPECT_NEAR(result.values[0], 0.3, 0.05);
  EXPECT_GT(result.values[1], 3e5 / 3);
  EXPECT_LT(result.values[1], 3e5 * 3);
  EXPECT_NEAR(result.values[2], 0.35, 0.05);
  // and the point found scores no worse than the truth on the noisy data
  const double at_truth = MeanScore(
      replay.Run(WithParameters(fit.replay, fit.parameters, {0.3, 3e5, 0.35})), Metric::kEq);
  EXPECT_LE(result.score, at_truth * 1.02);

  // the same seed, the same result, whatever the threads
  fit.replay.jobs = 1;
  fit.budget = 15;
  const FitResult a = Fit(replay, fit);
  fit.replay.jobs = 3;
  const FitResult b = Fit(replay, fit);
  EXPECT_EQ(a.values, b.values);
  EXPECT_EQ(a.score, b.score);
}

// Ten tosses simulated with kTruth and two with a far bouncier tag (a
// disturbed or mislabelled measurement): the mean's fit of restitution is
// pulled towards the two; a fit that leaves the worst 20% out (2 of 12) is
// not, and reports the trimmed mean as its score.
TEST(FitTest, ATrimmedScoreIsNotPulledByOutliers) {
  const MeasuredData starts = TossStarts(12, 7);
  MeasuredData data = Simulated(CubeScene(kTruth), starts, TossOptions());
  const MeasuredData bouncy = Simulated(
      CubeScene("law=flores restitution=0.9 stiffness=3e5 friction=coulomb mu=0.35"), starts,
      TossOptions());
  data.trajectories[3] = bouncy.trajectories[3];
  data.trajectories[8] = bouncy.trajectories[8];
  const Scene scene = CubeScene(kTruth);
  const Replay replay(scene, data);
  FitOptions fit;
  fit.replay = TossOptions();
  fit.replay.jobs = 2;
  fit.parameters = ParseFitParameters("restitution=0.05:0.95", scene.model());
  fit.budget = 30;
  fit.seed = 5;
  const FitResult mean = Fit(replay, fit);
  fit.trim = 0.2;
  const FitResult trimmed = Fit(replay, fit);
  // noise-free tosses: the ten determine e to well within 0.02 (a bounce's
  // height goes with e^2); 30 evaluations of one parameter resolve 1e-3
  EXPECT_NEAR(trimmed.values[0], 0.3, 0.02);
  EXPECT_GT(std::abs(mean.values[0] - 0.3), 0.02) << "the two tosses did not pull the mean";
  const std::vector<ReplayedTrajectory> at =
      replay.Run(WithParameters(fit.replay, fit.parameters, trimmed.values));
  EXPECT_EQ(trimmed.score, TrimmedMeanScore(at, Metric::kEq, 0.2));
  EXPECT_LT(trimmed.score, MeanScore(at, Metric::kEq));
  fit.trim = 0.5;
  EXPECT_EQ(Refused([&] { Fit(replay, fit); }), "trim 0.5: must be in [0, 0.5)");
}

// A fit's evaluation sets its values on the tags as numbers and its edits on
// a copy of the model: the tags' text is read once, when the scene is made.
// Overwritten after that with words the parser refuses, it changes no
// evaluation (tag keys and a model edit); read again, it would be refused.
TEST(FitTest, AnEvaluationReadsNoText) {
  const Scene scene = CubeScene(kTruth);
  const MeasuredData tosses = Simulated(scene, TossStarts(4, 5), TossOptions());
  const Replay replay(scene, tosses);
  FitOptions fit;
  fit.replay = TossOptions();
  fit.replay.jobs = 2;
  fit.parameters =
      ParseFitParameters("restitution=0.1:0.9,mu=0.1:1,cube.mass_scale=0.5:2", scene.model());
  fit.budget = 5;
  fit.seed = 5;
  const FitResult intact = Fit(replay, fit);
  // the test's own model: nothing else reads it
  mjModel* m = const_cast<mjModel*>(scene.model());
  for (int i = 0; i < m->ntextdata; ++i) {
    if (m->text_data[i] != '\0') m->text_data[i] = '!';
  }
  EXPECT_THROW(ContactModel(scene.model(), "cube.xml"), Error);
  const FitResult unread = Fit(replay, fit);
  EXPECT_EQ(unread.evaluations, 5);
  EXPECT_EQ(unread.values, intact.values);
  EXPECT_EQ(unread.score, intact.score);
}

// The start of a fit refused in one line naming the key, value and bounds.
TEST(FitTest, RefusesAStartNamingTheKey) {
  const Scene scene = CubeScene("law=flores restitution=0.3 stiffness=3e5 friction=coulomb mu=0.3");
  const std::vector<FitParameter> p = ParseFitParameters(
      "restitution=0.1:0.9,stiffness=1e4:1e7:log,board.offset=-0.004:0.001", scene.model());
  const std::vector<std::optional<double>> accepted =
      ParseFitInitial("board.offset=-0.002,restitution=0.5", p, scene.model());
  EXPECT_EQ(accepted, (std::vector<std::optional<double>>{0.5, std::nullopt, -0.002}));
  auto refusal = [&](const std::string& text) {
    return Refused([&] { ParseFitInitial(text, p, scene.model()); });
  };
  EXPECT_EQ(refusal("restitutoin=0.5"),
            "restitutoin=0.5: 'restitutoin' is not a contactlaw tag key (did you mean "
            "'restitution'?), nor OBJECT.KEY (mass_scale, inertia_scale, offset, mujoco.*)");
  EXPECT_EQ(refusal("ball.mass_scale=1"),
            "ball.mass_scale=1: the scene has no moving body 'ball'");
  EXPECT_EQ(refusal("mu=0.3"),
            "mu=0.3: 'mu' is not one of the parameters (restitution, stiffness, "
            "board.offset)");
  EXPECT_EQ(refusal("restitution=0.95"),
            "restitution=0.95: outside its bounds [0.1, 0.9]");
  EXPECT_EQ(refusal("stiffness=1e3"),
            "stiffness=1000: outside its bounds [10000, 10000000]");
  EXPECT_EQ(refusal("restitution=x"), "restitution=x: 'x' is not a finite number");
  EXPECT_EQ(refusal("restitution=nan"), "restitution=nan: 'nan' is not a finite number");
  EXPECT_EQ(refusal("restitution=0.5,restitution=0.6"),
            "restitution=0.6: key 'restitution' is given twice");
  EXPECT_EQ(refusal("restitution"), "restitution: is not of the form KEY=VALUE");
  // the library's own check, for a start not parsed from text
  EXPECT_EQ(Refused([&] { CheckInitial(p, {0.5}); }),
            "1 values given for 3 parameters (restitution, stiffness, board.offset)");
  EXPECT_EQ(Refused([&] { CheckInitial(p, {0.5, std::nullopt, 0.002}); }),
            "board.offset=0.002: outside its bounds [-0.004, 0.001]");
  EXPECT_EQ(Refused([&] { CheckInitial(p, {}); }), "accepted");  // no start: the middle
}

// The first evaluation is the start, at the values given to the bit: with a
// budget of one, the fit's point and score are the start's.
TEST(FitTest, ABudgetOfOneEvaluatesTheStart) {
  const Scene scene = CubeScene("law=flores restitution=0.7 stiffness=1e6 friction=coulomb mu=0.8");
  const MeasuredData data = Simulated(CubeScene(kTruth), TossStarts(3, 5), TossOptions());
  const Replay replay(scene, data);
  FitOptions fit;
  fit.replay = TossOptions();
  fit.parameters =
      ParseFitParameters("restitution=0.05:0.9,stiffness=3e4:3e6:log,mu=0.05:1", scene.model());
  fit.budget = 1;
  // values that At(Unit(value)) misses by a rounding (0.3 and 3e5 here)
  fit.initial = {0.3, 3e5, std::nullopt};
  const FitResult result = Fit(replay, fit);
  ASSERT_EQ(result.evaluations, 1);
  // mu, not given, at its range's middle
  const std::vector<double> start = {0.3, 3e5, fit.parameters[2].At(0.5)};
  EXPECT_EQ(result.values, start);
  EXPECT_EQ(result.score,
            MeanScore(replay.Run(WithParameters(fit.replay, fit.parameters, start)), Metric::kEq));
  // a log range's middle is the geometric mean of its bounds
  EXPECT_NEAR(fit.parameters[1].At(0.5), 3e5, 3e5 * 1e-14);  // exp(log) rounds
  fit.initial = {0.3, 3e6 * 1.01, std::nullopt};
  EXPECT_THROW(Fit(replay, fit), Error);
}

// Started at the truth of the noisy tosses, a small budget ends no worse
// than the truth scores (the first evaluation is the truth), and the same
// seed gives the same bits.
TEST(FitTest, AStartAtTheTruthEndsNoWorseThanIt) {
  const MeasuredData noisy = NoisyTosses();
  const Scene scene = CubeScene("law=flores restitution=0.7 stiffness=1e6 friction=coulomb mu=0.8");
  const Replay replay(scene, noisy);
  FitOptions fit;
  fit.replay = TossOptions();
  fit.replay.start = StartRule::kRefit;
  fit.replay.jobs = 2;
  fit.parameters =
      ParseFitParameters("restitution=0.05:0.9,stiffness=3e4:3e6:log,mu=0.05:1", scene.model());
  fit.budget = 12;
  fit.seed = 3;
  fit.initial = {0.3, 3e5, 0.35};
  double first = -1;
  fit.on_evaluation = [&](int n, double score, double) {
    if (n == 1) first = score;
  };
  const FitResult a = Fit(replay, fit);
  const double at_truth = MeanScore(
      replay.Run(WithParameters(fit.replay, fit.parameters, {0.3, 3e5, 0.35})), Metric::kEq);
  EXPECT_EQ(first, at_truth);
  EXPECT_LE(a.score, at_truth);
  EXPECT_EQ(a.evaluations, 12);
  fit.replay.jobs = 1;
  const FitResult b = Fit(replay, fit);
  EXPECT_EQ(a.values, b.values);
  EXPECT_EQ(a.score, b.score);
}

}  // namespace
}  // namespace contactlaws
