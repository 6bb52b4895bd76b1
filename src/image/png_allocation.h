// PNGs that make stb_image, the decoder of the glTF textures and of the
// aperture mask, allocate gigabytes from a few hundred bytes: an IDAT chunk
// that claims more bytes than the file holds (stb grows its buffer to the
// claim before reading; the aperture-mask fuzz target found a 219-byte file
// claiming 2 GB), and image data that inflates beyond the pixels the header
// declares (stb grows its output for whatever the zlib stream yields and
// checks the size afterwards). Checked before decoding, with zlib and a fixed
// scratch buffer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

namespace lensrt {

// Width and height the IHDR chunk of a PNG declares, read before a decoder
// allocates for them; nullopt when `bytes` do not start a PNG.
std::optional<std::pair<std::uint32_t, std::uint32_t>> pngDeclaredSize(const unsigned char* bytes,
                                                                       std::size_t size);

// Why `bytes`, when they are a PNG, may not be decoded: a chunk runs past the
// end of the data, or the image data inflates to more than the width, height
// and pixel format of its header allow. nullopt for a PNG within them and for
// anything else (other breakage, another format: the decoder's to report).
std::optional<std::string> pngAllocationProblem(const unsigned char* bytes, std::size_t size);

}  // namespace lensrt
