#include "measure/sample_mean.hpp"

#include <cmath>

namespace dilatant {

SampleMean sample_mean(std::span<const double> values) {
  SampleMean s;
  s.n = values.size();
  if (s.n == 0) return s;
  double sum = 0.0;
  for (const double v : values) sum += v;
  s.mean = sum / static_cast<double>(s.n);
  if (s.n < 2) return s;
  // Two passes: the deviations from the mean, not sum(v^2) - n mean^2, which
  // cancels catastrophically for fractions like 0.6355 +- 0.0013.
  double ss = 0.0;
  for (const double v : values) ss += (v - s.mean) * (v - s.mean);
  s.sd = std::sqrt(ss / static_cast<double>(s.n - 1));
  s.sem = s.sd / std::sqrt(static_cast<double>(s.n));
  return s;
}

}  // namespace dilatant
