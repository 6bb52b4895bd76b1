#include "api/aperture_mask_file.h"

#include <fmt/format.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.h"
#include "image/png_allocation.h"
#include "image/stb_io.h"

namespace lensrt {
namespace {

constexpr int kMaxSide = 4096;

std::string readBytes(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) throw InputError(file.string(), "no such file");
  if (std::filesystem::is_directory(file, ec)) throw InputError(file.string(), "is a directory");
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) throw InputError(file.string(), "cannot read: " + ec.message());
  if (size > (64u << 20)) throw InputError(file.string(), "the aperture mask file is larger than 64 MiB");
  std::ifstream in(file, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof()) throw InputError(file.string(), "cannot read the file");
  return bytes;
}

}  // namespace

ApertureMask readApertureMask(const std::filesystem::path& file) {
  return decodeApertureMask(readBytes(file), file.string());
}

ApertureMask decodeApertureMask(std::string_view bytes, const std::string& name) {
  // A header claiming gigapixels is refused instead of allocated.
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  if (const auto size = pngDeclaredSize(data, bytes.size());
      size && (size->first > kMaxSide || size->second > kMaxSide))
    throw InputError(name, fmt::format("the aperture mask is {}x{}, larger than {}x{}", size->first,
                                       size->second, kMaxSide, kMaxSide));
  if (const std::optional<std::string> bomb = pngAllocationProblem(data, bytes.size()))
    throw InputError(name, "the aperture mask: " + *bomb);
  // The decoder of the glTF textures (image/stb_io.h).
  const std::optional<StbCodes> image = decodeStbCodes(bytes);
  const int channels = image ? image->components : 0;
  const std::size_t bytesPerValue = image && image->bits == 16 ? 2 : 1;
  if (!image || channels < 1 || channels > 4)
    throw InputError(name, "cannot decode the aperture mask (expected a PNG, JPEG, BMP or TGA image)");
  if (image->width > kMaxSide || image->height > kMaxSide)
    throw InputError(name, fmt::format("the aperture mask is {}x{}, larger than {}x{}", image->width,
                                       image->height, kMaxSide, kMaxSide));
  // Grey and grey+alpha images carry grey in channel 0; RGB(A) its mean.
  const int colours = channels >= 3 ? 3 : 1;
  const double full = image->bits == 16 ? 65535.0 : 255.0;
  const auto value = [&](std::size_t i) {
    if (bytesPerValue == 1) return double(image->data[i]);
    std::uint16_t v = 0;  // stb_image keeps 16-bit values in the machine's byte order
    std::memcpy(&v, &image->data[2 * i], sizeof v);
    return double(v);
  };
  std::vector<float> values(std::size_t(image->width) * std::size_t(image->height));
  for (std::size_t p = 0; p < values.size(); ++p) {
    double sum = 0.0;
    for (int c = 0; c < colours; ++c) sum += value(p * std::size_t(channels) + std::size_t(c));
    values[p] = float(sum / (colours * full));
  }
  try {
    return ApertureMask(image->width, image->height, std::move(values),
                        std::filesystem::path(name).filename().string());
  } catch (const std::invalid_argument& e) {
    throw InputError(name, std::string("aperture mask: ") + e.what());
  }
}

}  // namespace lensrt
