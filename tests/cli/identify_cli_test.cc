// Copyright contactlaws authors.
//
// contactlaws replay and fit, run as a user runs them.

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "cli_test_util.h"

namespace contactlaws::testing {
namespace {

// A cube thrown onto a board, its tag's words given.
std::string CubeScene(const std::string& name, const std::string& tag) {
  return WriteScene(name, fmt::format(R"(<mujoco>
  <option timestep="5e-4" integrator="RK4"/>
  <worldbody>
    <geom name="board" type="plane" size="1 1 0.1"/>
    <body name="cube" pos="0 0 0.2">
      <freejoint/>
      <inertial pos="0 0 0" mass="0.37" diaginertia="8.1e-4 8.1e-4 8.1e-4"/>
      <geom name="cube" type="box" size="0.0524 0.0524 0.0524"/>
    </body>
  </worldbody>
  <keyframe><key qpos="0 0 0.2 0.96 0.2 0.2 0" qvel="1 0 -0.5 3 -2 1"/></keyframe>
  <custom><text name="contactlaw:cube-board" data="geom1=cube geom2=board {}"/></custom>
</mujoco>)",
                                                 tag));
}

constexpr char kTag[] = "law=flores restitution=0.3 stiffness=3e5 friction=coulomb mu=0.3";

// `run`'s trajectory of scene as measured data: a trajectory column added,
// twice (two trajectories of the same run).
std::string MeasuredFromRun(const std::string& scene, const std::string& name,
                            double duration = 0.5) {
  const std::string run = ::testing::TempDir() + "/" + name + "_run.csv";
  const Result r = RunCli(fmt::format("run {} --duration {} --sample-rate 148 --columns bodies "
                                      "--output {}",
                                      scene, duration, run));
  EXPECT_EQ(r.status, 0) << r.output;
  const std::vector<std::string> lines = Lines(ReadFile(run));
  const std::string path = ::testing::TempDir() + "/" + name + ".csv";
  std::ofstream out(path);
  out << "trajectory," << lines[0] << "\n";
  for (const char* t : {"a", "b"}) {
    for (size_t i = 1; i < lines.size(); ++i) out << t << "," << lines[i] << "\n";
  }
  return path;
}

TEST(IdentifyCliTest, ARunReplaysAgainstItselfToZero) {
  const std::string scene = CubeScene("replay_self", kTag);
  const std::string data = MeasuredFromRun(scene, "replay_self");
  const std::string dir = ::testing::TempDir() + "/replay_self_out";
  const Result r = RunCli(fmt::format("replay {} --data {} --timestep 5e-4 --output {}", scene,
                                      data, dir));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("2 trajectories of"), std::string::npos) << r.output;
  const std::vector<std::string> rows = Lines(ReadFile(dir + "/replay.csv"));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0], "trajectory,samples,start,e_q,position_rms,angle_rms,joint_rms,weighted,status");
  for (size_t i = 1; i < rows.size(); ++i) {
    const std::vector<std::string> f = Split(rows[i], ',');
    EXPECT_EQ(f[1], "75");  // 0.5 s at 148 Hz, t = 0 included
    // the start state read back from the CSV's shortest exact numbers and
    // renormalized: rounding, grown through the landing
    EXPECT_LT(std::stod(f[4]), 1e-12) << rows[i];
    EXPECT_LT(std::stod(f[5]), 1e-10) << rows[i];
    EXPECT_EQ(f[8], "complete");
  }
  // the simulated trajectories, in the data's columns
  const std::vector<std::string> simulated = Lines(ReadFile(dir + "/trajectories.csv"));
  EXPECT_EQ(simulated[0], Lines(ReadFile(data))[0]);
  EXPECT_EQ(simulated.size(), 1u + 2 * 75u);
  // another law is far from it: the score can fail
  const Result hertz = RunCli(fmt::format("replay {} --data {} --timestep 5e-4 --law hertz",
                                          scene, data));
  EXPECT_EQ(hertz.status, 0) << hertz.output;
  EXPECT_EQ(hertz.output.find("e_q mean 0 "), std::string::npos) << hertz.output;
}

TEST(IdentifyCliTest, BadInputIsRefusedInOneLineAndNothingIsWritten) {
  const std::string scene = CubeScene("replay_bad", kTag);
  const std::string data = MeasuredFromRun(scene, "replay_bad");
  const std::string dir = ::testing::TempDir() + "/replay_bad_out";
  std::filesystem::remove_all(dir);
  const std::string other = WriteScene("replay_bad_ball", TagScene(Tag("geom1=ball geom2=floor law=hertz stiffness=1e6")));
  // 0.1 s from 0.2 m: the cube is still falling at the end
  const std::string falling = MeasuredFromRun(scene, "replay_bad_falling", 0.1);
  const std::string never_rest =
      fmt::format("{}: 0 of 2 trajectories come to rest (slower than 0.02 m/s over their last 5 "
                  "samples): an offset from their resting height needs at least 5",
                  falling);
  const std::pair<std::string, std::string> cases[] = {
      {fmt::format("replay {} --data /nonexistent.csv --output {}", scene, dir),
       "contactlaws: /nonexistent.csv: cannot open the file"},
      {fmt::format("replay {} --data {} --output {}", other, data, dir),
       fmt::format("contactlaws: {}: column 'cube.x': the scene {} has no body or joint 'cube'",
                   data, other)},
      {fmt::format("replay {} --data {} --start last --output {}", scene, data, dir),
       "contactlaws: --start=last must be first or refit"},
      {fmt::format("replay {} --data {} --metric rms --output {}", scene, data, dir),
       "contactlaws: --metric=rms must be e_q, position_rms, angle_rms or weighted"},
      {fmt::format("fit {} --data {} --params mu=0.1:0.5 --laws flores,hartz --output {}", scene,
                   data, dir),
       "contactlaws: --laws=flores,hartz has 'hartz', which is not a law"},
      {fmt::format("fit {} --data {} --params stribeck_velocity=0.01:0.1 --output {}", scene, data,
                   dir),
       "contactlaws: --params: stribeck_velocity: no tag of " + scene +
           " reads it (law=flores, friction=coulomb)"},
      {fmt::format("fit {} --data {} --params restitution=0.5:2 --output {}", scene, data, dir),
       "contactlaws: --params: restitution=0.5:2: the bound 2 is refused: " + scene +
           ": contactlaw:cube-board: restitution=2 must be in [0, 1]"},
      {fmt::format("fit {} --data {} --params mu=0.5:0.5 --output {}", scene, data, dir),
       "contactlaws: --params: mu=0.5:0.5: the bounds are empty (0.5 >= 0.5)"},
      {fmt::format("fit {} --data {} --params mu=0.1:0.5 --initial mu=0.3,restitutoin=0.5 "
                   "--output {}",
                   scene, data, dir),
       "contactlaws: --initial: restitutoin=0.5: 'restitutoin' is not a contactlaw tag key (did "
       "you mean 'restitution'?)"},
      {fmt::format("fit {} --data {} --params mu=0.1:0.5 --initial restitution=0.5 --output {}",
                   scene, data, dir),
       "contactlaws: --initial: restitution=0.5: 'restitution' is not one of the parameters (mu)"},
      {fmt::format("fit {} --data {} --params mu=0.1:0.5 --initial mu=0.6 --output {}", scene,
                   data, dir),
       "contactlaws: --initial: mu=0.6: outside its bounds [0.1, 0.5]"},
      {fmt::format("fit {} --data {} --params mu=0.1:0.5 --initial mu=low --output {}", scene,
                   data, dir),
       "contactlaws: --initial: mu=low: 'low' is not a finite number"},
      {fmt::format("fit {} --data {} --params mu=0.1:0.5 --initial mu=0.2,mu=0.3 --output {}",
                   scene, data, dir),
       "contactlaws: --initial: mu=0.3: key 'mu' is given twice"},
      {fmt::format("fit {} --data {} --params mu=0.1:0.5 --folds 1 --output {}", scene, data, dir),
       fmt::format("contactlaws: --folds=1 must be a whole number in [2, 2] (the trajectories of "
                   "{})", data)},
      {fmt::format("fit {} --data {} --params mu=0.1:0.5 --folds 3 --output {}", scene, data, dir),
       fmt::format("contactlaws: --folds=3 must be a whole number in [2, 2] (the trajectories of "
                   "{})", data)},
      {fmt::format("fit {} --data {} --params mu=0.1:0.5 --trim 0.5 --output {}", scene, data, dir),
       "contactlaws: --trim=0.5 must be a number in [0, 0.5)"},
      {fmt::format("fit {} --data {} --params mu=0.1:0.5 --trim some --output {}", scene, data, dir),
       "contactlaws: --trim=some must be a number in [0, 0.5)"},
      {fmt::format("fit {} --data {} --params mu=0.1:0.5 --profile mu,restitution --output {}",
                   scene, data, dir),
       "contactlaws: --profile=mu,restitution has 'restitution', which is not a key of --params "
       "(mu) nor all"},
      {fmt::format("fit {} --data {} --params mu=0.1:0.5 --profile mu,mu --output {}", scene, data,
                   dir),
       "contactlaws: --profile=mu,mu names mu twice"},
      {fmt::format("fit {} --data {} --params mu=0.1:0.5 --profile all --profile-points 2 "
                   "--output {}",
                   scene, data, dir),
       "contactlaws: --profile-points=2 must be a whole number in [3, 200]"},
      {fmt::format("fit {} --data {} --params mu=0.1:0.5 --profile-points 5 --output {}", scene,
                   data, dir),
       "contactlaws: --profile-points=5 goes with --profile"},
      {fmt::format("fit {} --data {} --params mu=0.1:0.5 --profile-budget 5 --output {}", scene,
                   data, dir),
       "contactlaws: --profile-budget=5 goes with --profile"},
      {fmt::format("replay {} --data {} --rest-plane board --output {}", scene, falling, dir),
       "contactlaws: " + never_rest},
      {fmt::format("fit {} --data {} --params mu=0.1:0.5,board.offset=rest --output {}", scene,
                   falling, dir),
       "contactlaws: --params: board.offset=rest: " + never_rest},
      {fmt::format("replay {} --data {} --rest-plane cube --output {}", scene, data, dir),
       fmt::format("contactlaws: {}: geom 'cube' is not a plane of the world facing up", scene)},
  };
  for (const auto& [arguments, message] : cases) {
    const Result r = RunCli(arguments);
    EXPECT_EQ(r.status, 2) << arguments << "\n" << r.output;
    const std::vector<std::string> lines = Lines(r.output);
    ASSERT_EQ(lines.size(), 1u) << arguments << "\n" << r.output;
    EXPECT_EQ(lines[0].substr(0, message.size()), message) << arguments;
    EXPECT_FALSE(std::filesystem::exists(dir)) << arguments;
  }
}

TEST(IdentifyCliTest, AFitWritesItsRankingAndTheTagToPaste) {
  const std::string truth = CubeScene("fit_truth", kTag);
  const std::string data = MeasuredFromRun(truth, "fit_data");
  const std::string scene = CubeScene("fit_start", "law=flores restitution=0.6 stiffness=3e5 friction=coulomb mu=0.6");
  const std::string dir = ::testing::TempDir() + "/fit_out";
  const Result r = RunCli(fmt::format("fit {} --data {} --validate {} --timestep 5e-4 --params "
                                      "restitution=0.1:0.9,mu=0.1:0.9 --budget 30 --laws flores,hertz "
                                      "--quiet --output {}",
                                      scene, data, data, dir));
  ASSERT_EQ(r.status, 0) << r.output;
  const std::vector<std::string> ranking = Lines(ReadFile(dir + "/ranking.csv"));
  ASSERT_EQ(ranking.size(), 3u);
  // each mean and median with its interval, beside the scores in mm and degrees
  const std::string head = "law,friction,restitution,mu,train_mean,train_mean_lo,train_mean_hi,"
                           "train_median,train_median_lo,train_median_hi,train_p90,"
                           "train_position_mm_mean,train_position_mm_mean_lo,";
  EXPECT_EQ(ranking[0].substr(0, head.size()), head);
  const std::string tail = ",validate_another_face,validate_another_face_lo,"
                           "validate_another_face_hi,versus_winner,versus_winner_lo,"
                           "versus_winner_hi,distinguishable,evaluations,wall_seconds,status";
  EXPECT_EQ(ranking[0].substr(ranking[0].size() - tail.size()), tail);
  for (const char* column : {",train_angle_deg_median_hi,", ",train_final_angle_deg_p90,",
                             ",validate_mean,validate_mean_lo,validate_mean_hi,"}) {
    EXPECT_NE(ranking[0].find(column), std::string::npos) << column;
  }
  EXPECT_NE(r.output.find("another face: "), std::string::npos) << r.output;
  // flores fits its own data best; hertz reads no restitution
  EXPECT_EQ(ranking[1].substr(0, 15), "flores,coulomb,");
  EXPECT_EQ(ranking[2].substr(0, 15), "hertz,coulomb,,");
  const std::vector<std::string> best = Split(ranking[1], ',');
  // near the data's e and mu: 30 evaluations on one toss check the plumbing
  // (fit_test holds the recovery to its tolerances)
  EXPECT_NEAR(std::stod(best[2]), 0.3, 0.1);
  EXPECT_NEAR(std::stod(best[3]), 0.3, 0.1);
  EXPECT_LT(std::stod(best[4]), std::stod(Split(ranking[2], ',')[4]));
  const std::string tag = ReadFile(dir + "/best_tag.txt");
  EXPECT_EQ(tag.rfind("<text name=\"contactlaw:cube-board\" data=\"geom1=cube geom2=board "
                      "law=flores restitution=0.",
                      0),
            0u)
      << tag;
  EXPECT_EQ(Lines(ReadFile(dir + "/errors.csv")).size(), 1u + 2 * 2 * 2);
}

// --folds: every combination fitted on each fold's complement and scored on
// it, ranked by that score; the same files whatever the threads.
TEST(IdentifyCliTest, FoldsCrossValidateTheSameWhateverTheJobs) {
  const std::string truth = CubeScene("fit_folds_truth", kTag);
  const std::string data = MeasuredFromRun(truth, "fit_folds_data");
  std::string files[2][3];
  for (int jobs : {1, 2}) {
    const std::string dir = fmt::format("{}/fit_folds_out{}", ::testing::TempDir(), jobs);
    const Result r = RunCli(fmt::format("fit {} --data {} --timestep 5e-4 --params mu=0.1:0.9 "
                                        "--budget 6 --laws flores,hertz --folds 2 --seed 4 "
                                        "--jobs {} --quiet --output {}",
                                        truth, data, jobs, dir));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("the data (cv e_q, paired 95% bootstrap over 2 trajectories) tell "),
              std::string::npos)
        << r.output;
    std::string ranking;
    for (const std::string& line : Lines(ReadFile(dir + "/ranking.csv"))) {
      std::vector<std::string> f = Split(line, ',');
      f[f.size() - 2].clear();  // wall_seconds
      for (const std::string& field : f) ranking += field + ",";
      ranking += "\n";
    }
    files[jobs - 1][0] = ranking;
    files[jobs - 1][1] = ReadFile(dir + "/folds.csv");
    files[jobs - 1][2] = ReadFile(dir + "/errors.csv");
  }
  EXPECT_EQ(files[0][0], files[1][0]);
  EXPECT_EQ(files[0][1], files[1][1]);
  EXPECT_EQ(files[0][2], files[1][2]);
  EXPECT_EQ(Lines(files[0][1]).size(), 3u);  // header, a, b
  EXPECT_NE(files[0][0].find(",cv_mean,cv_mean_lo,cv_mean_hi,cv_median,"), std::string::npos);
  // the training and the held-out score of every trajectory, per combination
  EXPECT_EQ(Lines(files[0][2]).size(), 1u + 2 * (2 + 2));
  EXPECT_NE(files[0][2].find("flores,coulomb,cv,a,"), std::string::npos);
}

// --profile: the winner's profile written as numbers, a line per parameter
// said, and the same file whatever the threads (the others re-fitted at
// each point: each re-fit a seeded search too).
TEST(IdentifyCliTest, AProfileIsTheSameWhateverTheJobs) {
  const std::string truth = CubeScene("fit_profile_truth", kTag);
  const std::string data = MeasuredFromRun(truth, "fit_profile_data");
  std::string files[2];
  for (int jobs : {1, 2}) {
    const std::string dir = fmt::format("{}/fit_profile_out{}", ::testing::TempDir(), jobs);
    const Result r = RunCli(fmt::format("fit {} --data {} --timestep 5e-4 --params "
                                        "restitution=0.1:0.9,stiffness=1e4:1e7:log --budget 6 "
                                        "--laws flores,hertz --profile all --profile-points 4 "
                                        "--profile-budget 2 "
                                        "--seed 4 --jobs {} --quiet --output {}",
                                        truth, data, jobs, dir));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("profile of flores/coulomb on " + data + " (4 points per parameter "
                            "and the fitted value, the others re-fitted over 2 evaluations at "
                            "each;"),
              std::string::npos)
        << r.output;
    // a verdict per parameter the winner reads, in its units
    for (const char* key : {"\n  restitution: ", "\n  stiffness: "}) {
      const size_t at = r.output.find(key);
      ASSERT_NE(at, std::string::npos) << r.output;
      const std::string line = r.output.substr(at + 1, r.output.find('\n', at + 1) - at - 1);
      EXPECT_TRUE(line.find(": determined: ") != std::string::npos ||
                  line.find(": not determined by the data: any value in [") != std::string::npos)
          << line;
      if (std::string(key).find("stiffness") != std::string::npos) {
        EXPECT_NE(line.find("] N/m^n"), std::string::npos) << line;
      }
    }
    EXPECT_NE(r.output.find(dir + "/profile.csv"), std::string::npos) << r.output;
    files[jobs - 1] = ReadFile(dir + "/profile.csv");
  }
  EXPECT_EQ(files[0], files[1]);
  const std::vector<std::string> rows = Lines(files[0]);
  ASSERT_GE(rows.size(), 1u + 2 * 4u);
  EXPECT_LE(rows.size(), 1u + 2 * 5u);  // 4 points and the fitted value, per parameter
  EXPECT_EQ(rows[0], "key,scale,value,fitted,mean,mean_lo,mean_hi,versus_best,versus_best_lo,"
                     "versus_best_hi,indistinguishable,span_lo,span_hi,determined");
  int best = 0, fitted = 0;
  for (size_t i = 1; i < rows.size(); ++i) {
    const std::vector<std::string> f = Split(rows[i], ',');
    ASSERT_EQ(f.size(), 14u) << rows[i];
    EXPECT_TRUE(f[0] == "restitution" || f[0] == "stiffness") << rows[i];
    EXPECT_EQ(f[1], f[0] == "stiffness" ? "log" : "linear");
    best += f[10] == "best";
    fitted += f[3] == "yes";
    // the best point: its own difference 0, inside its span
    if (f[10] == "best") {
      EXPECT_EQ(f[7], "0") << rows[i];
      EXPECT_LE(std::stod(f[11]), std::stod(f[2])) << rows[i];
      EXPECT_GE(std::stod(f[12]), std::stod(f[2])) << rows[i];
    }
  }
  EXPECT_EQ(best, 2);
  EXPECT_EQ(fitted, 2);
}

// With a budget of one, every combination's one evaluation is the start:
// its values are the ranking's, the same for each law that reads them.
TEST(IdentifyCliTest, AFitStartsWhereItIsTold) {
  const std::string truth = CubeScene("fit_initial_truth", kTag);
  const std::string data = MeasuredFromRun(truth, "fit_initial_data");
  const std::string dir = ::testing::TempDir() + "/fit_initial_out";
  const Result r = RunCli(fmt::format("fit {} --data {} --timestep 5e-4 --params "
                                      "restitution=0.1:0.9,mu=0.1:0.9 --initial mu=0.25,"
                                      "restitution=0.35 --budget 1 --laws flores,hertz --quiet "
                                      "--output {}",
                                      truth, data, dir));
  ASSERT_EQ(r.status, 0) << r.output;
  const std::vector<std::string> ranking = Lines(ReadFile(dir + "/ranking.csv"));
  ASSERT_EQ(ranking.size(), 3u);
  // law,friction,restitution,mu,train_mean,...,evaluations,...
  for (size_t i = 1; i < ranking.size(); ++i) {
    const std::vector<std::string> row = Split(ranking[i], ',');
    EXPECT_EQ(row[2], row[0] == "hertz" ? "" : "0.35") << ranking[i];
    EXPECT_EQ(row[3], "0.25") << ranking[i];
    EXPECT_EQ(row[row.size() - 3], "1") << ranking[i];
  }
}

TEST(IdentifyCliTest, CtrlCEndsAFitWithTheBestSoFarWritten) {
  const std::string truth = CubeScene("fit_int_truth", kTag);
  const std::string data = MeasuredFromRun(truth, "fit_int_data");
  const std::string dir = ::testing::TempDir() + "/fit_interrupted";
  std::filesystem::remove_all(dir);
  const std::string log = ::testing::TempDir() + "/fit_interrupted.log";
  const pid_t pid = SpawnCli({"fit", truth, "--data", data, "--timestep", "5e-4", "--params",
                              "restitution=0.1:0.9", "--budget", "100000", "--jobs", "1",
                              "--output", dir},
                             log);
  ASSERT_GE(pid, 0);
  // progress at the first evaluation and every 10th: Ctrl-C once the 10th is done
  bool evaluated = false;
  for (int i = 0; i < 1200 && !evaluated; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    evaluated = ReadFile(log).find("evaluation 10/") != std::string::npos;
  }
  ASSERT_TRUE(evaluated) << ReadFile(log);
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << ReadFile(log);
  EXPECT_EQ(WEXITSTATUS(status), 130) << ReadFile(log);
  EXPECT_NE(ReadFile(log).find("interrupted: the best result so far is written"),
            std::string::npos)
      << ReadFile(log);
  // the start's score is shown: the first line of progress is the first evaluation's
  EXPECT_NE(ReadFile(log).find(": evaluation 1/100000: "), std::string::npos) << ReadFile(log);
  const std::vector<std::string> ranking = Lines(ReadFile(dir + "/ranking.csv"));
  ASSERT_EQ(ranking.size(), 2u);
  EXPECT_EQ(ranking[1].substr(ranking[1].rfind(',') + 1), "interrupted");
  EXPECT_FALSE(std::filesystem::exists(dir + "/ranking.csv.tmp"));
}

}  // namespace
}  // namespace contactlaws::testing
