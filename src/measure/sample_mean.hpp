#pragma once
// The mean of n independent measurements of one quantity (seeds, packings) and
// its statistical error: the sample standard deviation (Bessel's n - 1) and the
// standard error of the mean, sd / sqrt(n). One rule for too few values, shared
// by every caller: with none the mean is NaN, with fewer than two sd and sem
// are NaN (a spread cannot be measured from one value; callers that print 0 or
// null for "unknown" say so where they do).
#include <cstddef>
#include <limits>
#include <span>

namespace dilatant {

struct SampleMean {
  std::size_t n = 0;
  double mean = std::numeric_limits<double>::quiet_NaN();
  double sd = std::numeric_limits<double>::quiet_NaN();
  double sem = std::numeric_limits<double>::quiet_NaN();
};

SampleMean sample_mean(std::span<const double> values);

}  // namespace dilatant
