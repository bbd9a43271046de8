#pragma once
// Template definition of steady_average (see flow_series.hpp).
#include <cmath>

namespace dilatant {

template <class Field>
SteadyAverage steady_average(const std::vector<FlowRow>& rows, double from, Field field) {
  SteadyAverage out;
  std::vector<const FlowRow*> steady;
  double total = 0.0;
  for (const FlowRow& r : rows) {
    if (r.strain - 1e-12 <= from || r.duration <= 0.0) continue;
    steady.push_back(&r);
    total += r.duration;
  }
  out.samples = static_cast<int>(steady.size());
  if (steady.empty()) return out;
  double sum = 0.0;
  for (const FlowRow* r : steady) sum += field(*r) * r->duration;
  out.mean = sum / total;
  if (out.samples < 2 * kBlocks) return out;  // too short for an error bar: 0 means unknown
  std::array<double, kBlocks> block_sum{}, block_time{};
  double elapsed = 0.0;
  for (const FlowRow* r : steady) {
    const auto b = std::min(kBlocks - 1, static_cast<int>(elapsed / total * kBlocks));
    block_sum[static_cast<std::size_t>(b)] += field(*r) * r->duration;
    block_time[static_cast<std::size_t>(b)] += r->duration;
    elapsed += r->duration;
  }
  double m = 0.0, m2 = 0.0;
  for (int b = 0; b < kBlocks; ++b) {
    const double v = block_sum[b] / block_time[b];
    m += v;
    m2 += v * v;
  }
  m /= kBlocks;
  const double var = std::max(0.0, m2 / kBlocks - m * m) * kBlocks / (kBlocks - 1);
  out.error = std::sqrt(var / kBlocks);
  return out;
}

}  // namespace dilatant
