// Copyright contactlaws authors.

#include "contactlaws/replay.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <fmt/format.h>

#include "contactlaws/contact_model.h"

namespace contactlaws {

namespace {

// SplitMix64 (Steele, Lea & Flood 2014): a fixed, portable sequence per seed,
// where the standard library's distributions may differ between libraries.
class Random {
 public:
  explicit Random(uint64_t seed) : state_(seed) {}
  uint64_t Next() {
    uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  // uniform in [0, n): the remainder's bias, n / 2^64, is nil here
  size_t Below(size_t n) { return static_cast<size_t>(Next() % n); }

 private:
  uint64_t state_;
};

double Mean(const std::vector<double>& values) {
  double sum = 0;
  for (double v : values) sum += v;  // in order: the same bits every time
  return values.empty() ? 0.0 : sum / values.size();
}

// The interval of the resampled statistics' (1 - kConfidence) / 2 and
// (1 + kConfidence) / 2 points.
Interval Percentiles(std::vector<double> statistics) {
  std::sort(statistics.begin(), statistics.end());
  return {Quantile(statistics, (1 - kConfidence) / 2), Quantile(statistics, (1 + kConfidence) / 2)};
}

void CheckResamples(int resamples) {
  if (resamples < 1) throw Error(fmt::format("bootstrap: {} resamples: must be >= 1", resamples));
}

}  // namespace

double Quantile(const std::vector<double>& sorted, double p) {
  if (sorted.empty()) return 0;
  const double at = p * (sorted.size() - 1);
  const size_t lo = static_cast<size_t>(std::floor(at));
  const size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (at - lo) * (sorted[hi] - sorted[lo]);
}

Distribution Distribute(std::vector<double> values) {
  Distribution d;
  if (values.empty()) return d;
  d.mean = Mean(values);
  std::sort(values.begin(), values.end());
  d.median = Quantile(values, 0.5);
  d.p90 = Quantile(values, 0.9);
  return d;
}

Summary Summarize(const std::vector<double>& values, uint64_t seed, int resamples) {
  CheckResamples(resamples);
  Summary s;
  s.count = static_cast<int>(values.size());
  s.value = Distribute(values);
  if (values.empty()) return s;
  Random random(seed);
  std::vector<double> means(resamples), medians(resamples), resample(values.size());
  for (int r = 0; r < resamples; ++r) {
    for (double& v : resample) v = values[random.Below(values.size())];
    means[r] = Mean(resample);
    std::sort(resample.begin(), resample.end());
    medians[r] = Quantile(resample, 0.5);
  }
  s.mean = Percentiles(std::move(means));
  s.median = Percentiles(std::move(medians));
  return s;
}

PairedDifference ComparePaired(const std::vector<double>& a, const std::vector<double>& b,
                               uint64_t seed, int resamples) {
  CheckResamples(resamples);
  if (a.size() != b.size()) {
    throw Error(fmt::format("paired comparison: {} values against {}: the pairs must be the "
                            "same trajectories",
                            a.size(), b.size()));
  }
  std::vector<double> difference(a.size());
  for (size_t i = 0; i < a.size(); ++i) difference[i] = a[i] - b[i];
  PairedDifference d;
  d.mean = Mean(difference);
  if (difference.empty()) return d;
  Random random(seed);
  std::vector<double> means(resamples), resample(difference.size());
  for (int r = 0; r < resamples; ++r) {
    for (double& v : resample) v = difference[random.Below(difference.size())];
    means[r] = Mean(resample);
  }
  d.interval = Percentiles(std::move(means));
  return d;
}

double TrimmedMean(std::vector<double> values, double trim) {
  if (!(trim >= 0 && trim < 0.5)) {
    throw Error(fmt::format("trimmed mean: trim {}: must be in [0, 0.5)", trim));
  }
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const size_t kept = values.size() - static_cast<size_t>(std::floor(trim * values.size()));
  double sum = 0;
  for (size_t i = 0; i < kept; ++i) sum += values[i];
  return sum / kept;
}

Estimate SummarizeTrimmed(const std::vector<double>& values, double trim, uint64_t seed,
                          int resamples) {
  CheckResamples(resamples);
  Estimate e;
  e.value = TrimmedMean(values, trim);
  if (values.empty()) return e;
  Random random(seed);
  std::vector<double> statistics(resamples), resample(values.size());
  for (int r = 0; r < resamples; ++r) {
    for (double& v : resample) v = values[random.Below(values.size())];
    statistics[r] = TrimmedMean(resample, trim);
  }
  e.interval = Percentiles(std::move(statistics));
  return e;
}

PairedDifference ComparePairedTrimmed(const std::vector<double>& a, const std::vector<double>& b,
                                      double trim, uint64_t seed, int resamples) {
  if (trim == 0) return ComparePaired(a, b, seed, resamples);
  CheckResamples(resamples);
  if (a.size() != b.size()) {
    throw Error(fmt::format("paired comparison: {} values against {}: the pairs must be the "
                            "same trajectories",
                            a.size(), b.size()));
  }
  PairedDifference d;
  d.mean = TrimmedMean(a, trim) - TrimmedMean(b, trim);
  if (a.empty()) return d;
  Random random(seed);
  std::vector<double> differences(resamples), ra(a.size()), rb(b.size());
  for (int r = 0; r < resamples; ++r) {
    for (size_t i = 0; i < a.size(); ++i) {
      const size_t k = random.Below(a.size());
      ra[i] = a[k];
      rb[i] = b[k];
    }
    differences[r] = TrimmedMean(ra, trim) - TrimmedMean(rb, trim);
  }
  d.interval = Percentiles(std::move(differences));
  return d;
}

std::vector<int> AssignFolds(int count, int folds, uint64_t seed) {
  if (folds < 2 || folds > count) {
    throw Error(fmt::format("folds {}: must be in [2, {}] (the number of trajectories)", folds,
                            count));
  }
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), 0);
  Random random(seed);
  for (int i = count - 1; i > 0; --i) {  // Fisher-Yates
    std::swap(order[i], order[random.Below(static_cast<size_t>(i) + 1)]);
  }
  std::vector<int> fold(count);
  for (int k = 0; k < count; ++k) fold[order[k]] = k % folds;
  return fold;
}

}  // namespace contactlaws
