#pragma once
// The bulk fraction a shear-cell run starts from, and the nominal phi that
// makes a cold start begin at a given one. In a wall cell the bulk fraction
// (the central half of the gap, drivers/shear_cell_summary.hpp) is not the
// nominal cell.phi: the layers at the walls are looser, by an offset that
// depends on the packing. A jam's cold start (sweep.cold_start_phi = "bulk",
// docs/sweeps.md "Ramps to the jam") is asked to begin where the ramp's jammed
// point began, so its nominal phi is chosen on the packings themselves.
#include <atomic>
#include <filesystem>
#include <vector>

#include "io/config.hpp"

namespace dilatant {

// The bulk fraction of the packing a cold run of `config` begins with: the
// cell built exactly as the run builds it (same seed, same phi), not run.
double starting_bulk_fraction(const Config& config);

// The bulk fraction of the state in a checkpoint: for the checkpoint of a
// finished run, the state a run continued from it begins with.
double checkpoint_bulk_fraction(const std::filesystem::path& checkpoint);

struct StartingFractionMatch {
  double phi = 0.0;             // the nominal phi chosen
  double phi_bulk_start = 0.0;  // the bulk fraction its packing begins with
  bool within_tolerance = false;
  // Every packing built: nominal phi and its starting bulk fraction.
  std::vector<std::pair<double, double>> tried;
};

// The nominal phi whose packing begins at bulk fraction `target` within
// `tolerance`. The first packing, at config's phi, measures the offset
// b(phi) - phi between its starting bulk and nominal fractions; the offset is
// nearly constant in phi on average, so the estimate phi + target - b(phi) is
// tried next, then nominal fractions around it a `tolerance` apart (+1, -1,
// +2, -2, ...). b is not smooth in phi: each nominal phi draws another packing
// (another N, other layers in the slab), and its starting bulk scatters about
// the mean offset, by up to 0.005 in the paper's cell (25 x 10 x 27 R) and
// 0.01 in a 20 R gap (docs/sweeps.md "Ramps to the jam"); a scan of neighbouring packings finds one
// that starts near the target where a root finder would chase the scatter. At most `max_packings`
// are built; the closest is chosen, and within_tolerance says whether it is within. A phi that does
// not pack is recorded with a NaN bulk and passed over; if none packs, phi_bulk_start is NaN.
// `stop` (optional): checked before each packing; once set, the search ends
// with the packings built so far.
StartingFractionMatch match_starting_bulk(Config config, double target, double tolerance,
                                          int max_packings,
                                          const std::atomic<bool>* stop = nullptr);

}  // namespace dilatant
