#pragma once
// CRC-32 as MCAP uses it (https://mcap.dev/spec, "CRC"): the IEEE 802.3 / zlib CRC-32, reflected polynomial
// 0xEDB88320, initial value 0xFFFFFFFF, final XOR 0xFFFFFFFF. crc32("123456789") == 0xCBF43926.
#include <cstddef>
#include <cstdint>

namespace gdnav::io::mcap {

// Continues a CRC: crc32_update(crc32_update(0, a), b) == crc32 of a followed by b. Start with 0.
std::uint32_t crc32_update(std::uint32_t crc, const std::uint8_t* data, std::size_t n);

}  // namespace gdnav::io::mcap
