// Copyright contactlaws authors.
//
// Test helpers: a fixture that fails on any MuJoCo warning, RAII model and
// data from inline XML, and the drop scenes the physics tests share.

#ifndef CONTACTLAWS_TESTS_MUJOCO_TEST_UTIL_H_
#define CONTACTLAWS_TESTS_MUJOCO_TEST_UTIL_H_

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include "contactlaws/contactlaws.h"

namespace contactlaws::testing {

// Fails the test on any MuJoCo warning: those sent to mju_user_warning, and
// those counted in the warning statistics of every mjData made by MakeData.
class MujocoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    previous_warning_ = mju_user_warning;
    mju_user_warning = &MujocoTest::RecordWarning;
    Warnings().clear();
  }

  void TearDown() override {
    mju_user_warning = previous_warning_;
    for (const std::string& w : Warnings()) ADD_FAILURE() << "MuJoCo warning: " << w;
    for (const UniqueData& d : data_) CheckNoWarnings(d.get());
    for (const auto& sim : simulations_) CheckNoWarnings(sim->data());
    if (std::getenv(kTestContactStepsVariable) && simulations_.empty()) {
      std::printf("note: no Simulation made by the fixture: this test ran without contact "
                  "steps\n");
    }
  }

  static void CheckNoWarnings(const mjData* d) {
    for (int i = 0; i < mjNWARNING; ++i) {
      EXPECT_EQ(d->warning[i].number, 0) << "MuJoCo warning " << i << " raised";
    }
  }

  // Takes back the MuJoCo warnings containing text, which the test caused on
  // purpose; fails when there is none. Returns how many there were.
  size_t ExpectMujocoWarning(std::string_view text) {
    std::vector<std::string>& w = Warnings();
    const auto matches = [&](const std::string& m) { return m.find(text) != std::string::npos; };
    const size_t before = w.size();
    w.erase(std::remove_if(w.begin(), w.end(), matches), w.end());
    EXPECT_LT(w.size(), before) << "no MuJoCo warning with: " << text;
    return before - w.size();
  }

  // The MuJoCo warnings so far that contain text.
  size_t CountMujocoWarnings(std::string_view text) {
    return std::count_if(Warnings().begin(), Warnings().end(),
                         [&](const std::string& m) { return m.find(text) != std::string::npos; });
  }

  // A model from inline XML, named after the test in messages.
  UniqueModel Load(std::string_view xml) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    return LoadModelString(xml, fmt::format("{}.xml", info->name()));
  }

  // A Simulation of inline XML, checked for warnings at the end of the test.
  Simulation& MakeSimulation(std::string_view xml, const SimulationOptions& options = {}) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string name = fmt::format("{}.xml", info->name());
    simulations_.push_back(std::make_unique<Simulation>(LoadModelString(xml, name), name,
                                                        WithTestContactSteps(options)));
    return *simulations_.back();
  }

  // A Simulation of a scene of mjcf/, checked like MakeSimulation's.
  Simulation& MakeSceneSimulation(const std::string& file, const SimulationOptions& options = {}) {
    const std::string path = std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf/" + file;
    simulations_.push_back(
        std::make_unique<Simulation>(LoadModelFile(path), file, WithTestContactSteps(options)));
    return *simulations_.back();
  }

  // options, with the contacts integrated inside each step when the test
  // runs under kTestContactStepsVariable (auto or a count of sub-steps; the
  // tests registered a second time, label contact-steps: tests/CMakeLists.txt)
  // and options do not set them already.
  static constexpr const char* kTestContactStepsVariable = "CONTACTLAWS_TEST_CONTACT_STEPS";
  static SimulationOptions WithTestContactSteps(SimulationOptions options) {
    const char* text = std::getenv(kTestContactStepsVariable);
    if (!text || options.contact_steps.enabled()) return options;
    const std::string value = text;
    if (value == "auto") {
      options.contact_steps.substeps = kContactStepsAuto;
    } else if (!value.empty() && value.find_first_not_of("0123456789") == std::string::npos &&
               value.size() < 7 && std::stoi(value) >= 1) {
      options.contact_steps.substeps = std::stoi(value);
    } else {
      throw Error(fmt::format("{}={} must be auto or a whole number >= 1",
                              kTestContactStepsVariable, value));
    }
    return options;
  }

  // Data owned by the fixture, checked for warnings at the end of the test.
  mjData* MakeData(const mjModel* m) {
    data_.emplace_back(mj_makeData(m));
    return data_.back().get();
  }

 private:
  static std::vector<std::string>& Warnings() {
    static std::vector<std::string> warnings;
    return warnings;
  }
  static void RecordWarning(const char* message) { Warnings().emplace_back(message); }

  void (*previous_warning_)(const char*) = nullptr;
  std::vector<UniqueData> data_;
  std::vector<std::unique_ptr<Simulation>> simulations_;
};

// A 1 kg cube of 0.1 m, axis-aligned, its centre at height z (m) over a floor
// plane, RK4 at timestep (s); its tag contactlaw:box carries tag_keys (the
// law and its keys; the stiffness is 1e7, friction none).
inline std::string CubeOnFloorXml(double timestep, double z, std::string_view tag_keys) {
  return fmt::format(R"(<mujoco>
  <option timestep="{}" integrator="RK4"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <body name="box" pos="0 0 {}"><freejoint/>
      <geom name="box" type="box" size="0.05 0.05 0.05" mass="1"/></body>
  </worldbody>
  <custom><text name="contactlaw:box" data="geom1=box geom2=floor {}
    stiffness=1e7 friction=none"/></custom>
</mujoco>)",
                     timestep, z, tag_keys);
}

// A 6 cm cube of 0.2 kg on a floor (plane-box: 4 corners), its bottom `depth`
// m into the floor, sliding at 1.2 m/s: zhiying-qishao e = 0.3, K 1e7 N/m^1.5,
// coulomb mu 0.2, at a fixed 5e-5 s (the lead's slide.xml block).
inline std::string SlidingBlockXml(double depth) {
  return fmt::format(R"(<mujoco>
  <option timestep="5e-5" integrator="RK4"/>
  <worldbody><geom name="floor" type="plane" size="2 2 0.1"/>
    <body name="block" pos="0 0 {0}"><freejoint/>
      <geom name="block" type="box" size="0.03 0.03 0.03" mass="0.2"/></body></worldbody>
  <keyframe><key qpos="0 0 {0} 1 0 0 0" qvel="1.2 0.3 0 0 0 0"/></keyframe>
  <custom><text name="contactlaw:block-floor" data="geom1=block geom2=floor
    law=zhiying-qishao restitution=0.3 stiffness=1e7 friction=coulomb mu=0.2"/></custom>
</mujoco>)",
                     0.03 - depth);
}

// A ball (radius 0.1 m, mass `mass` kg) with its centre at `height` m above a
// floor plane (default: 0.1 mm from touching), moving down at `speed` m/s,
// gravity off unless asked: the 1-D impact of the closed forms.
inline std::string DropXml(std::string_view tag_data, double speed,
                           std::string_view integrator = "Euler", double timestep = 1e-5,
                           bool gravity = false, double mass = 1.0, double height = 0.1001) {
  return fmt::format(R"(
<mujoco>
  <option timestep="{timestep}" integrator="{integrator}" gravity="0 0 {g}"/>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body name="ball" pos="0 0 {height}">
      <freejoint/>
      <inertial pos="0 0 0" mass="{mass}" diaginertia="0.004 0.004 0.004"/>
      <geom name="ball" type="sphere" size="0.1"/>
    </body>
  </worldbody>
  <keyframe><key qvel="0 0 -{speed} 0 0 0"/></keyframe>
  <custom><text name="contactlaw:ball-floor" data="geom1=ball geom2=floor {tag}"/></custom>
</mujoco>)",
                     fmt::arg("timestep", timestep), fmt::arg("integrator", integrator),
                     fmt::arg("g", gravity ? -9.81 : 0.0), fmt::arg("mass", mass),
                     fmt::arg("speed", speed), fmt::arg("tag", tag_data),
                     fmt::arg("height", height));
}

// Steps sim until its first contact episode closes (or max_time): the episode.
inline Episode FirstImpact(Simulation& sim, double max_time = 0.5) {
  while (sim.time() < max_time) {
    sim.Step();
    const std::vector<Episode>& impacts = sim.contacts().impacts();
    if (!impacts.empty() && !impacts[0].open) return impacts[0];
  }
  ADD_FAILURE() << "no closed contact episode within " << max_time << " s";
  return Episode{};
}

// Steps sim `steps` times and returns the largest rise of its mechanical
// energy (kinetic, potential, the laws' springs) from one step to the next,
// J; a divergence fails the test and returns infinity.
inline double WorstMechanicalRise(Simulation& sim, int steps) {
  double previous = 0, worst = -1;
  for (int step = 0; step < steps; ++step) {
    sim.Step();
    if (sim.contacts().divergence()) {
      ADD_FAILURE() << "diverged at step " << step;
      return std::numeric_limits<double>::infinity();
    }
    mj_forward(sim.model(), sim.data());
    const EnergyLedger e = sim.Energy();
    const double mechanical = e.kinetic + e.potential + e.elastic;
    if (step > 0) worst = std::max(worst, mechanical - previous);
    previous = mechanical;
  }
  return worst;
}

}  // namespace contactlaws::testing

#endif  // CONTACTLAWS_TESTS_MUJOCO_TEST_UTIL_H_
