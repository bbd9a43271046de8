#pragma once
// The solver's contact memory (warm-start impulses and regimes, by contact
// key) in a checkpoint: written sorted by key, so that the same state gives
// the same bytes; read back with every regime checked, since a byte out of
// the enum's range would be undefined behaviour once loaded.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <vector>

#include "detection/contact.hpp"
#include "io/binary_archive.hpp"

namespace dilatant {

using ContactMemoryMap = std::unordered_map<std::uint64_t, ContactMemory>;

inline void write_contact_memory(BinaryWriter& w, const ContactMemoryMap& memory) {
  std::vector<std::pair<std::uint64_t, ContactMemory>> sorted(memory.begin(), memory.end());
  std::sort(sorted.begin(), sorted.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  w.value(static_cast<std::uint64_t>(sorted.size()));
  for (const auto& [key, m] : sorted) {
    w.value(key);
    w.value(m.impulse);
    w.value(static_cast<std::uint8_t>(m.regime));
  }
}

// Throws std::runtime_error naming `file` for a regime out of range.
inline ContactMemoryMap read_contact_memory(BinaryReader& r, const std::filesystem::path& file) {
  constexpr std::size_t kBytesEach = sizeof(std::uint64_t) + 3 * sizeof(double) + 1;
  std::uint64_t n = 0;
  r.count(n, kBytesEach);
  ContactMemoryMap memory;
  for (std::uint64_t k = 0; k < n; ++k) {
    std::uint64_t key = 0;
    ContactMemory m;
    std::uint8_t regime = 0;
    r.value(key);
    r.value(m.impulse);
    r.value(regime);
    if (regime > static_cast<std::uint8_t>(kLastRegime))
      throw std::runtime_error(file.string() + ": corrupt checkpoint (contact regime)");
    m.regime = static_cast<Regime>(regime);
    memory.emplace(key, m);
  }
  return memory;
}

}  // namespace dilatant
