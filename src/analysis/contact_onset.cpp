#include "analysis/contact_onset.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace dilatant::analysis {

std::optional<ContactOnset> contact_onset(const FlowCurve& curve, double rise) {
  std::vector<const FlowPoint*> flowing;
  for (const auto& p : curve.points) {
    if (p.shear_rate <= 0.0) continue;  // jammed: no contacts sliding to count
    if (std::isnan(p.frac_bl)) return std::nullopt;
    flowing.push_back(&p);
  }
  if (flowing.size() < 2) return std::nullopt;
  std::stable_sort(flowing.begin(), flowing.end(), [](const FlowPoint* a, const FlowPoint* b) {
    return a->shear_stress < b->shear_stress;
  });
  const auto low = std::min_element(
      flowing.begin(), flowing.end(),
      [](const FlowPoint* a, const FlowPoint* b) { return a->frac_bl < b->frac_bl; });
  const double threshold = (*low)->frac_bl + rise;
  for (auto it = low + 1; it != flowing.end(); ++it) {
    if ((*it)->frac_bl <= threshold) continue;
    const FlowPoint& a = **(it - 1);
    const FlowPoint& b = **it;
    const double t = (threshold - a.frac_bl) / (b.frac_bl - a.frac_bl);
    const auto log_between = [t](double x, double y) {
      return std::exp((1.0 - t) * std::log(x) + t * std::log(y));
    };
    return ContactOnset{log_between(a.shear_stress, b.shear_stress),
                        log_between(a.shear_rate, b.shear_rate), (*low)->frac_bl};
  }
  return std::nullopt;
}

}  // namespace dilatant::analysis
