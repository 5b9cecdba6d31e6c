// Copyright contactlaws authors.
//
// contactlaws run as a user runs it: exit status, the one-line refusals, and
// the CSV it writes.

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace {

struct Result {
  int status = -1;
  std::string output;  // stdout and stderr
};

Result RunCli(const std::string& arguments) {
  const std::string command =
      std::string(CONTACTLAWS_CLI) + " " + arguments + " 2>&1";
  Result result;
  std::FILE* pipe = popen(command.c_str(), "r");
  char buffer[4096];
  size_t n;
  while ((n = std::fread(buffer, 1, sizeof(buffer), pipe)) > 0) result.output.append(buffer, n);
  const int status = pclose(pipe);
  result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

const std::string kBall = std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf/bouncing_ball.xml";

std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(CliTest, RefusalsExitTwoWithOneLine) {
  const struct {
    std::string arguments;
    std::string message;
  } cases[] = {
      {"run " + kBall + " --law hooke", "contactlaws: --law=hooke is not a law"},
      {"run " + kBall + " --restitution 1.5", "contactlaws: --restitution=1.5 must be in [0, 1]"},
      {"run " + kBall + " --restitution 0",
       "contactlaws: " + kBall +
           ": contactlaw:ball-floor: restitution=0 must be in (0, 1] for flores"},
      {"run " + kBall + " --duration 0", "contactlaws: --duration=0 must be a number > 0 (s)"},
      {"run " + kBall + " --timestep -1e-5", "contactlaws: --timestep=-1e-05 must be a number > 0"},
      {"run " + kBall + " --duration abc", "contactlaws: "},
      {"run " + kBall + " --integrator rk5", "contactlaws: --integrator=rk5 must be euler, rk4 or implicit"},
      {"run " + kBall + " --frobnicate", "contactlaws: "},
      {"run /nonexistent.xml", "contactlaws: /nonexistent.xml: "},
      {"run " + kBall + " --duration 0.01 --output /nonexistent/dir/out.csv",
       "contactlaws: /nonexistent/dir/out.csv: cannot write"},
  };
  for (const auto& c : cases) {
    const Result r = RunCli(c.arguments);
    EXPECT_EQ(r.status, 2) << c.arguments << "\n" << r.output;
    EXPECT_EQ(r.output.rfind(c.message, 0), 0u) << c.arguments << "\n" << r.output;
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << "one line: " << r.output;
  }
}

TEST(CliTest, RunWritesTheTrajectoryAndImpactLog) {
  const std::string dir = ::testing::TempDir();
  const std::string trajectory = dir + "/cli_ball.csv";
  const std::string impacts = dir + "/cli_impacts.csv";
  const Result r = RunCli("run " + kBall + " --law hunt-crossley --restitution 0.8 --duration 0.5 " +
                       "--sample-rate 100 --output " + trajectory + " --impacts " + impacts);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("ball-floor"), std::string::npos) << r.output;

  const std::string csv = ReadFile(trajectory);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "time,ball.x,ball.y,ball.z,ball.vx,ball.vy,ball.vz,ball-floor.depth,"
            "ball-floor.depth_rate,ball-floor.force,energy.kinetic,energy.potential,"
            "energy.elastic,energy.dissipated,energy.total");
  // 0 to 0.5 s at 100 rows per second: 51 rows and the header
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 52);
  EXPECT_NE(csv.find("\n0.5,"), std::string::npos);
  EXPECT_EQ(csv.find("nan"), std::string::npos);

  const std::string log = ReadFile(impacts);
  EXPECT_EQ(log.substr(0, log.find('\n')),
            "law,restitution,pair,geom1,geom2,index,time_contact,time_separation,"
            "impact_velocity,separation_velocity,restitution_post,max_depth,max_force");
  EXPECT_EQ(log.find("\nhunt-crossley,0.8,ball-floor,ball,floor,1,0.42"), log.find('\n'));
}

TEST(CliTest, LawsListsEveryLaw) {
  const Result r = RunCli("laws");
  ASSERT_EQ(r.status, 0) << r.output;
  for (const char* expected :
       {"\nhertz\n  F = K d^n\n", "\nkelvin-voigt\n  F = k d + c d'\n",
        "\nhunt-crossley\n  F = K d^n (1 + 3(1-e)/2 * d'/v0)\n",
        "\nlankarani-nikravesh\n  F = K d^n (1 + 3(1-e^2)/4 * d'/v0)\n",
        "\nflores\n  F = K d^n (1 + 8(1-e)/(5e) * d'/v0)\n", "Hunt, F. R. E. Crossley",
        "restitution e in (0, 1]", "default 0.001 m/s"}) {
    EXPECT_NE(r.output.find(expected), std::string::npos) << expected << "\n" << r.output;
  }
}

TEST(CliTest, TrajectoryToStandardOutput) {
  const Result r = RunCli("run " + kBall + " --duration 0.002 --output -");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.rfind("time,ball.x", 0), 0u) << r.output;
}

}  // namespace
