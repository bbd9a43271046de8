#include "analysis/analysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace dilatant::analysis {
namespace {

std::size_t rank(const std::vector<std::string>& samples, const std::string& s) {
  return static_cast<std::size_t>(std::find(samples.begin(), samples.end(), s) - samples.begin());
}

SampleReport sample_report(const AnalysisReport& r, const std::string& sample) {
  SampleReport s;
  s.sample = sample;
  s.series.sample = sample;
  if (const auto it = r.input.phi_max.find(sample); it != r.input.phi_max.end())
    s.phi_max_given = it->second;
  for (std::size_t i = 0; i < r.input.curves.size(); ++i) {
    const FlowCurve& c = r.input.curves[i];
    const CurveResult& res = r.curves[i];
    if (c.sample != sample) continue;
    ++s.curves;
    if (res.regime == Regime::Dst) {
      ++s.dst_curves;
      if (!(s.dst_phi_min <= c.phi)) s.dst_phi_min = c.phi;
    }
    if (res.regime != Regime::Cst) continue;
    ++s.cst_curves;
    if (s.phi_max_given && c.phi >= *s.phi_max_given) {
      s.notes.push_back(fmt::format("CST curve at phi {} >= the given phi_max {} left out ({})",
                                    c.phi, *s.phi_max_given, c.source));
      continue;
    }
    s.series.points.push_back({c.phi, res.n, res.n_sigma});
  }
  s.series.phi_max = s.phi_max_given;
  s.fit = fit_divergence({s.series});
  if (s.phi_max_given) {
    PhiSeries free = s.series;
    free.phi_max.reset();
    s.free_fit = fit_divergence({free});
  }
  return s;
}

CollapseReport collapse_report(const std::vector<SampleReport>& samples) {
  CollapseReport c;
  std::vector<PhiSeries> series;
  for (const auto& s : samples) {
    const std::size_t need = s.phi_max_given ? 1 : 2;
    if (s.series.points.size() < need) {
      c.left_out.push_back(fmt::format("{}: {} CST curve{} (needs {})", s.sample,
                                       s.series.points.size(),
                                       s.series.points.size() == 1 ? "" : "s", need));
      continue;
    }
    series.push_back(s.series);
    c.samples.push_back(s.sample);
  }
  if (series.empty()) {
    c.fit.why_not = "no sample has enough CST curves";
    return c;
  }
  c.fit = fit_divergence(series);
  return c;
}

}  // namespace

AnalysisReport analyse(AnalysisInput input, const AnalysisSettings& settings) {
  AnalysisReport r;
  std::stable_sort(input.curves.begin(), input.curves.end(), [&](const auto& a, const auto& b) {
    const auto ra = rank(input.samples, a.sample), rb = rank(input.samples, b.sample);
    return ra != rb ? ra < rb : a.phi < b.phi;
  });
  r.input = std::move(input);
  r.settings = settings;
  for (const auto& c : r.input.curves) r.curves.push_back(analyse_curve(c, settings));
  for (const auto& sample : r.input.samples) r.samples.push_back(sample_report(r, sample));
  r.collapse = collapse_report(r.samples);
  return r;
}

}  // namespace dilatant::analysis
