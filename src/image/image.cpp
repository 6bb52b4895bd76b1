#include "image/image.h"

#include <algorithm>

namespace lensrt {

int Image::channelIndex(const std::string& name) const {
  const auto it = std::find(channels.begin(), channels.end(), name);
  return it == channels.end() ? -1 : int(it - channels.begin());
}

}  // namespace lensrt
