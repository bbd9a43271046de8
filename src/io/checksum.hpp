#pragma once
// The CRC-32 of a byte string (zlib's crc32: the ISO-HDLC polynomial of gzip
// and PNG, RFC 1952 section 8). Checkpoints end with the CRC-32 of every byte
// before it (drivers/shear_cell_state.cpp), so that a byte damaged after
// writing is refused instead of resumed: a 32-bit CRC detects every burst of
// up to 32 bits and all but 2^-32 of other damage.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace dilatant {

std::uint32_t crc32_of(std::string_view bytes);

// A checkpoint's trailer: the CRC-32 of every byte before it, 4 bytes in the
// machine's order.
inline constexpr std::size_t kCrcTrailerBytes = sizeof(std::uint32_t);
// Appends the trailer to `bytes`.
void append_crc_trailer(std::string& bytes);
// Rewrites the trailer at the end of `bytes` to match the rest (for the
// fuzzer, whose mutations must reach the checks behind it).
void reseal_crc_trailer(std::string& bytes);
// Throws std::runtime_error naming `file` when the trailer does not match the
// bytes before it, or there are fewer than `header_bytes` of them: a byte
// changed after writing, or the file cut short.
void check_crc_trailer(std::string_view bytes, std::size_t header_bytes,
                       const std::filesystem::path& file);

}  // namespace dilatant
