#include "measure/steadiness.hpp"

#include <algorithm>
#include <cmath>

namespace dilatant {

namespace {

template <class Field>
Drift drift_of(const std::vector<FlowRow>& rows, double from, Field field, double floor) {
  Drift d;
  if (rows.empty() || rows.back().strain <= from) return d;
  const double mid = 0.5 * (from + rows.back().strain);
  std::vector<FlowRow> first;
  for (const FlowRow& r : rows)
    if (r.strain - 1e-12 <= mid) first.push_back(r);
  const SteadyAverage a = steady_average(first, from, field);
  const SteadyAverage b = steady_average(rows, mid, field);
  const SteadyAverage all = steady_average(rows, from, field);
  if (a.samples < 2 * kBlocks || b.samples < 2 * kBlocks || all.mean == 0.0) return d;
  const double scale = std::abs(all.mean);
  d.known = true;
  d.change = (b.mean - a.mean) / scale;
  d.error = std::hypot(a.error, b.error) / scale;
  d.steady = std::abs(d.change) <= std::max(3.0 * d.error, floor);
  return d;
}

}  // namespace

Drift wall_speed_drift(const std::vector<FlowRow>& rows, double from) {
  return drift_of(
      rows, from, [](const FlowRow& r) { return r.wall_velocity; }, 0.05);
}

Drift volume_fraction_drift(const std::vector<FlowRow>& rows, double from) {
  return drift_of(
      rows, from, [](const FlowRow& r) { return r.phi_bulk; }, 0.01);
}

}  // namespace dilatant
