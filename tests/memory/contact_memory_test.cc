// Copyright contactlaws authors.
//
// Per-contact memory on its own (no MuJoCo): episodes opened, advanced and
// closed, and the dissipation ledger, against values worked by hand.

#include "contactlaws/contact_memory.h"

#include <vector>

#include <gtest/gtest.h>

namespace contactlaws {
namespace {

// Times and depths below are sums of a few binary-exact numbers: the
// bookkeeping must reproduce them to rounding.
constexpr double kRoundoff = 1e-15;

PointEvaluation Point(int slot, int tag, double depth, double rate, double force,
                      bool touch = false) {
  PointEvaluation e;
  e.pair = slot;  // one point per pair here
  e.tag = tag;
  e.slot = slot;
  e.touch = touch;
  e.depth = depth;
  e.depth_rate = rate;
  e.force = force;
  e.pos[2] = -depth;
  e.normal[2] = 1;
  return e;
}

TEST(EpisodeLogTest, AnEpisodeOpensAdvancesAndCloses) {
  EpisodeLog log(/*slots=*/2, /*tags=*/1);
  // first seen at t = 1 at depth 1e-3, rate 1 m/s, having touched at 3 m/s:
  // the depth was reached at the mean rate 2 m/s, so 0.5 ms earlier
  PointEvaluation touch = Point(0, 0, 1e-3, 1.0, 10.0, true);
  touch.touch_velocity = 3.0;
  log.Commit(1.0, {touch});
  ASSERT_EQ(log.impacts().size(), 1u);
  EXPECT_EQ(log.OpenEpisode(0), 0);
  EXPECT_EQ(log.OpenEpisode(1), -1);
  EXPECT_EQ(log.impacts()[0].impact_velocity, 3.0);
  EXPECT_NEAR(log.impacts()[0].time_contact, 1.0 - 0.5e-3, kRoundoff);
  EXPECT_EQ(log.impacts()[0].index, 1);

  // deeper, then shallower: the maxima stay
  log.Commit(2.0, {Point(0, 0, 4e-3, 0.5, 40.0)});
  log.Commit(3.0, {Point(0, 0, 2e-3, -2.0, 20.0)});
  log.CloseVanished([](int, const double*, const double*, double) -> double {
    ADD_FAILURE() << "nothing vanished";
    return 0;
  });
  EXPECT_TRUE(log.impacts()[0].open);
  EXPECT_EQ(log.impacts()[0].max_depth, 4e-3);
  EXPECT_EQ(log.impacts()[0].max_force, 40.0);

  // gone at the next commit: closed with the speed the caller gives, at the
  // point and normal last seen; separation extrapolated at the mean of the
  // last rate (2 m/s apart) and that speed (2 m/s): 2e-3 / 2 = 1 ms later
  log.Commit(4.0, {});
  int calls = 0;
  log.CloseVanished([&](int pair, const double pos[3], const double normal[3], double last_rate) {
    ++calls;
    EXPECT_EQ(pair, 0);
    EXPECT_EQ(pos[2], -2e-3);
    EXPECT_EQ(normal[2], 1.0);
    EXPECT_EQ(last_rate, -2.0);
    return 2.0;
  });
  EXPECT_EQ(calls, 1);
  const Impact& impact = log.impacts()[0];
  EXPECT_FALSE(impact.open);
  EXPECT_EQ(impact.separation_velocity, 2.0);
  EXPECT_NEAR(impact.time_separation, 3.0 + 1e-3, kRoundoff);
  EXPECT_NEAR(impact.restitution_post(), 2.0 / 3.0, kRoundoff);
  EXPECT_EQ(log.OpenEpisode(0), -1);
}

TEST(EpisodeLogTest, EpisodesAreCountedPerTagAndClosedOneByOne) {
  EpisodeLog log(/*slots=*/3, /*tags=*/2);
  log.Commit(0.0, {Point(0, 0, 1e-3, 1, 1, true), Point(1, 1, 1e-3, 1, 1, true),
                   Point(2, 1, 1e-3, 1, 1, true)});
  EXPECT_EQ(log.impacts()[0].index, 1);
  EXPECT_EQ(log.impacts()[1].index, 1);
  EXPECT_EQ(log.impacts()[2].index, 2);
  // slot 1 leaves; 0 and 2 stay
  log.Commit(1.0, {Point(0, 0, 1e-3, 0, 1), Point(2, 1, 1e-3, 0, 1)});
  log.CloseVanished([](int, const double*, const double*, double) { return 1.0; });
  EXPECT_TRUE(log.impacts()[0].open);
  EXPECT_FALSE(log.impacts()[1].open);
  EXPECT_TRUE(log.impacts()[2].open);
  // slot 1 touches again: a new episode, the tag's third
  log.Commit(2.0, {Point(0, 0, 1e-3, 0, 1), Point(1, 1, 1e-3, 1, 1, true),
                   Point(2, 1, 1e-3, 0, 1)});
  ASSERT_EQ(log.impacts().size(), 4u);
  EXPECT_EQ(log.impacts()[3].index, 3);
  EXPECT_EQ(log.OpenEpisode(1), 3);

  log.Reset();
  EXPECT_TRUE(log.impacts().empty());
  EXPECT_EQ(log.OpenEpisode(0), -1);
  log.Commit(3.0, {Point(1, 1, 1e-3, 1, 1, true)});
  EXPECT_EQ(log.impacts()[0].index, 1);
}

TEST(DissipationLedgerTest, TrapezoidOfThePower) {
  DissipationLedger ledger;
  PointEvaluation p = Point(0, 0, 1e-3, 1, 1);
  p.dissipated_power = 4.0;  // W
  // the first commit only starts the integral
  ledger.Commit(0.0, {p});
  EXPECT_EQ(ledger.Dissipated(0.0, {p}), 0.0);
  ledger.Commit(0.5, {p});
  ledger.Commit(1.0, {p});
  EXPECT_NEAR(ledger.Dissipated(1.0, {p}), 4.0, kRoundoff);
  // up to a later evaluation: the trapezoid to it, power 4 W -> 8 W
  PointEvaluation later = p;
  later.dissipated_power = 8.0;
  EXPECT_NEAR(ledger.Dissipated(1.5, {later}), 4.0 + 0.5 * (4.0 + 8.0) * 0.5, kRoundoff);
  ledger.Reset();
  EXPECT_EQ(ledger.Dissipated(2.0, {p}), 0.0);
}

TEST(DissipationLedgerTest, ATouchDissipatesFromItsTouchNotFromTheLastCommit) {
  DissipationLedger ledger;
  ledger.Commit(0.0, {});
  // a point touched at 0.75 (depth 0.25 m at mean rate 1 m/s, seen at t = 1)
  // with 6 W at the touch and 2 W at t = 1: 0.5 (6 + 2) 0.25 = 1 J
  PointEvaluation touch = Point(0, 0, 0.25, 1.0, 1, true);
  touch.touch_velocity = 1.0;
  touch.touch_power = 6.0;
  touch.dissipated_power = 2.0;
  ledger.Commit(1.0, {touch});
  EXPECT_NEAR(ledger.Dissipated(1.0, {touch}), 1.0, kRoundoff);
}

}  // namespace
}  // namespace contactlaws
