// Copyright contactlaws authors.
//
// Run summaries computed by hand.

#include "sim/summary.h"

#include <vector>

#include <gtest/gtest.h>

namespace contactlaws {
namespace {


// An impact of pair p from t0 to t1 (open when t1 < 0).
Episode Impact(int pair, double t0, double t1, double depth = 1e-3, double force = 1e3) {
  Episode i;
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
  const std::vector<Episode> impacts = {Impact(0, 0.1, 0.2, 2e-3, 5e3),
                                       Impact(0, 0.5, 0.65, 3e-3, 4e3),
                                       Impact(0, 0.7, 0.75), Impact(0, 0.8, -1)};
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
  EXPECT_FALSE(Summarize({Impact(0, 0.1, 0.2), Impact(0, 0.5, 0.6)}, 2.0).time_to_rest);
  // a first episode still open: no post-restitution, no duration; resting from t = 0
  const RunSummary resting = Summarize({Impact(0, 0.0, -1)}, 1.0);
  EXPECT_FALSE(resting.restitution_post);
  EXPECT_FALSE(resting.contact_duration);
  EXPECT_EQ(resting.time_to_rest, 0.0);
  // bodies placed overlapping, pushed apart at t = 0 without approaching:
  // no rebound to measure; the first impact after it is the first
  Episode pushed_apart = Impact(0, 0.0, 0.004);
  pushed_apart.impact_velocity = 0;
  pushed_apart.separation_velocity = 4.1;
  const RunSummary after = Summarize({pushed_apart, Impact(0, 0.3, 0.31)}, 1.0);
  EXPECT_EQ(after.impacts, 2);
  EXPECT_EQ(after.restitution_post, 0.75);
  EXPECT_EQ(after.impact_velocity, 2.0);
  EXPECT_FALSE(Summarize({pushed_apart}, 1.0).restitution_post);
  // a contact placed touching that sank into its spring at 6 mm/s and was
  // lifted at 25 mm/s by a push (SettlingImpacts): no impact; the first
  // impact after it is the first
  Episode settled = Impact(0, 0.0, 0.0216);
  settled.impact_velocity = 0;
  settled.max_approach_velocity = 0.006;
  settled.separation_velocity = 0.025;
  const RunSummary landing = Summarize({settled, Impact(0, 0.3, 0.31)}, 1.0, {1, 0});
  EXPECT_EQ(landing.restitution_post, 0.75);
  EXPECT_NEAR(*Summarize({settled, Impact(0, 0.3, 0.31)}, 1.0).restitution_post, 25.0 / 6, 1e-12)
      << "without the flags, its lift-off against its sinking";
  // no contact at all
  const RunSummary none = Summarize({}, 1.0);
  EXPECT_EQ(none.impacts, 0);
  EXPECT_FALSE(none.time_to_rest);
  EXPECT_FALSE(none.impact_velocity);
}

TEST(SummaryTest, EveryPairMustRestAndTheLatestDecides) {
  std::vector<Episode> impacts = {Impact(0, 0.1, 0.2), Impact(1, 0.15, 0.25),
                                 Impact(0, 0.4, -1), Impact(1, 0.6, -1)};
  EXPECT_EQ(Summarize(impacts, 2.0).time_to_rest, 0.6);
  impacts.push_back(Impact(2, 0.5, 0.55));  // a third pair that touched and left
  EXPECT_FALSE(Summarize(impacts, 2.0).time_to_rest);
}

}  // namespace
}  // namespace contactlaws
