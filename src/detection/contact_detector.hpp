#pragma once
// Broad and narrow phase: finds every sphere pair and sphere–plane pair whose
// surfaces are closer than a margin, using a uniform cell list (O(N)).
//
// The margin must cover how far surfaces can approach during one step; pairs
// found here but still apart at the end of the step simply get zero impulse
// (the solver's Signorini condition), so a generous margin costs only time.
#include <array>
#include <cstdint>
#include <vector>

#include "detection/contact.hpp"
#include "world/world.hpp"

namespace dilatant {

class ContactDetector {
 public:
  // Fills `contacts` (cleared first) in a deterministic order: sphere pairs by
  // (i, j), then sphere–plane pairs. Pairs of two fixed bodies are skipped.
  // The sphere pairs are searched by `threads` threads, each over a block of
  // spheres i; the blocks are joined in order, so the result does not depend on it.
  void detect(const World& world, double margin, std::vector<Contact>& contacts, int threads = 1);

 private:
  void build_cells(const World& world, double cell_size);
  void add_pair_contacts(const World& world, double margin, std::size_t i,
                         std::vector<Contact>& contacts) const;

  std::array<int, 3> n_cells_{};
  Vec3 origin_ = Vec3::Zero();
  Vec3 cell_edge_ = Vec3::Ones();
  std::vector<std::int32_t> cell_start_;  // CSR layout: bodies of cell c are
  std::vector<std::int32_t> cell_body_;   // cell_body_[cell_start_[c] .. cell_start_[c+1])
  std::vector<std::int32_t> body_cell_;
  std::vector<std::vector<Contact>> per_thread_;  // reused between calls
};

// Fills the geometry-derived fields of a contact (arms, Delassus coefficients).
void finish_contact(const Bodies& bodies, Contact& c);

}  // namespace dilatant
