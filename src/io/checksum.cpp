#include "io/checksum.hpp"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>

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

void append_crc_trailer(std::string& bytes) {
  const std::uint32_t crc = crc32_of(bytes);
  bytes.append(reinterpret_cast<const char*>(&crc), kCrcTrailerBytes);
}

void reseal_crc_trailer(std::string& bytes) {
  if (bytes.size() < kCrcTrailerBytes) return;
  const std::uint32_t crc =
      crc32_of(std::string_view(bytes).substr(0, bytes.size() - kCrcTrailerBytes));
  std::memcpy(bytes.data() + bytes.size() - kCrcTrailerBytes, &crc, kCrcTrailerBytes);
}

// Without the check a damaged number resumed silently (4 bytes in the middle
// of a shear cell's checkpoint put 1.08e-222 into the time series where 0.391
// belonged).
void check_crc_trailer(std::string_view bytes, std::size_t header_bytes,
                       const std::filesystem::path& file) {
  if (bytes.size() < header_bytes + kCrcTrailerBytes)
    throw std::runtime_error("checkpoint is truncated");
  const std::size_t body = bytes.size() - kCrcTrailerBytes;
  std::uint32_t stored = 0;
  std::memcpy(&stored, bytes.data() + body, kCrcTrailerBytes);
  if (crc32_of(bytes.substr(0, body)) != stored)
    throw std::runtime_error(fmt::format(
        "{}: checkpoint is damaged or truncated: its CRC-32 does not match its contents (a "
        "byte changed after it was written, or the file was cut short)",
        file.string()));
}

}  // namespace dilatant
