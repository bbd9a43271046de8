#pragma once
// The jamming fraction of boundary-lubricated spheres against their friction,
// phi_max_BL(mu0), as `dilatant jam` measured it (docs/jamming.md), and the
// regime the paper's model assigns to a suspension (Fernandez et al. 2013,
// Fig. 4): continuous thickening (CST) when phi <= phi_max_BL(mu0); DST when
// phi_max_BL(mu0) < phi <= phi_max_HD; no flow above phi_max_HD, which the
// model takes equal to random close packing, the frictionless (mu0 = 0)
// jamming fraction.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/numeric_csv.hpp"

namespace dilatant::analysis {

struct JammingPoint {
  double mu0 = 0.0;
  double phi_max = 0.0;
  double phi_max_err = 0.0;
};

struct MeasuredFraction {
  double value = 0.0;
  double error = 0.0;
};

class JammingTable {
 public:
  // From a table with (at least) the columns mu0, phi_max, phi_max_err: mu0
  // strictly increasing from 0, phi_max in (0, 0.74). Throws InputError
  // naming the line.
  static JammingTable parse(const NumericCsv& csv);
  static JammingTable read(const std::filesystem::path& file);
  // The table shipped with this version (data/jamming/phi_max_bl.csv).
  static JammingTable builtin();

  // Linear in mu0 between the measured points; beyond the last one, the last
  // value (the sediment's fraction saturates with friction: docs/jamming.md).
  MeasuredFraction phi_max_bl(double mu0) const;
  MeasuredFraction phi_rcp() const {
    return {points_.front().phi_max, points_.front().phi_max_err};
  }
  const std::vector<JammingPoint>& points() const { return points_; }

 private:
  std::vector<JammingPoint> points_;
};

enum class FlowRegime { Cst, Dst, NoFlow };
std::string_view flow_regime_name(FlowRegime r);  // "cst", "dst", "no_flow"

struct Prediction {
  FlowRegime regime = FlowRegime::Cst;
  MeasuredFraction phi_max_bl;
  MeasuredFraction phi_rcp;
  // Distance from phi to the nearer boundary, in units of that boundary's
  // error; below 2 the regime is uncertain.
  double margin_sigma = 0.0;
  bool uncertain = false;
};

// mu0 >= 0 and phi in (0, 0.74) are the caller's to check.
Prediction predict_regime(const JammingTable& table, double mu0, double phi);

}  // namespace dilatant::analysis
