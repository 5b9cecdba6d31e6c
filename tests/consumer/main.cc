// Copyright contactlaws authors.
//
// A consumer of the installed library (find_package(contactlaws)): one ball
// falls on a plane under the Hunt-Crossley law (e = 0.8) and must rebound with
// the law's restitution. Exits 0 when e_post is in (0.7, 0.95) (closed form
// ~0.833), 1 otherwise.

#include <cstdio>
#include <exception>
#include <utility>

#include <contactlaws/contactlaws.h>

namespace {

constexpr char kScene[] = R"(
<mujoco model="consumer">
  <option timestep="1e-5" gravity="0 0 0"/>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body name="ball" pos="0 0 0.1005">
      <freejoint name="ball"/>
      <inertial pos="0 0 0" mass="1" diaginertia="0.004 0.004 0.004"/>
      <geom name="ball" type="sphere" size="0.1"/>
    </body>
  </worldbody>
  <keyframe>
    <key qvel="0 0 -1 0 0 0"/>
  </keyframe>
  <custom>
    <text name="contactlaw:ball-floor"
          data="geom1=ball geom2=floor law=hunt-crossley restitution=0.8 stiffness=1e7"/>
  </custom>
</mujoco>
)";

}  // namespace

int main() {
  try {
    contactlaws::Simulation sim(contactlaws::LoadModelString(kScene, "consumer.xml"),
                                "consumer.xml");
    const auto& impacts = sim.contacts().impacts();
    while (sim.time() < 0.2 && (impacts.empty() || impacts[0].open)) sim.Step();
    if (impacts.empty() || impacts[0].open) {
      std::fprintf(stderr, "consumer: no closed impact after %g s\n", sim.time());
      return 1;
    }
    const double e_post = impacts[0].restitution_post();
    std::printf("consumer: hunt-crossley e=0.8 rebounds with e_post=%.4f\n", e_post);
    return e_post > 0.7 && e_post < 0.95 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
}
