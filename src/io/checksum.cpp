#include "io/checksum.hpp"

#include <zlib.h>

#include <algorithm>
#include <limits>

namespace dilatant {

std::uint32_t crc32_of(std::string_view bytes) {
  // zlib takes at most a uInt of bytes per call.
  uLong crc = crc32(0L, Z_NULL, 0);
  const auto* p = reinterpret_cast<const Bytef*>(bytes.data());
  for (std::size_t left = bytes.size(); left > 0;) {
    const auto n = static_cast<uInt>(std::min<std::size_t>(left, std::numeric_limits<uInt>::max()));
    crc = crc32(crc, p, n);
    p += n;
    left -= n;
  }
  return static_cast<std::uint32_t>(crc);
}

}  // namespace dilatant
