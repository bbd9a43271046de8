#include "measure/steadiness.hpp"

#include <algorithm>
#include <cmath>

namespace dilatant {

Drift wall_speed_drift(const std::vector<FlowRow>& rows, double from) {
  Drift d;
  if (rows.empty() || rows.back().strain <= from) return d;
  const double mid = 0.5 * (from + rows.back().strain);
  std::vector<FlowRow> first;
  for (const FlowRow& r : rows)
    if (r.strain - 1e-12 <= mid) first.push_back(r);
  const auto speed = [](const FlowRow& r) { return r.wall_velocity; };
  const SteadyAverage a = steady_average(first, from, speed);
  const SteadyAverage b = steady_average(rows, mid, speed);
  const SteadyAverage all = steady_average(rows, from, speed);
  if (a.samples < 2 * kBlocks || b.samples < 2 * kBlocks || all.mean == 0.0) return d;
  const double scale = std::abs(all.mean);
  d.known = true;
  d.change = (b.mean - a.mean) / scale;
  d.error = std::hypot(a.error, b.error) / scale;
  d.steady = std::abs(d.change) <= std::max(3.0 * d.error, 0.05);
  return d;
}

}  // namespace dilatant
