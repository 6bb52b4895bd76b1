#include "image/flo_io.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "core/error.h"

namespace lensrt {

namespace {
static_assert(std::endian::native == std::endian::little, "the .flo writer writes the host's bytes");

template <class T>
void put(std::vector<char>& out, T value) {
  char bytes[sizeof value];
  std::memcpy(bytes, &value, sizeof value);
  out.insert(out.end(), bytes, bytes + sizeof value);
}
}  // namespace

void writeFlo(const std::filesystem::path& file, const Image& image, const std::string& u,
              const std::string& v) {
  const int cu = image.channelIndex(u), cv = image.channelIndex(v);
  if (cu < 0 || cv < 0) throw std::invalid_argument("the image has no channels " + u + " and " + v);
  std::vector<char> out;
  out.reserve(12 + std::size_t(image.width) * std::size_t(image.height) * 8);
  put(out, kFloTag);
  put(out, std::int32_t(image.width));
  put(out, std::int32_t(image.height));
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      put(out, image.at(x, y, cu));
      put(out, image.at(x, y, cv));
    }
  std::ofstream f(file, std::ios::binary | std::ios::trunc);
  if (!f || !f.write(out.data(), std::streamsize(out.size())) || !f.flush())
    throw InputError(file.string(), "cannot write the flow file");
}

}  // namespace lensrt
