#pragma once
// The CRC-32 of a byte string (zlib's crc32: the ISO-HDLC polynomial of gzip
// and PNG, RFC 1952 section 8). Checkpoints end with the CRC-32 of every byte
// before it (drivers/shear_cell_state.cpp), so that a byte damaged after
// writing is refused instead of resumed: a 32-bit CRC detects every burst of
// up to 32 bits and all but 2^-32 of other damage.
#include <cstdint>
#include <string_view>

namespace dilatant {

std::uint32_t crc32_of(std::string_view bytes);

}  // namespace dilatant
