// Copyright contactlaws authors.
//
// The summaries' intervals against distributions whose answers are known.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "contactlaws/contactlaws.h"

namespace contactlaws {
namespace {

std::vector<double> Normal(int n, unsigned seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> v(n);
  for (double& x : v) x = normal(random);
  return v;
}

TEST(StatisticsTest, QuantilesInterpolateBetweenOrderStatistics) {
  const Distribution d = Distribute({4, 1, 3, 2, 5});
  EXPECT_DOUBLE_EQ(d.mean, 3);
  EXPECT_DOUBLE_EQ(d.median, 3);
  EXPECT_DOUBLE_EQ(d.p90, 4.6);  // 0.9 x 4 = 3.6: 4 + 0.6 (5 - 4)
  EXPECT_DOUBLE_EQ(Quantile({1, 2}, 0.5), 1.5);
}

// The percentile interval of the mean of n N(0, 1) draws: about
// +-1.96 / sqrt(n); of the median, sqrt(pi / 2) times wider (the median's
// asymptotic variance, pi sigma^2 / 2n).
TEST(StatisticsTest, IntervalsHaveTheWidthsOfTheNormalTheory) {
  constexpr int kN = 400;
  const Summary s = Summarize(Normal(kN, 5), 9);
  const double half = 1.96 / std::sqrt(kN);
  // a bootstrap's width is itself a random number: 15% of it
  constexpr double kWidthTolerance = 0.15;
  EXPECT_NEAR((s.mean.hi - s.mean.lo) / 2, half, kWidthTolerance * half);
  EXPECT_NEAR((s.median.hi - s.median.lo) / 2, half * std::sqrt(M_PI / 2),
              kWidthTolerance * 1.5 * half * std::sqrt(M_PI / 2));  // the median's jumps
  EXPECT_TRUE(s.mean.Contains(s.value.mean));
  EXPECT_TRUE(s.median.Contains(s.value.median));
}

// Over many samples, the 95% intervals contain the true mean (0) and the
// true median of an exponential (ln 2) about 95% of the time.
TEST(StatisticsTest, IntervalsCoverTheTruthNinetyFivePercentOfTheTime) {
  constexpr int kSamples = 200, kN = 100;
  int mean_covered = 0, median_covered = 0;
  std::mt19937_64 random(17);
  std::exponential_distribution<double> exponential(1.0);
  for (int i = 0; i < kSamples; ++i) {
    mean_covered += Summarize(Normal(kN, 100 + i), i, 500).mean.Contains(0.0);
    std::vector<double> e(kN);
    for (double& x : e) x = exponential(random);
    median_covered += Summarize(e, i, 500).median.Contains(std::log(2.0));
  }
  // 200 trials of p = 0.95: a standard deviation of 0.015; 3 of them
  constexpr double kCoverageTolerance = 0.046;
  EXPECT_NEAR(mean_covered / double(kSamples), 0.95, kCoverageTolerance);
  EXPECT_NEAR(median_covered / double(kSamples), 0.95, kCoverageTolerance);
}

TEST(StatisticsTest, TheSameSeedGivesTheSameIntervals) {
  const std::vector<double> v = Normal(50, 3);
  const Summary a = Summarize(v, 4), b = Summarize(v, 4), c = Summarize(v, 5);
  EXPECT_EQ(a.mean.lo, b.mean.lo);
  EXPECT_EQ(a.median.hi, b.median.hi);
  EXPECT_NE(a.mean.lo, c.mean.lo);
}

TEST(StatisticsTest, PairedDifferencesTellAShiftFromNoise) {
  const std::vector<double> b = Normal(200, 1);
  std::vector<double> shifted = b, noisy = b;
  const std::vector<double> noise = Normal(200, 2);
  for (size_t i = 0; i < b.size(); ++i) {
    shifted[i] += 0.05 + 0.1 * noise[i];  // 0.05 against a 0.007 standard error
    noisy[i] += 0.1 * noise[i];
  }
  const PairedDifference s = ComparePaired(shifted, b, 1);
  EXPECT_TRUE(s.Distinguishable());
  EXPECT_GT(s.interval.lo, 0);
  EXPECT_NEAR(s.mean, 0.05 + 0.1 * Distribute(noise).mean, 1e-12);
  // the shift alone is invisible to an unpaired look: b's own spread is 1
  EXPECT_TRUE(Summarize(shifted, 1).mean.Contains(Distribute(b).mean));
  const PairedDifference n = ComparePaired(noisy, b, 1);
  EXPECT_TRUE(n.interval.Contains(n.mean));
  EXPECT_FALSE(ComparePaired(b, b, 1).Distinguishable());
  EXPECT_THROW(ComparePaired(b, {1.0}, 1), Error);
}

TEST(StatisticsTest, ATrimmedMeanLeavesTheLargestOut) {
  // floor(0.25 * 4) = 1 value left out: the largest, wherever it stands
  EXPECT_EQ(TrimmedMean({100, 1, 3, 2}, 0.25), 2.0);
  EXPECT_EQ(TrimmedMean({100, 1, 3, 2}, 0.2), 26.5);  // floor(0.8) = 0: the mean
  EXPECT_EQ(TrimmedMean({}, 0.25), 0.0);
  EXPECT_THROW(TrimmedMean({1, 2}, 0.5), Error);
  EXPECT_THROW(TrimmedMean({1, 2}, -0.1), Error);
  // one outlier in 200 moves the mean by 0.25 and the 10% trimmed mean by
  // less than its own interval's half-width
  std::vector<double> values = Normal(200, 3);
  const double clean = TrimmedMean(values, 0.1);
  values[17] = 50;
  const Estimate e = SummarizeTrimmed(values, 0.1, 4);
  EXPECT_TRUE(e.interval.Contains(e.value));
  EXPECT_LT(std::abs(e.value - clean), 0.5 * (e.interval.hi - e.interval.lo));
  EXPECT_GT(Distribute(values).mean - Distribute(Normal(200, 3)).mean, 0.2);
  // trim 0: ComparePaired's numbers to the bit
  const std::vector<double> b = Normal(200, 1);
  const PairedDifference p = ComparePairedTrimmed(values, b, 0, 2);
  const PairedDifference q = ComparePaired(values, b, 2);
  EXPECT_EQ(p.mean, q.mean);
  EXPECT_EQ(p.interval.lo, q.interval.lo);
  EXPECT_EQ(p.interval.hi, q.interval.hi);
}

TEST(StatisticsTest, FoldsAreBalancedSeededAndRefusedOutOfRange) {
  const std::vector<int> f = AssignFolds(11, 3, 7);
  std::vector<int> size(3);
  for (int k : f) ++size.at(k);
  EXPECT_EQ(size, (std::vector<int>{4, 4, 3}));
  EXPECT_EQ(f, AssignFolds(11, 3, 7));
  EXPECT_NE(f, AssignFolds(11, 3, 8));
  EXPECT_THROW(AssignFolds(11, 1, 7), Error);
  EXPECT_THROW(AssignFolds(11, 12, 7), Error);
  EXPECT_EQ(AssignFolds(4, 4, 1).size(), 4u);
}

}  // namespace
}  // namespace contactlaws
