#pragma once
// Mean x-velocity of the dynamic bodies (world/bodies.hpp: a boundary's driven
// bodies are left out) in slabs across the gap, accumulated
// over the steady state (each sample weighted by its step's duration).
// Its slope in the central region is the bulk shear rate gamma_dot_bulk; a
// profile that is not linear across the gap means wall slip or a shear band.
#include <string>
#include <vector>

#include "world/world.hpp"

namespace dilatant {

struct LinearFit {
  double slope = 0.0, intercept = 0.0;
  double max_deviation = 0.0;  // largest |v - fit| over the bins used
};

class VelocityProfile {
 public:
  VelocityProfile() = default;
  VelocityProfile(double lz, int bins) : lz_(lz), sum_vx_(bins, 0.0), weight_(bins, 0.0) {}

  void add(const World& world, double weight);
  int bins() const { return static_cast<int>(sum_vx_.size()); }
  double bin_centre(int k) const { return (k + 0.5) * lz_ / bins(); }
  double mean_vx(int k) const { return weight_[k] > 0.0 ? sum_vx_[k] / weight_[k] : 0.0; }
  // Least-squares line through the bins whose centres lie in [z_lo, z_hi].
  LinearFit fit(double z_lo, double z_hi) const;
  std::string csv() const;  // z,vx,weight

  std::vector<double>& sums() { return sum_vx_; }
  std::vector<double>& weights() { return weight_; }
  double& height() { return lz_; }

 private:
  double lz_ = 0.0;
  std::vector<double> sum_vx_;
  std::vector<double> weight_;  // sum of weights x spheres in the bin
};

}  // namespace dilatant
