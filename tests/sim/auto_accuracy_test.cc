// Copyright contactlaws authors.
//
// --accuracy TOL: the error the auto timestep delivers on the paper's sweep
// (mjcf/bouncing_ball.xml, the paper's five laws, e = 0.1 ... 1.0) stays
// below TOL in the rebound, the peak force and the contact duration, against
// the independent integration of the drop (drop_reference.h) at 1/20000 of
// the contact, converged far below the smallest TOL.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "contactlaws/contactlaws.h"
#include "sim/drop_reference.h"

namespace contactlaws {
namespace {

using testing::Drop;
using testing::IntegrateDrop;
using testing::Reference;
using testing::SweepFirstImpact;

struct Errors {
  double rebound = 0, force = 0, duration = 0;
  long steps = 0;
};

double Relative(double value, double reference) {
  return std::abs(value - reference) / std::abs(reference);
}

// The largest relative errors of the sweep at one accuracy.
Errors SweepErrors(const Scene& scene, double accuracy) {
  const Drop drop;
  Errors worst;
  AutoTimestepOptions options;
  options.accuracy = accuracy;
  for (LawId law : testing::kPaperLaws) {
    for (double e : testing::kPaperSweep) {
      const Reference r = IntegrateDrop(drop, law, e);
      long steps = 0;
      const Episode i = SweepFirstImpact(scene, law, e, std::nullopt, options, &steps);
      const std::string what = fmt::format("{} e = {} accuracy {}", LawName(law), e, accuracy);
      const double rebound = Relative(i.restitution_post(), r.restitution_post);
      const double force = Relative(i.max_force, r.max_force);
      const double duration = Relative(i.time_separation - i.time_contact, r.contact_duration);
      EXPECT_LT(rebound, accuracy) << what;
      EXPECT_LT(force, accuracy) << what;
      EXPECT_LT(duration, accuracy) << what;
      worst.rebound = std::max(worst.rebound, rebound);
      worst.force = std::max(worst.force, force);
      worst.duration = std::max(worst.duration, duration);
      worst.steps += steps;
    }
  }
  return worst;
}

TEST(AutoAccuracyTest, TheSweepIsWithinTheAccuracyAskedFor) {
  const Scene scene(std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf/bouncing_ball.xml");
  for (double accuracy : {1e-3, 1e-4, 1e-5}) {
    const Errors e = SweepErrors(scene, accuracy);
    std::printf("accuracy %.0e: largest relative error: rebound %.2e, peak force %.2e, "
                "duration %.2e; %ld steps for the 50 runs\n",
                accuracy, e.rebound, e.force, e.duration, e.steps);
  }
}

}  // namespace
}  // namespace contactlaws
