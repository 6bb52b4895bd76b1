// MurmurHash3_x86_32 (Austin Appleby's public-domain reference, little-endian
// blocks) and Cryptomatte's mapping of a hash to a float32 id.
#pragma once

#include <cstdint>
#include <string_view>

namespace lensrt {

std::uint32_t murmurHash3X86_32(std::string_view bytes, std::uint32_t seed = 0);

// Cryptomatte 1.2.0: the hash's bits read as a float32, with bit 23 flipped
// where the exponent would be 0 or 255, so the id is never a denormal, an
// infinity or a NaN (its exponent lies in [1, 254]).
std::uint32_t cryptomatteIdBits(std::uint32_t hash);
float cryptomatteId(std::string_view name);

}  // namespace lensrt
