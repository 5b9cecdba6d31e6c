// Copyright contactlaws authors.
//
// Summaries of per-trajectory scores that a reader can weigh: the mean,
// median and 90th percentile, each mean and median with a 95% percentile
// bootstrap interval (Efron & Tibshirani 1993, ch. 13) over trajectories;
// paired differences of two score arrays with their interval; the folds of
// a cross-validation. Pure functions of the arrays and a seed: the same
// numbers to the bit whatever the threads or processes that made the arrays.

#ifndef CONTACTLAWS_STATISTICS_H_
#define CONTACTLAWS_STATISTICS_H_

#include <cstdint>
#include <vector>

namespace contactlaws {

// Mean, median and 90th percentile (linear interpolation between order
// statistics) of values; zeros when empty.
struct Distribution {
  double mean = 0, median = 0, p90 = 0;
};
Distribution Distribute(std::vector<double> values);

// The p-quantile of sorted values (linear interpolation between order
// statistics, p in [0, 1]); 0 when empty.
double Quantile(const std::vector<double>& sorted, double p);

struct Interval {
  double lo = 0, hi = 0;
  bool Contains(double x) const { return lo <= x && x <= hi; }
};

// 2000 resamples: the 2.5% and 97.5% points of the resampled statistic then
// move by about 1% of the interval's width between seeds (Efron &
// Tibshirani's rule: 1000-2000 for percentile intervals).
inline constexpr int kBootstrapResamples = 2000;
inline constexpr double kConfidence = 0.95;

// Distribute's numbers, and an interval for the mean and the median: the
// percentile bootstrap, `resamples` resamples of the values with replacement
// drawn from seed (the same seed and count, the same resamples: two arrays
// of one length are resampled alike).
struct Summary {
  int count = 0;
  Distribution value;
  Interval mean, median;
};
Summary Summarize(const std::vector<double>& values, uint64_t seed,
                  int resamples = kBootstrapResamples);

// The mean of a[i] - b[i] and its percentile bootstrap interval (pairs
// resampled together). An interval that contains 0: the arrays' means are
// not told apart at that confidence.
struct PairedDifference {
  double mean = 0;
  Interval interval;
  bool Distinguishable() const { return !interval.Contains(0.0); }
};
// Throws Error when a and b differ in length.
PairedDifference ComparePaired(const std::vector<double>& a, const std::vector<double>& b,
                               uint64_t seed, int resamples = kBootstrapResamples);

// The mean of values without the floor(trim n) largest (trim in [0, 0.5)),
// summed smallest first: a robust mean that a few outliers cannot carry
// (a cube toss that lands on another face scores about 50 times a typical
// one). Throws Error for a trim outside [0, 0.5).
double TrimmedMean(std::vector<double> values, double trim);

// TrimmedMean of values and its percentile bootstrap interval, from the
// resamples Summarize draws with the same seed and count.
struct Estimate {
  double value = 0;
  Interval interval;
};
Estimate SummarizeTrimmed(const std::vector<double>& values, double trim, uint64_t seed,
                          int resamples = kBootstrapResamples);

// ComparePaired for trimmed means: TrimmedMean(a) - TrimmedMean(b), and the
// interval of that difference over resampled pairs (trim 0: ComparePaired).
PairedDifference ComparePairedTrimmed(const std::vector<double>& a, const std::vector<double>& b,
                                      double trim, uint64_t seed,
                                      int resamples = kBootstrapResamples);

// The fold (0 .. folds - 1) of each of count items: a seeded shuffle dealt
// in turn, so fold sizes differ by at most one. Throws Error unless
// 2 <= folds <= count.
std::vector<int> AssignFolds(int count, int folds, uint64_t seed);

}  // namespace contactlaws

#endif  // CONTACTLAWS_STATISTICS_H_
