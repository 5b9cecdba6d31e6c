// Copyright contactlaws authors.
//
// Per-contact memory on its own (no MuJoCo): episodes opened, advanced and
// closed, and the dissipation ledger, against values worked by hand.

#include "memory/contact_memory.h"

#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

namespace contactlaws {
namespace {

// Times and depths below are sums of a few binary-exact numbers: the
// bookkeeping must reproduce them to rounding.
constexpr double kRoundoff = 1e-15;

// A point of pair (its tag) at depth, rate, force; episode: the open episode
// it continues, -1 for a touch.
PointEvaluation Point(int pair, int tag, double depth, double rate, double force,
                      int episode = -1) {
  PointEvaluation e;
  e.pair = pair;
  e.tag = tag;
  e.episode = episode;
  e.touch = episode < 0;
  e.depth = depth;
  e.depth_rate = rate;
  e.force = force;
  e.pos[2] = -depth;
  e.normal[2] = 1;
  return e;
}

TEST(PeakForceTest, AParabolaSampledUnevenlyGivesItsVertex) {
  // F = 10 - 4 (t - 1.3)^2 sampled at t = 0.5, 1, 2 (largest at t = 1):
  // the peak between the samples is 10 N; a sample alone gives 9.64 N
  PeakForce peak;
  for (double t : {0.5, 1.0, 2.0}) peak.Add(t, 10 - 4 * (t - 1.3) * (t - 1.3));
  EXPECT_NEAR(peak.peak(), 10.0, 10 * kRoundoff);  // 10 N: relative roundoff
  // a rising force has no vertex yet: the largest sample
  PeakForce rising;
  for (double t : {0.0, 1.0, 2.0}) rising.Add(t, t * t);
  EXPECT_EQ(rising.peak(), 4.0);
}

TEST(PeakForceTest, ASliverBesideALongIntervalGivesNoVertex) {
  // contact steps' sub-samples: 752 N twice 13 us apart, then 711 N 39 ns
  // later (a sub-step cut short at the step's end). The parabola through the
  // three would put a vertex of about 752 + 41 13e-6 / (4 39e-9) = 4,170 N
  // between the first two, from the sliver's slope alone; the samples are
  // 1:333 apart, beyond PeakForce::kPeakSpacing: the largest sample
  PeakForce peak;
  peak.Add(0.0, 752.0);
  peak.Add(13e-6, 752.0);
  peak.Add(13.039e-6, 711.0);
  EXPECT_EQ(peak.peak(), 752.0);
}

TEST(EpisodeLogTest, AnEpisodeOpensAdvancesAndCloses) {
  EpisodeLog log(/*points_per_pair=*/{1, 1}, /*tags=*/1);
  // first seen at t = 1 at depth 1e-3, rate 1 m/s, having touched at 3 m/s:
  // the depth was reached at the mean rate 2 m/s, so 0.5 ms earlier
  PointEvaluation touch = Point(0, 0, 1e-3, 1.0, 10.0);
  touch.touch_velocity = 3.0;
  log.Commit(1.0, {touch});
  ASSERT_EQ(log.episodes().size(), 1u);
  EXPECT_EQ(log.OpenEpisodes(0), std::vector<int>{0});
  EXPECT_TRUE(log.OpenEpisodes(1).empty());
  EXPECT_EQ(log.episodes()[0].impact_velocity, 3.0);
  EXPECT_NEAR(log.episodes()[0].time_contact, 1.0 - 0.5e-3, kRoundoff);
  EXPECT_EQ(log.episodes()[0].index, 1);

  // deeper, then shallower: the maxima stay
  log.Commit(2.0, {Point(0, 0, 4e-3, 0.5, 40.0, 0)});
  log.Commit(3.0, {Point(0, 0, 2e-3, -2.0, 20.0, 0)});
  log.CloseVanished([](int, const double*, const double*, double) -> double {
    ADD_FAILURE() << "nothing vanished";
    return 0;
  });
  EXPECT_TRUE(log.episodes()[0].open);
  EXPECT_EQ(log.episodes()[0].max_depth, 4e-3);
  // the force peaks between the samples 10, 40, 20 N at t = 1, 2, 3: the
  // parabola through them, 10 + 30 (t - 1) - 25 (t - 1)(t - 2), has its
  // vertex at t = 2.1, 40.25 N (PeakForce)
  EXPECT_NEAR(log.episodes()[0].max_force, 40.25, 40 * kRoundoff);

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
  const Episode& impact = log.episodes()[0];
  EXPECT_FALSE(impact.open);
  EXPECT_EQ(impact.separation_velocity, 2.0);
  EXPECT_NEAR(impact.time_separation, 3.0 + 1e-3, kRoundoff);
  EXPECT_NEAR(impact.restitution_post(), 2.0 / 3.0, kRoundoff);
  EXPECT_TRUE(log.OpenEpisodes(0).empty());
  EXPECT_EQ(log.closed(), std::vector<int>{0});
}

TEST(EpisodeLogTest, EpisodesAreCountedPerTagAndClosedOneByOne) {
  EpisodeLog log(/*points_per_pair=*/{1, 1, 1}, /*tags=*/2);
  log.Commit(0.0, {Point(0, 0, 1e-3, 1, 1), Point(1, 1, 1e-3, 1, 1), Point(2, 1, 1e-3, 1, 1)});
  EXPECT_EQ(log.episodes()[0].index, 1);
  EXPECT_EQ(log.episodes()[1].index, 1);
  EXPECT_EQ(log.episodes()[2].index, 2);
  // pair 1 leaves; 0 and 2 stay
  log.Commit(1.0, {Point(0, 0, 1e-3, 0, 1, 0), Point(2, 1, 1e-3, 0, 1, 2)});
  log.CloseVanished([](int, const double*, const double*, double) { return 1.0; });
  EXPECT_TRUE(log.episodes()[0].open);
  EXPECT_FALSE(log.episodes()[1].open);
  EXPECT_TRUE(log.episodes()[2].open);
  // pair 1 touches again: a new episode, the tag's third
  log.Commit(2.0, {Point(0, 0, 1e-3, 0, 1, 0), Point(1, 1, 1e-3, 1, 1), Point(2, 1, 1e-3, 0, 1, 2)});
  ASSERT_EQ(log.episodes().size(), 4u);
  EXPECT_EQ(log.episodes()[3].index, 3);
  EXPECT_EQ(log.OpenEpisodes(1), std::vector<int>{3});

  log.Reset();
  EXPECT_TRUE(log.episodes().empty());
  EXPECT_TRUE(log.OpenEpisodes(0).empty());
  log.Commit(3.0, {Point(1, 1, 1e-3, 1, 1)});
  EXPECT_EQ(log.episodes()[0].index, 1);
}

// A point at (x, 0, 0) on body 0 and (x + shift, 0, 0) on body 1.
PointEvaluation At(double x, double shift, int episode = -1) {
  PointEvaluation e = Point(0, 0, 1e-3, 0, 1, episode);
  e.local[0][0] = x;
  e.local[1][0] = x + shift;
  return e;
}

// The open episodes log matches to points of pair 0, in their order.
std::vector<int> Match(const EpisodeLog& log, const std::vector<PointEvaluation>& points,
                       double tolerance) {
  std::vector<double> local;
  for (const PointEvaluation& e : points) {
    for (const int b : {0, 1}) local.insert(local.end(), e.local[b], e.local[b] + 3);
  }
  std::vector<int> episode(points.size());
  log.MatchOpenEpisodes(0, local.data(), static_cast<int>(points.size()), tolerance,
                        episode.data());
  return episode;
}

// Two corners of a box on the floor, listed in either order, sliding: each
// evaluation finds its own corner's episode, by where it sits on the box.
TEST(EpisodeLogTest, PointsAreMatchedByWhereTheySitOnTheBodies) {
  constexpr double kTolerance = 0.01;  // m
  EpisodeLog log(/*points_per_pair=*/{4}, /*tags=*/1);
  log.Commit(0.0, {At(-0.1, 0), At(0.1, 0)});
  ASSERT_EQ(log.OpenEpisodes(0), (std::vector<int>{0, 1}));

  // listed the other way round, slid 0.5 m along the floor: fixed on body 0;
  // each episode is taken once: a third point at the same corner is new
  const PointEvaluation right = At(0.1, 0.5);
  const PointEvaluation left = At(-0.1, 0.5);
  EXPECT_EQ(Match(log, {right, left}, kTolerance), (std::vector<int>{1, 0}));
  EXPECT_EQ(Match(log, {right, left, right}, kTolerance), (std::vector<int>{1, 0, -1}));
  // beyond the tolerance on both bodies: a new point
  EXPECT_EQ(Match(log, {At(0.0, 0.5)}, kTolerance), (std::vector<int>{-1}));
  // within it: the nearer episode
  EXPECT_EQ(Match(log, {At(0.095, 0.5)}, kTolerance), (std::vector<int>{1}));
}

// A face patch's point that appears beside a point in contact, within the
// tolerance of its episode and listed first, takes nothing from it: the
// episode goes to the nearer point. Taken by the first point listed, the
// point in contact was a touch at its depth, at the floor of v0 (box_stack.xml
// at 2 ms with contact steps: a Hunt-Crossley force of 41.7 N against 12.6 N,
// its friction spring at the cap storing 1.9e-3 J out of nothing).
TEST(EpisodeLogTest, ANewPointBesideOneInContactTakesNotItsEpisode) {
  constexpr double kTolerance = 0.01;  // m
  EpisodeLog log(/*points_per_pair=*/{4}, /*tags=*/1);
  log.Commit(0.0, {At(0.1, 0)});
  const PointEvaluation appearing = At(0.097, 0.5);  // 3 mm away
  const PointEvaluation kept = At(0.1, 0.5);
  EXPECT_EQ(Match(log, {appearing, kept}, kTolerance), (std::vector<int>{-1, 0}));
  EXPECT_EQ(Match(log, {kept, appearing}, kTolerance), (std::vector<int>{0, -1}));
}

// A pair whose narrowphase returns one point (MuJoCo's convex collider: a
// mesh face on a box face) has one contact, wherever its point moves: the
// collider puts it anywhere on the face from one step to the next, and a new
// episode found deep at a rate far above the floor of v0 turned the law's
// damping into a wall (a mesh cube landing on a box diverged).
TEST(EpisodeLogTest, APairOfOnePointKeepsItsEpisodeWhereverThePointMoves) {
  constexpr double kTolerance = 0.01;  // m
  EpisodeLog one(/*points_per_pair=*/{1}, /*tags=*/1);
  one.Commit(0.0, {At(-0.04, 0)});
  const PointEvaluation across = At(0.04, 0);  // 8 cm away on both bodies
  EXPECT_EQ(Match(one, {across}, kTolerance), (std::vector<int>{0}));
  EXPECT_EQ(Match(one, {across, across}, kTolerance), (std::vector<int>{0, -1}));  // taken once
  // a pair of several points: far away, it is another point
  EpisodeLog several(/*points_per_pair=*/{4}, /*tags=*/1);
  several.Commit(0.0, {At(-0.04, 0)});
  EXPECT_EQ(Match(several, {across}, kTolerance), (std::vector<int>{-1}));
  // no open episode: a touch
  EpisodeLog none(/*points_per_pair=*/{1}, /*tags=*/1);
  EXPECT_EQ(Match(none, {across}, kTolerance), (std::vector<int>{-1}));
}

TEST(ImpactLogTest, AnImpactRunsFromTheFirstTouchToTheLastPointLeaving) {
  EpisodeLog episodes(/*points_per_pair=*/{4}, /*tags=*/1);
  ImpactLog impacts(/*pairs=*/1, /*tags=*/1);
  auto commit = [&](double t, const std::vector<PointEvaluation>& points, double leaving) {
    episodes.Commit(t, points);
    episodes.CloseVanished([&](int, const double*, const double*, double) { return leaving; });
    impacts.Commit(t, points, episodes);
  };
  // a tilted box: one corner touches at 2 m/s, then a second at 1 m/s
  PointEvaluation a = At(-0.1, 0);
  a.touch_velocity = 2.0;
  a.depth_rate = 2.0;
  a.force = 5.0;
  commit(1.0, {a}, 0);
  ASSERT_EQ(impacts.impacts().size(), 1u);
  EXPECT_EQ(impacts.impacts()[0].impact_velocity, 2.0);
  EXPECT_NEAR(impacts.impacts()[0].time_contact, 1.0 - 1e-3 / 2.0, kRoundoff);
  a.episode = 0;
  a.touch = false;
  PointEvaluation b = At(0.1, 0);
  b.touch_velocity = 1.0;
  b.force = 7.0;
  b.depth = 3e-3;
  commit(2.0, {a, b}, 0);
  // the first corner leaves at 0.5 m/s, the second later at 0.8 m/s
  b.episode = 1;
  b.touch = false;
  commit(3.0, {b}, 0.5);
  EXPECT_TRUE(impacts.impacts()[0].open);
  commit(4.0, {}, 0.8);
  ASSERT_EQ(impacts.impacts().size(), 1u);
  const Episode& c = impacts.impacts()[0];
  EXPECT_FALSE(c.open);
  EXPECT_EQ(c.points, 2);
  // both corners at once, 12 N at t = 2 between 5 and 7 N: the vertex of
  // 5 + 7 (t - 1) - 6 (t - 1)(t - 2) at t = 2 + 1/12, 12 + 1/24 N
  EXPECT_NEAR(c.max_force, 12.0 + 1.0 / 24, 12 * kRoundoff);
  EXPECT_EQ(c.max_depth, 3e-3);
  EXPECT_EQ(c.impact_velocity, 2.0);      // the first touch
  EXPECT_EQ(c.separation_velocity, 0.8);  // the last to leave
  EXPECT_EQ(c.time_separation, episodes.episodes()[1].time_separation);
  EXPECT_EQ(c.index, 1);
  // the next touch of the pair is its second impact
  commit(5.0, {At(0, 0)}, 0);
  EXPECT_EQ(impacts.impacts().at(1).index, 2);
}

// Chained: compressed faster than the law's v0 at the touch. A contact that
// opened at rest and settles within the v0 floor (1e-3 m/s here) is not.
// Two cubes falling together touch at a relative rate of ~1e-21 m/s: the
// depth over the mean rate extrapolates far back. A touch is no earlier than
// the last commit, where the point was not in contact.
TEST(EpisodeLogTest, ATouchIsNoEarlierThanTheLastCommit) {
  EpisodeLog episodes(/*points_per_pair=*/{1}, /*tags=*/1);
  ImpactLog impacts(/*pairs=*/1, /*tags=*/1);
  episodes.Commit(0.1, {});
  impacts.Commit(0.1, {}, episodes);
  PointEvaluation slow = Point(0, 0, 1e-5, 0.08, 1.0);  // compressed at 0.08 m/s now
  slow.touch_velocity = 1e-21;  // touched at no rate at all
  episodes.Commit(0.1001, {slow});
  impacts.Commit(0.1001, {slow}, episodes);
  EXPECT_DOUBLE_EQ(episodes.episodes()[0].time_contact, 0.1);  // unbounded: 0.1001 - 2.5e-4
  EXPECT_DOUBLE_EQ(impacts.impacts()[0].time_contact, 0.1);
  // a rate that places it within the step is kept
  EXPECT_DOUBLE_EQ(TouchTime(Point(0, 0, 1e-6, 0.02, 1.0), 0.2, 0.1), 0.2 - 1e-6 / 0.01);
}

// A tumbling body lands a second corner faster than the first touched, in
// the same impact: no chain (a pair's impact was flagged for every
// tetrahedron, box and capsule dropped tumbling). A corner pushed after its
// own touch is one, whatever the others did.
TEST(ImpactLogTest, ASecondCornerLandingFasterIsNoChainAPushedOneIs) {
  EpisodeLog episodes(/*points_per_pair=*/{4}, /*tags=*/1);
  ImpactLog impacts(/*pairs=*/1, /*tags=*/1);
  auto commit = [&](double t, const std::vector<PointEvaluation>& points) {
    episodes.Commit(t, points);
    impacts.Commit(t, points, episodes);
  };
  auto corner = [](double x, int episode, double touch, double max_approach) {
    PointEvaluation e = At(x, 0, episode);
    e.touch_velocity = touch;
    e.impact_velocity = std::max(touch, max_approach);  // the law's v0, raised
    e.max_approach = max_approach;
    return e;
  };
  commit(1.0, {corner(-0.1, -1, 0.1, 0.1)});
  commit(2.0, {corner(-0.1, 0, 0.1, 0.1), corner(0.1, -1, 0.3, 0.3)});
  ASSERT_EQ(impacts.impacts().size(), 1u);
  const Episode& c = impacts.impacts()[0];
  EXPECT_EQ(c.impact_velocity, 0.1);         // the first touch
  EXPECT_EQ(c.max_approach_velocity, 0.3);   // the second corner's
  EXPECT_FALSE(c.chained());
  EXPECT_FALSE(episodes.episodes()[0].chained());
  EXPECT_FALSE(episodes.episodes()[1].chained());
  // the first corner compressed at 0.5 m/s, 5 x its touch: a push
  commit(3.0, {corner(-0.1, 0, 0.1, 0.5), corner(0.1, 1, 0.3, 0.3)});
  EXPECT_TRUE(episodes.episodes()[0].chained());
  EXPECT_TRUE(impacts.impacts()[0].chained());
}

// A contact there at the start (bodies placed touching) sinks into its
// spring: the first compression is its settling, no chain; a pulse that
// comes through later, faster than kChainFactor x the settling, is one.
TEST(EpisodeLogTest, AContactThereAtTheStartSettlesAPulseThroughItIsAChain) {
  EpisodeLog log(/*points_per_pair=*/{1}, /*tags=*/1);
  auto commit = [&](double t, double rate) {
    PointEvaluation e = Point(0, 0, 1e-6, rate, 1, t > 0 ? 0 : -1);
    e.at_start = t == 0;
    e.touch_velocity = t == 0 ? rate : 0.0;
    e.impact_velocity = 1e-3;  // the law's floor of v0
    e.max_approach = std::max(t > 0 ? log.MaxApproach(0) : rate, rate);
    log.Commit(t, {e});
  };
  commit(0.0, 0.0);
  double t = 0;
  for (const double rate : {0.05, 0.12, 0.04, -0.02, 0.03}) commit(++t, rate);
  const Episode& placed = log.episodes()[0];
  EXPECT_EQ(placed.settling_velocity, 0.12);  // its first compression's peak
  EXPECT_FALSE(placed.chained());
  commit(10.0, 0.23);  // below 2 x 0.12
  EXPECT_FALSE(log.episodes()[0].chained());
  commit(11.0, 0.5);  // a pulse
  EXPECT_TRUE(log.episodes()[0].chained());
  // touched during the run at the same rates: a chain from its first push
  EpisodeLog later(/*points_per_pair=*/{1}, /*tags=*/1);
  PointEvaluation touch = Point(0, 0, 1e-6, 0.0, 1);
  touch.impact_velocity = 1e-3;
  later.Commit(1.0, {touch});
  PointEvaluation pushed = Point(0, 0, 1e-6, 0.12, 1, 0);
  pushed.max_approach = 0.12;
  later.Commit(2.0, {pushed});
  EXPECT_TRUE(later.episodes()[0].chained());
}

TEST(ImpactTest, ChainedMeansCompressedFasterThanTheTouchsV0) {
  Episode settling;
  settling.impact_velocity = 0;
  settling.touch_v0 = 1e-3;  // the floor
  settling.max_approach_velocity = 4e-4;
  EXPECT_FALSE(settling.chained());
  Episode pulsed = settling;
  pulsed.max_approach_velocity = 0.5;  // a pulse came through
  EXPECT_TRUE(pulsed.chained());
  pulsed.separation_velocity = 0.4;
  EXPECT_DOUBLE_EQ(pulsed.restitution_post(), 0.8);  // against the pulse's rate
  Episode impact;  // an impact's rate only falls after its touch
  impact.impact_velocity = impact.touch_v0 = impact.max_approach_velocity = 2.0;
  EXPECT_FALSE(impact.chained());
  // gravity raised the paper's ball's rate after its touch: no chain
  impact.impact_velocity = impact.touch_v0 = 4.202142257;
  impact.max_approach_velocity = 4.20216232;
  EXPECT_FALSE(impact.chained());
  impact.max_approach_velocity = 2.01 * impact.impact_velocity;  // beyond kChainFactor
  EXPECT_TRUE(impact.chained());
}

TEST(DissipationLedgerTest, TrapezoidOfThePower) {
  DissipationLedger ledger;
  PointEvaluation p = Point(0, 0, 1e-3, 1, 1, /*episode=*/0);  // not a touch
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
  PointEvaluation touch = Point(0, 0, 0.25, 1.0, 1);
  touch.touch_velocity = 1.0;
  touch.touch_power = 6.0;
  touch.dissipated_power = 2.0;
  ledger.Commit(1.0, {touch});
  EXPECT_NEAR(ledger.Dissipated(1.0, {touch}), 1.0, kRoundoff);
}

TEST(DissipationLedgerTest, ADeferredQuadratureReplacesTheTrapezoidTheNextCommitCloses) {
  // an integrator took 3 J over [0, 1] where the ledger's trapezoid books
  // 0.5 (4 + 8) = 6 J: it defers 3 J less the trapezoid's start half (2 J)
  // and the end half at the next commit's power of the same episode
  DissipationLedger ledger;
  PointEvaluation p = Point(0, 0, 1e-3, 1, 1, /*episode=*/0);
  p.dissipated_power = 4.0;  // W
  ledger.Commit(0.0, {p});
  ledger.Defer(/*episode=*/0, 3.0 - 0.5 * 4.0, /*half_step=*/0.5);
  PointEvaluation end = p;
  end.dissipated_power = 8.0;
  ledger.Commit(1.0, {end});
  EXPECT_NEAR(ledger.Dissipated(1.0, {end}), 3.0, kRoundoff);
  // the next commits book their trapezoids alone
  ledger.Commit(2.0, {end});
  EXPECT_NEAR(ledger.Dissipated(2.0, {end}), 3.0 + 8.0, kRoundoff);
  // a point gone at the next commit (it separated): its end half is 0
  ledger.Reset();
  ledger.Commit(0.0, {p});
  ledger.Defer(0, 1.0 - 0.5 * 4.0, 0.5);
  ledger.Commit(1.0, {});
  EXPECT_NEAR(ledger.Dissipated(1.0, {}), 1.0, kRoundoff);
}

}  // namespace
}  // namespace contactlaws
